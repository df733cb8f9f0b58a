#!/usr/bin/env bash
# stickslip trace: the chain of branches both ways from a start, written as one run directory per
# branch plus trace.csv and trace.json; the same bytes from run to run; a [trace] table in a run
# file for `run` and `check`; each branch a run of its own (restart, export); the exit codes; bad
# input refused with exit 2 and nothing written.
source "$(dirname "$0")/expect.sh"
r="$work/r"
p41=(--preset paper-4.1 --parameter omega --range 0.3,0.69 --ds 0.005 --ds-max 0.05 --results "$r")
p51=(--preset paper-5.1 --parameter omega --range 0.3,0.9 --ds 0.005 --ds-max 0.05 --results "$r")

# Section 4.1 downwards: the crossing-sliding at omega = 0.5999775071 switches to the sticking
# orbit, whose adding-sliding further down is not confirmed: an end like any other, written and
# printed, exit 0. The ends name the parameter and its value rounded ("reached omega = 0.69").
"$bin" trace "${p41[@]}" --output t41 > "$work/t41.txt" 2> "$work/t41.err"
code=$?
[ "$code" -eq 0 ] && pass || fail "trace 4.1 exit $code, want 0: $(cat "$work/t41.err")"
[ ! -s "$work/t41.err" ] && pass || fail "stderr not empty: $(cat "$work/t41.err")"
grep -q "^  down: not-confirmed: " "$work/t41.txt" && pass || fail "the down end is not printed: $(cat "$work/t41.txt")"
grep -qx "  up: parameter-bound: reached omega = 0.69" "$work/t41.txt" && pass ||
  fail "the up end is not 'reached omega = 0.69': $(cat "$work/t41.txt")"
for f in trace.csv trace.json branch-1/summary.json branch-2/branch.csv branch-3/special-points.csv; do
  [ -s "$r/t41/$f" ] && pass || fail "t41/$f missing"
done
/usr/bin/python3 - "$r/t41" <<'PY' && pass || fail "trace.json/trace.csv of t41"
import csv, json, sys
d = sys.argv[1]
t = json.load(open(d + "/trace.json"))
assert [x["direction"] for x in t["directions"]] == ["down", "up"], t["directions"]
assert t["directions"][0]["end"] == "not-confirmed" and t["directions"][1]["end"] == "parameter-bound"
assert t["directions"][1]["message"] == "reached omega = 0.69", t["directions"][1]
b = t["branches"]
assert b[0]["signature"] == "slip- / antisymmetric" and b[0]["end"] == "switched", b[0]
assert b[1]["signature"] == "slip- stick / antisymmetric" and b[1]["margin"] == "reversal:1", b[1]
assert b[1]["switch"]["bifurcation"] == "crossing-sliding" and b[1]["switch"]["persists"], b[1]
rows = list(csv.DictReader(open(d + "/trace.csv")))
for k, branch in enumerate(b, 1):
    mine = [r for r in rows if r["branch"] == str(k)]
    assert len(mine) == branch["points"], (k, len(mine))
    assert all(r["signature"] == branch["signature"] for r in mine)
    assert len(list(csv.DictReader(open(f"{d}/branch-{k}/branch.csv")))) == branch["points"]
# Continuous across the switch: the located point and the sticking branch's start.
end1 = [r for r in rows if r["branch"] == "1"][-1]
start2 = [r for r in rows if r["branch"] == "2"][0]
assert abs(float(end1["omega"]) - 0.5999775071) < 1e-10, end1["omega"]
for c in ("omega", "phi", "period", "x10", "x20", "v10"):
    assert abs(float(end1[c]) - float(start2[c])) <= 1e-10, c
PY

# The same trace again: the same bytes.
"$bin" trace "${p41[@]}" --output t41b > /dev/null 2>&1
for f in trace.csv trace.json branch-1/branch.csv branch-2/special-points.csv branch-3/summary.json; do
  if [ "$f" = "trace.json" ] || [ "$f" = "branch-3/summary.json" ]; then
    diff <(sed 's/t41b/t41/' "$r/t41b/$f") "$r/t41/$f" > /dev/null && pass || fail "t41b/$f differs"
  else
    cmp -s "$r/t41b/$f" "$r/t41/$f" && pass || fail "t41b/$f differs"
  fi
done

# Each branch is a run: a restart from its labelled point, and the AUTO export.
"$bin" continue --results "$r/t41" --point branch-2:EP1 --parameter omega --range 0.3,0.69 --ds 0.005 --ds-max 0.05 \
  --direction down --max-points 5 --output again > /dev/null && pass || fail "restart from branch-2"
cmp -s <(sed -n 2,5p "$r/t41/again/branch.csv" | cut -d, -f3-12) <(sed -n 2,5p "$r/t41/branch-2/branch.csv" | cut -d, -f3-12) &&
  pass || fail "the restart does not retrace branch-2"
"$bin" export --auto "$r/t41/branch-2" > /dev/null && [ -s "$r/t41/branch-2/b.branch-2" ] && pass || fail "export"

# Section 5.1 followed past its changes of type, which switch nowhere: the loop closes, exit 0.
"$bin" trace "${p51[@]}" --follow-past-unswitched --output t51 > "$work/t51.txt" && pass || fail "trace 5.1 exit $?"
grep -q "down: loop" "$work/t51.txt" && grep -q "up: loop" "$work/t51.txt" && pass || fail "5.1: $(cat "$work/t51.txt")"
# Without following past, the first changes end both directions: ends like any other, exit 0.
"$bin" trace "${p51[@]}" --output t51s > /dev/null 2>&1
[ $? -eq 0 ] && pass || fail "trace 5.1 without following past: not exit 0"

# A run file with a [trace] table: `run` writes the trace, `check` compares it (ok, then a
# difference after trace.json was edited).
cat > "$work/t.toml" <<'TOML'
output = "t41r"
[start]
preset = "paper-4.1"
[continuation]
parameter = "omega"
range = [0.3, 0.69]
ds = 0.005
ds_max = 0.05
[trace]
max_branches = 10
TOML
"$bin" run --results "$r" "$work/t.toml" > /dev/null 2>&1
[ $? -eq 0 ] && pass || fail "run with [trace] not exit 0"
cmp -s "$r/t41r/trace.csv" "$r/t41/trace.csv" && pass || fail "run's trace.csv differs from trace's"
"$bin" check --results "$r" "$work/t.toml" > "$work/check.txt" 2>&1 && pass || fail "check: $(cat "$work/check.txt")"
grep -q "check t41r/branch-2: ok" "$work/check.txt" && pass || fail "check output: $(cat "$work/check.txt")"
sed -i 's/"end": "parameter-bound"/"end": "loop"/' "$r/t41r/trace.json"
"$bin" check --results "$r" "$work/t.toml" > "$work/check.txt" 2>&1
[ $? -eq 1 ] && grep -q "trace.json" "$work/check.txt" && pass || fail "check missed an edit: $(cat "$work/check.txt")"

# Bad input: one line, exit 2, nothing written.
o=(--preset paper-4.1 --parameter omega --range 0.3,0.69 --results "$work/out" --output bad)
expect 2 "max-branches = 0 is invalid" "$bin" trace "${o[@]}" --max-branches 0
expect 2 "max-branches = 2.5 is invalid" "$bin" trace "${o[@]}" --max-branches 2.5
expect 2 "max-branches = 1e+300 is invalid" "$bin" trace "${o[@]}" --max-branches 1e300
expect 2 "max-amplitude = -1 is invalid: valid range a finite max-amplitude > 0" "$bin" trace "${o[@]}" --max-amplitude -1
expect 2 "loop-tolerance = 1 is invalid: valid range 0 < loop-tolerance <= 1e-2" "$bin" trace "${o[@]}" --loop-tolerance 1
expect 2 "loop-tolerance = 0 is invalid" "$bin" trace "${o[@]}" --loop-tolerance 0
expect 2 "range" "$bin" trace "${o[@]/0.3,0.69/0.7,0.9}"
mkdir -p "$work/out/mine" && touch "$work/out/mine/notes.txt"
expect 2 "output = 'mine' is invalid" "$bin" trace --preset paper-4.1 --parameter omega --range 0.3,0.69 \
  --results "$work/out" --output mine
for bad in 'direction = "up"' 'continue_past_type_changes = true' ; do
  sed "s/^range = .*/&\n$bad/" "$work/t.toml" > "$work/bad.toml"
  expect 2 "$(echo "$bad" | cut -d' ' -f1)" "$bin" run --results "$work/out" "$work/bad.toml"
done
for bad in 'max_branches = 0' 'max_branches = 1.5' 'max_amplitude = -2' 'loop_tolerance = 0.5' 'follow_past = true' \
           'follow_past_unswitched = 1' 'allow_inadmissible = "yes"'; do
  sed "s/^max_branches = 10/$bad/" "$work/t.toml" > "$work/bad.toml"
  expect 2 "trace.$(echo "$bad" | cut -d' ' -f1)" "$bin" run --results "$work/out" "$work/bad.toml"
done
finish
