#!/usr/bin/env bash
# stickslip continue: the run file's keys as flags (user values, shooting, linear solver, fold
# and branch-point detection, both directions in one command, the restart's switch_branch and
# boundary), --point restarts, a closed branch
# reported as such, and bad values refused with exit 2 and nothing written.
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
src=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
base=(continue --preset paper-5.1 --parameter omega --range 0.3,0.9 --ds 0.005 --ds-max 0.05 --results "$work")

# Both directions: two runs, <output>-down and <output>-up, each as the run file with that
# direction writes it (the stored paper-5.1-omega-up/-down; check compares them).
"$bin" "${base[@]}" --direction both --user-value omega=0.58 --output p > "$work/both.txt"
[ "$(wc -l < "$work/both.txt")" -eq 2 ]
grep -q "^p-down: " "$work/both.txt" && grep -q "^p-up: " "$work/both.txt"
for d in down up; do
  cmp "$work/p-$d/special-points.csv" "$src/results/paper-5.1-omega-$d/special-points.csv"
  cmp "$work/p-$d/branch.csv" "$src/results/paper-5.1-omega-$d/branch.csv"
done

# A user value of another unknown (a released u_r) and of the parameter, each located there.
"$bin" "${base[@]}" --free u_r --fix phi --user-value u_r=0.5 --user-value omega=0.575 --max-points 40 \
  --output uz > /dev/null
/usr/bin/python3 - "$work/uz/special-points.csv" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["type"] == "UZ"]
assert rows, "no UZ"
for r in rows:
    assert abs(float(r["u_r"]) - 0.5) < 1e-9 or abs(float(r["omega"]) - 0.575) < 1e-9, r
PY

# Fold detection off: the fold at omega = 0.5868 is no special point; the rest is the same.
"$bin" "${base[@]}" --detect-folds false --detect-branch-points false --output nofold > /dev/null
! grep -q ",LP," "$work/nofold/special-points.csv"
grep -q ",LP," "$src/results/paper-5.1-omega-up/special-points.csv"
grep -q ",TR," "$work/nofold/special-points.csv"

# Multiple shooting with UMFPACK finds the same special points (to the check's tolerance).
"$bin" "${base[@]}" --shooting multiple --linear-solver umfpack --user-value omega=0.58 --output ms > /dev/null
/usr/bin/python3 - "$work/ms/special-points.csv" "$src/results/paper-5.1-omega-up/special-points.csv" <<'PY'
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:])
assert [r["type"] for r in a] == [r["type"] for r in b], ([r["type"] for r in a], [r["type"] for r in b])
for r, s in zip(a, b):
    assert abs(float(r["omega"]) - float(s["omega"])) < 1e-8 * (1 + abs(float(s["omega"]))), (r["omega"], s["omega"])
PY
grep -q '"shooting": "multiple"' "$work/ms/summary.json"

# A restart from a labelled point of a run under --results: the fold of the run above.
"$bin" continue --point p-up:LP4 --parameter omega --range 0.3,0.9 --direction down --max-points 20 \
  --results "$work" --output from-lp > "$work/lp.txt"
grep -q "^from-lp: 20 points" "$work/lp.txt"
head -2 "$work/from-lp/branch.csv" | tail -1 | cut -d, -f5 | grep -q "^0.58681886"

# The restart's kinds as flags give the run files' branches byte for byte: the fold's curve in
# (omega, u_r) (paper-5.1-fold-curve.toml) and the period-2 branch that leaves PD2
# (paper-5.2-period-2.toml), from copies of the runs they restart from.
mkdir "$work/kinds"
cp -r "$src/results/paper-5.1-omega-up" "$src/results/paper-5.2-omega-to-pd" "$work/kinds/"
"$bin" continue --point paper-5.1-omega-up:LP4 --boundary u_r --parameter omega --direction down --range 0.555,0.65 \
  --ds 0.002 --ds-max 0.01 --max-points 3000 --results "$work/kinds" --output fold-curve > /dev/null
"$bin" continue --point paper-5.2-omega-to-pd:PD2 --switch-branch --parameter omega --range 0.6,0.8 --ds 0.005 \
  --ds-max 0.02 --max-points 500 --results "$work/kinds" --output period-2 > /dev/null
for f in branch.csv special-points.csv; do
  cmp "$work/kinds/fold-curve/$f" "$src/results/paper-5.1-fold-curve/$f"
  cmp "$work/kinds/period-2/$f" "$src/results/paper-5.2-period-2/$f"
done

# A closed branch: section 5.1 past its type changes is a loop; it ends where it began.
"$bin" "${base[@]}" --continue-past-type-changes --max-points 100000 --output loop > "$work/loop.txt"
grep -q "closed-loop: the branch came back to its start" "$work/loop.txt"
/usr/bin/python3 - "$work/loop/branch.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
first, last = rows[0], rows[-1]
assert len(rows) < 5000, len(rows)
for k in ("omega", "x10", "x20", "v10", "phi"):
    assert abs(float(first[k]) - float(last[k])) < 1e-7, (k, first[k], last[k])
PY

# Round the loop from one of its special points (the SK where the sticking orbit's second
# reversal becomes a stick): the lap ends on it without finding it again.
"$bin" continue --point loop:SK8 --parameter omega --range 0.3,0.9 --ds 0.005 --ds-max 0.05 \
  --continue-past-type-changes --max-points 100000 --results "$work" --output loop-sk > "$work/loop-sk.txt"
grep -q "closed-loop" "$work/loop-sk.txt"
/usr/bin/python3 - "$work/loop-sk/special-points.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
start = float(rows[0]["omega"])
at_start = [r["label"] for r in rows if abs(float(r["omega"]) - start) < 1e-9]
assert at_start == [rows[0]["label"], rows[-1]["label"]] and rows[-1]["type"] == "EP", at_start
PY

# Bad values: exit 2, one line naming the option, nothing written.
expect_rejected() {
  local field=$1; shift
  set +e
  "$bin" "$@" > "$work/out" 2> "$work/err"
  local code=$?
  set -e
  [ "$code" -eq 2 ] || { echo "exit $code for: $*"; cat "$work/err"; exit 1; }
  [ "$(wc -l < "$work/err")" -eq 1 ] && grep -q "^error: $field" "$work/err" || { echo "for: $*"; cat "$work/err"; exit 1; }
  [ ! -e "$work/bad" ] && [ ! -e "$work/bad-up" ] && [ ! -e "$work/bad-down" ] || { echo "written: $*"; exit 1; }
}
expect_rejected "direction = 'sideways'" "${base[@]}" --direction sideways --output bad
expect_rejected "detect-folds = 'maybe'" "${base[@]}" --detect-folds maybe --output bad
expect_rejected "detect-branch-points = 'no'" "${base[@]}" --detect-branch-points no --output bad
expect_rejected "user-value = 'omega'" "${base[@]}" --user-value omega --output bad
expect_rejected "user-value = 'abc'" "${base[@]}" --user-value omega=abc --output bad
expect_rejected "user-value names 'chi'" "${base[@]}" --user-value chi=0.3 --output bad
expect_rejected "--shooting" "${base[@]}" --shooting double --output bad
expect_rejected "set" "${base[@]}" --set u_r=0.5 --set u_r=0.6 --output bad
expect_rejected "guess" "${base[@]}" --guess d1=3 --guess d1=3.1 --output bad
# The restart's kinds: with --point only, one at a time, at a point of their kind.
lp=(continue --point p-up:LP4 --parameter omega --range 0.3,0.9 --results "$work")
expect_rejected "switch-branch = true is invalid without point: valid with point RUN:LABEL" "${base[@]}" --switch-branch --output bad
expect_rejected "boundary = 'u_r' is invalid without point: valid with point RUN:LABEL" "${base[@]}" --boundary u_r --output bad
expect_rejected "boundary = '' is invalid" "${lp[@]}" --boundary '' --output bad
expect_rejected "boundary cannot go with switch-branch: give one of them" "${lp[@]}" --boundary u_r --switch-branch --output bad
expect_rejected "switch-branch = true is invalid at 'LP4'" "${lp[@]}" --switch-branch --output bad
expect_rejected "boundary = 'omega' is invalid at 'LP4'" "${lp[@]}" --boundary omega --output bad
expect_rejected "boundary = 'u_r' is invalid at 'EP1'" continue --point p-up:EP1 --boundary u_r --parameter omega \
  --range 0.3,0.9 --results "$work" --output bad
expect_rejected "continue-past-type-changes = true is invalid with boundary: valid false" "${lp[@]}" --boundary u_r \
  --continue-past-type-changes --output bad
# A trace has no side to switch to and follows no boundary's curve: refused, not traced (a trace
# with --switch-branch once traced the same up-going branch as both its chains).
pd=(trace --point paper-5.2-omega-to-pd:PD2 --parameter omega --range 0.7,0.74 --results "$work/kinds")
# trace takes neither flag (its --help does not offer them); a [trace] run file is refused at the keys.
expect_rejected "The following argument was not expected: --switch-branch" "${pd[@]}" --switch-branch --output bad
expect_rejected "The following arguments were not expected: u_r --boundary" "${pd[@]}" --boundary u_r --output bad
[ ! -e "$work/kinds/bad" ]
! "$bin" trace --help | grep -q -e "--switch-branch" -e "--boundary"
# A start that does not converge is named by the run's output, not as a run file "(command line)".
set +e
"$bin" continue --preset paper-4.1 --free u_r --fix phi --parameter omega --range 0.3,0.9 --results "$work" \
  --output nostart > /dev/null 2> "$work/err"
code=$?
set -e
[ "$code" -eq 3 ] && grep -q "^error: nostart: the start point does not converge" "$work/err" && [ ! -e "$work/nostart" ] ||
  { echo "exit $code"; cat "$work/err"; exit 1; }
# Both sides of PD2, where the range holds the first point of the branch that leaves it downwards
# only: refused, and the down side is not written either.
set +e
"$bin" continue --point paper-5.2-omega-to-pd:PD2 --switch-branch --parameter omega --range 0.73548,0.73548861 \
  --direction both --results "$work/kinds" --output bad > /dev/null 2> "$work/err"
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "excludes the first point of the branch that leaves 'PD2'" "$work/err" &&
  [ ! -e "$work/kinds/bad-down" ] && [ ! -e "$work/kinds/bad-up" ] || { echo "exit $code"; cat "$work/err"; ls "$work/kinds"; exit 1; }
for bad in 0 -1 nan inf 1e309; do expect_rejected "max-amplitude" "${base[@]}" --max-amplitude "$bad" --output bad; done

# A resonance: the §4.1 orbit (never sticking) continued up in omega towards omega1 = 0.7012302
# ends where its amplitude passes --max-amplitude (termination 'stopped'; every point before within
# it), or else where it has come within 1 % of omega1. Started above the bound, it ends at its start
# and says so.
p41=(continue --preset paper-4.1 --parameter omega --range 0.3,0.8 --ds 0.01 --ds-max 1 --results "$work")
"$bin" "${p41[@]}" --max-amplitude 20 --output res > "$work/res.txt"
grep -q "stopped: resonance: the amplitude max(|x1|, |x2|) = .* passed max_amplitude = 20 at omega = 0.6" "$work/res.txt" ||
  { cat "$work/res.txt"; exit 1; }
/usr/bin/python3 - "$work/res/branch.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
amplitude = [max(float(r["amplitude:x1"]), float(r["amplitude:x2"])) for r in rows]
assert amplitude[-1] > 20 and max(amplitude[:-1]) <= 20, amplitude[-3:]
assert 0.65 < float(rows[-1]["omega"]) < 0.99 * 0.7012302, rows[-1]["omega"]
PY
"$bin" "${p41[@]}" --output res-near > "$work/res-near.txt"
# --resonance-approach 0 turns the approach off: the amplitude's bound ends the branch instead.
"$bin" "${p41[@]}" --resonance-approach 0 --max-amplitude 200 --output res-far > "$work/res-far.txt"
grep -q "stopped: resonance: the amplitude max(|x1|, |x2|) = .* passed max_amplitude = 200 at omega = 0.69" "$work/res-far.txt" ||
  { cat "$work/res-far.txt"; exit 1; }
for bad in -0.1 1 nan; do expect_rejected "resonance-approach" "${base[@]}" --resonance-approach "$bad" --output bad; done
grep -q "stopped: resonance: at omega_1 = 0.7012301669, a natural frequency of the undamped slip" "$work/res-near.txt" ||
  { cat "$work/res-near.txt"; exit 1; }
/usr/bin/python3 - "$work/res-near/branch.csv" <<'PY'
import csv, sys
omega = [float(r["omega"]) for r in csv.DictReader(open(sys.argv[1]))]
assert 0.99 * 0.7012302 <= omega[-1] < 0.7012302 and max(omega[:-1]) < 0.99 * 0.7012302, omega[-3:]
PY
"$bin" "${p41[@]}" --max-amplitude 3 --output res-start > "$work/res-start.txt"
grep -q "^res-start: 1 points in .*; stopped: resonance: the amplitude .* of the start is above max_amplitude = 3" "$work/res-start.txt" ||
  { cat "$work/res-start.txt"; exit 1; }
# Both outputs are checked before either run: a file in the way of -up leaves no -down.
touch "$work/bad-up"
set +e
"$bin" "${base[@]}" --direction both --output bad > /dev/null 2> "$work/err"
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "^error: output" "$work/err" && [ ! -e "$work/bad-down" ] && [ -f "$work/bad-up" ] ||
  { echo "exit $code"; cat "$work/err"; exit 1; }
echo "continue flags ok"
