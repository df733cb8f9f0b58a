#!/usr/bin/env bash
# stickslip find: a new user's period-4 motion found and verified (exit 0), the solve command line
# it prints gives the same orbit, the run file it writes is one `stickslip run` takes; --trace gives
# the files of find then trace by hand, and a run file --as trace the same branches; --json is the
# text output's orbit as JSON; exit 5 for a motion that is not periodic within --max-multiple or has
# no orbit type (nothing traced or written); and a table of bad input: exit 2, one line naming the
# option and its range, no file created or changed.
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

data=(--set chi=0.5 --set eta=2 --set u_s=0.1 --set u_r=0.3 --set omega=0.27 --set x10=1)
"$bin" find "${data[@]}" --write-run "$work/p4.toml" > "$work/p4.txt" 2> "$work/p4.err"
code=$?
[ "$code" -eq 0 ] || fail "period-4 case: exit $code (want 0): $(cat "$work/p4.err")"
grep -q "k = 4 forcing period(s)" "$work/p4.txt" || fail "period-4 case: no 'k = 4' in the output"
grep -q "^signature  slip- stick slip+ stick slip- stick slip+ stick slip- stick slip+ stick slip- stick slip+ stick / period 4$" \
  "$work/p4.txt" || fail "period-4 case: not slip- stick slip+ stick x4 / period 4"
grep -q "^verification passed" "$work/p4.txt" || fail "period-4 case: verification did not pass"

# The printed solve command gives the same solution line.
command=$(grep "^  stickslip solve " "$work/p4.txt" | sed 's/^  stickslip //')
eval "\"\$bin\" $command" > "$work/solve.txt" 2>&1 || fail "the printed solve command exits $?"
[ "$(grep '^solution' "$work/solve.txt")" = "$(grep '^solution' "$work/p4.txt")" ] ||
  fail "the printed solve command gives another solution: $(grep '^solution' "$work/solve.txt")"

# The run file is one stickslip run accepts.
"$bin" run --results "$work/results" "$work/p4.toml" > "$work/run.txt" 2>&1 ||
  fail "stickslip run on the written run file exits $?: $(cat "$work/run.txt")"
[ -f "$work/results/p4/branch.csv" ] || fail "the run of the written run file left no branch.csv"

# find --trace: the trace from the found orbit is the trace `stickslip trace` makes from the solve line find
# prints (by hand), file for file; --write-run --as trace writes a run file whose run gives the same branches.
range=0.59,0.62
"$bin" find --preset paper-4.1 --trace "$range" --results "$work/found" --output t41 \
  --write-run "$work/t41.toml" --as trace > "$work/ft.txt" 2> "$work/ft.err" || fail "find --trace exits $?: $(cat "$work/ft.err")"
grep -q "^t41: [0-9]* branches in" "$work/ft.txt" || fail "find --trace did not report the trace: $(tail -3 "$work/ft.txt")"
solve_flags=$(grep "^  stickslip solve " "$work/ft.txt" | sed 's/^  stickslip solve //')
eval "\"\$bin\" trace $solve_flags --parameter omega --range $range --results \"\$work/by-hand\" --output t41" \
  > /dev/null 2>&1 || fail "trace by hand from the printed solve line exits $?"
diff -r "$work/found/t41" "$work/by-hand/t41" > "$work/diff.txt" || fail "find --trace differs from find then trace: $(head -5 "$work/diff.txt")"
[ "$(ls "$work/found/t41" | grep -c '^branch-')" -ge 2 ] || fail "find --trace over $range switched nowhere: $(ls "$work/found/t41")"
grep -q '^\[trace\]' "$work/t41.toml" && grep -q "^range = \[0.59, 0.62\]" "$work/t41.toml" || fail "the run file is no trace over $range"
"$bin" run --results "$work/from-file" "$work/t41.toml" > /dev/null 2>&1 || fail "stickslip run of the trace run file exits $?"
for f in trace.csv branch-1/branch.csv branch-2/branch.csv; do
  cmp -s "$work/found/t41/$f" "$work/from-file/t41/$f" || fail "the run file's trace differs in $f"
done

# The steps of the trace's branches, as continue and trace take them (--ds, --ds-min, --ds-max,
# --max-points): find --trace with them is trace by hand with them, file for file; the run file it
# writes keeps those not at their defaults (with --write-run alone too), and its run gives the same
# trace. Without --trace or --write-run, or out of range, they are refused before the work.
"$bin" find --preset paper-4.1 --trace "$range" --max-points 6 --ds-max 0.02 --results "$work/found" --output steps \
  --write-run "$work/steps.toml" --as trace > /dev/null 2> "$work/steps.err" || fail "find --trace with steps exits $?: $(cat "$work/steps.err")"
eval "\"\$bin\" trace $solve_flags --parameter omega --range $range --max-points 6 --ds-max 0.02 --results \"\$work/by-hand\" --output steps" \
  > /dev/null 2>&1 || fail "trace by hand with the steps exits $?"
diff -r "$work/found/steps" "$work/by-hand/steps" > "$work/diff.txt" || fail "find --trace with steps differs from trace with them: $(head -5 "$work/diff.txt")"
cmp -s "$work/found/steps/trace.csv" "$work/found/t41/trace.csv" && fail "--max-points 6 --ds-max 0.02 changed nothing in the trace"
grep -q "^ds_max = 0.02$" "$work/steps.toml" && grep -q "^max_points = 6$" "$work/steps.toml" && ! grep -q "^ds = " "$work/steps.toml" ||
  fail "the run file does not keep the steps given (only): $(cat "$work/steps.toml")"
"$bin" run --results "$work/from-file" "$work/steps.toml" > /dev/null 2>&1 || fail "stickslip run of the run file with steps exits $?"
cmp -s "$work/found/steps/trace.csv" "$work/from-file/steps/trace.csv" || fail "the run file's steps give another trace"
"$bin" find --preset paper-4.1 --write-run "$work/alone.toml" --ds 0.002 > /dev/null 2>&1 && grep -q "^ds = 0.002$" "$work/alone.toml" ||
  fail "find --write-run --ds 0.002 did not write the step: $(cat "$work/alone.toml")"
for refused in "--max-points 6|max-points = 6 is invalid: valid range with --trace or --write-run" \
  "--ds 0.001|ds = 0.001 is invalid: valid range with --trace or --write-run" \
  "--trace $range --output s2 --ds 0.5|ds = 0.5 is invalid: valid range 0 < ds-min (1e-08) <= ds <= ds-max (0.05)" \
  "--trace $range --output s2 --ds-min 0|ds-min = 0 is invalid: valid range ds-min > 0" \
  "--trace $range --output s2 --ds-max 1e-9|ds-max = 1e-09 is invalid: valid range ds-max >= ds-min (1e-08)" \
  "--trace $range --output s2 --max-points 0|max-points = 0 is invalid"; do
  "$bin" find --preset paper-4.1 ${refused%%|*} --results "$work/refused" > "$work/r.out" 2> "$work/r.err"
  code=$?
  [ "$code" -eq 2 ] && [ "$(wc -l < "$work/r.err")" -eq 1 ] && grep -qF "${refused#*|}" "$work/r.err" && [ ! -s "$work/r.out" ] &&
    [ ! -e "$work/refused" ] || fail "find ${refused%%|*}: exit $code, $(cat "$work/r.err")"
done

# A run file inside the trace's own directory is refused before the work, even with --force: the trace
# replaces that directory whole (before: a run file at branch-1/branch.csv was reported written and
# then replaced, and one at trace.json replaced the trace's, which then refused to write, exit 2
# after the work with the earlier trace damaged). Nothing written, the trace as it was.
for inside in trace.json branch-1/branch.csv notes.toml ../t41/new.toml; do
  "$bin" find --preset paper-4.1 --trace "$range" --results "$work/found" --output t41 \
    --write-run "$work/found/t41/$inside" --force > "$work/in.out" 2> "$work/in.err"
  code=$?
  [ "$code" -eq 2 ] && [ "$(wc -l < "$work/in.err")" -eq 1 ] && [ ! -s "$work/in.out" ] &&
    grep -qF "write-run = '$work/found/t41/$inside' is invalid: valid a file outside the trace's directory '$work/found/t41'" "$work/in.err" ||
    fail "--write-run $inside inside the trace: exit $code, $(cat "$work/in.err")"
  diff -r "$work/found/t41" "$work/by-hand/t41" > /dev/null || fail "--write-run $inside changed the trace"
done

# A run name with a quote and a backslash is a TOML string the run file escapes: `stickslip run`
# reads it back and writes that very name (before, the file did not parse).
name='q"uo\te'
"$bin" find --preset paper-4.1 --write-run "$work/$name.toml" > /dev/null 2> "$work/q.err" || fail "find --write-run '$name.toml' exits $?"
"$bin" run --results "$work/quoted" "$work/$name.toml" > /dev/null 2> "$work/q.err" || fail "run of '$name.toml' exits $?: $(cat "$work/q.err")"
[ -f "$work/quoted/$name/branch.csv" ] || fail "run of '$name.toml' did not write '$name/': $(ls "$work/quoted" 2>&1)"

# find --json: one object that python3 parses, equal to the text output.
"$bin" find --preset paper-4.1 --json > "$work/found.json" 2> "$work/json.err" || fail "find --json exits $?: $(cat "$work/json.err")"
"$bin" find --preset paper-4.1 > "$work/found.txt" 2>&1
/usr/bin/python3 - "$work/found.json" "$work/found.txt" <<'PY' || fail "find --json does not match the text output"
import json, sys
found = json.load(open(sys.argv[1]))
text = open(sys.argv[2]).read().splitlines()
line = lambda key: next(l for l in text if l.startswith(key)).split(None, 1)[1]
orbit = found["orbit"]
assert found["status"] == "found" and found["period_multiple"] == int(line("motion").split("k = ")[1].split()[0])
assert orbit["signature"] == line("signature") == found["signature"]
parameters = dict(item.split("=") for item in line("parameters").split())
assert {k: float(v) for k, v in parameters.items()} == orbit["parameters"], (parameters, orbit["parameters"])
assert list(orbit["unknowns"]) == line("unknowns").split()
solution = dict(item.split("=") for item in line("solution").split())
assert all(float(solution[key]) == orbit[key] for key in ("x10", "x20", "v10", "phi")), (solution, orbit)
assert orbit["unknowns"]["x10"] == orbit["x10"]
assert orbit["admissible"] is (line("smallest").split(": ")[1] == "admissible")
assert orbit["stable"] is (line("stability") == "stable")
assert orbit["verification"]["passed"] is (line("verification") == "passed")
PY
# Found nothing: the JSON says why (orbit null), the exit code is find's, nothing traced or written.
"$bin" find "${data[@]}" --max-multiple 2 --json > "$work/none.json" 2> /dev/null
code=$?
[ "$code" -eq 5 ] && /usr/bin/python3 -c 'import json, sys; f = json.load(open(sys.argv[1])); assert f["status"] == "not-periodic" and f["orbit"] is None' \
  "$work/none.json" || fail "find --json of a motion not periodic within 2: exit $code, $(cat "$work/none.json")"
"$bin" find "${data[@]}" --max-multiple 2 --trace 0.2,0.3 --results "$work/none" --output t --write-run "$work/none.toml" \
  > /dev/null 2> "$work/none.err"
code=$?
[ "$code" -eq 5 ] && [ "$(wc -l < "$work/none.err")" -eq 1 ] && [ ! -e "$work/none" ] && [ ! -e "$work/none.toml" ] ||
  fail "find --trace finding nothing: exit $code, $(cat "$work/none.err"), $(ls "$work")"

# Not periodic within --max-multiple 2 (the motion repeats after 4): exit 5, one line, no run file.
"$bin" find "${data[@]}" --max-multiple 2 --write-run "$work/none.toml" > /dev/null 2> "$work/np.err"
code=$?
[ "$code" -eq 5 ] || fail "max-multiple 2: exit $code (want 5)"
[ "$(wc -l < "$work/np.err")" -eq 1 ] && grep -q "not periodic with k <= 2" "$work/np.err" ||
  fail "max-multiple 2: message $(cat "$work/np.err")"
[ ! -e "$work/none.toml" ] || fail "max-multiple 2 wrote a run file"

# A permanent stick (at rest, u_r far above the forcing) has no orbit type: exit 5.
"$bin" find --set chi=0.3 --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=10 > /dev/null 2> "$work/stick.err"
code=$?
[ "$code" -eq 5 ] && grep -q "permanent stick" "$work/stick.err" || fail "permanent stick: exit $code, $(cat "$work/stick.err")"

expect_rejected() {  # expect_rejected <field> <expected text> <args...>
  local field=$1 text=$2
  shift 2
  local out="$work/out.toml"
  printf 'keep\n' > "$work/existing.toml"
  "$bin" find "$@" --write-run "$out" > "$work/stdout" 2> "$work/stderr"
  local code=$?
  local problem=""
  [ "$code" -eq 2 ] || problem+=" exit code $code (want 2);"
  [ "$(wc -l < "$work/stderr")" -eq 1 ] || problem+=" $(wc -l < "$work/stderr") stderr lines (want 1);"
  grep -q -- "$field" "$work/stderr" || problem+=" message does not name '$field';"
  grep -q -- "$text" "$work/stderr" || problem+=" message lacks '$text';"
  [ ! -e "$out" ] || problem+=" output file was created;"
  "$bin" find "$@" --write-run "$work/existing.toml" > /dev/null 2>&1
  [ "$(cat "$work/existing.toml")" = "keep" ] || problem+=" existing file was changed;"
  if [ -n "$problem" ]; then
    fail "[find $*]:$problem"
    sed 's/^/    stderr: /' "$work/stderr"
  else
    echo "ok   [find $*]: $(cat "$work/stderr")"
  fi
}

p=(--preset paper-4.1)
expect_rejected transients "0 <= transients <= 1000000" "${p[@]}" --transients -1
expect_rejected transients "0 <= transients <= 1000000" "${p[@]}" --transients 2000000
expect_rejected transients "0 <= transients <= 1000000" "${p[@]}" --transients 2.5
expect_rejected transients "finite number" "${p[@]}" --transients many
expect_rejected transients "finite number" "${p[@]}" --transients 1e999
expect_rejected max-multiple "1 <= max-multiple <= 999" "${p[@]}" --max-multiple 0
expect_rejected max-multiple "1 <= max-multiple <= 999" "${p[@]}" --max-multiple 1000
expect_rejected max-multiple "finite number" "${p[@]}" --max-multiple nan
expect_rejected tolerance "1e-12 <= tolerance <= 0.01" "${p[@]}" --tolerance 0
expect_rejected tolerance "1e-12 <= tolerance <= 0.01" "${p[@]}" --tolerance 0.5
expect_rejected tolerance "finite number" "${p[@]}" --tolerance -inf
expect_rejected confirmations "1 <= confirmations <= 100" "${p[@]}" --confirmations 0
expect_rejected omega "0.01 <= omega <= 100" "${p[@]}" --set omega=0
expect_rejected omega "finite number" "${p[@]}" --set omega=1e-300x
expect_rejected x10 "1e+06" "${p[@]}" --set x10=1e308
expect_rejected u_r "u_r" "${p[@]}" --set u_r=1e308
expect_rejected preset "paper-4.1" --preset paper-9
expect_rejected chi "missing" --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=0.3
expect_rejected trace "trace = '0.7,0.5' is invalid: valid range LO,HI with 0.01 <= LO < HI <= 100" "${p[@]}" --trace 0.7,0.5 --output t
expect_rejected trace "trace = 'nan' is not a finite number: valid range LO,HI" "${p[@]}" --trace nan,0.7 --output t
expect_rejected trace "trace = '0.5' is invalid: valid range LO,HI" "${p[@]}" --trace 0.5 --output t
# Not a part of the text (before: trace = '0.7,0.9' is not a finite number).
expect_rejected trace "trace = '0.5,0.7,0.9' is invalid: valid range LO,HI" "${p[@]}" --trace 0.5,0.7,0.9 --output t
expect_rejected trace "trace = '0.1,0.2' is invalid: valid range LO,HI that holds the start's omega = 0.6" "${p[@]}" \
  --trace 0.1,0.2 --output t
expect_rejected range "range = '0.1,0.2' is invalid: valid range LO,HI that holds the start's omega = 0.6" "${p[@]}" \
  --range 0.1,0.2
# Refused before the simulation (before: after 1e6 transient periods, the orbit printed first).
timeout 30 "$bin" find "${p[@]}" --transients 1000000 --trace 0.1,0.2 --output t > "$work/early.out" 2> "$work/early.err"
code=$?
[ "$code" -eq 2 ] && [ ! -s "$work/early.out" ] && grep -q "trace = '0.1,0.2' is invalid" "$work/early.err" ||
  fail "--trace without the start's omega is refused only after the simulation: exit $code, $(head -c 300 "$work/early.out")"
expect_rejected output "output is missing: valid a run name, with --trace" "${p[@]}" --trace 0.5,0.7
expect_rejected range "range = '0.7,0.5' is invalid" "${p[@]}" --range 0.7,0.5
expect_rejected range "range = '0.5,0.7' is invalid: valid left out with --trace" "${p[@]}" --trace 0.5,0.7 --output t --range 0.5,0.7
expect_rejected json "json = 'true' is invalid: valid without --trace" "${p[@]}" --trace 0.5,0.7 --output t --json
expect_rejected as "branch" "${p[@]}" --as branch

# An output path that cannot be written: exit 2 naming --write-run, before the work.
"$bin" find "${p[@]}" --write-run "$work" > /dev/null 2> "$work/dir.err"
code=$?
[ "$code" -eq 2 ] && grep -q "write-run" "$work/dir.err" || fail "--write-run a directory: exit $code, $(cat "$work/dir.err")"
"$bin" find "${p[@]}" --write-run "$work/no/such/dir/x.toml" > /dev/null 2> "$work/nodir.err"
code=$?
[ "$code" -eq 2 ] && grep -q "write-run" "$work/nodir.err" || fail "--write-run in a missing directory: exit $code"
[ ! -e "$work/no" ] || fail "--write-run in a missing directory created it"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "find: all cases ok"
