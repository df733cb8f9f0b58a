#!/usr/bin/env bash
# stickslip simulate --transients N: the events shown are those of one simulation over N + P
# periods that fall after the transient (same times, the paper's absolute t, and same states);
# the CSV starts at t = N 2 pi/omega; N is bounded like --periods.
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for method in exact odeint; do
  "$bin" simulate --preset paper-6 --set x10=1 --periods 5 --json --method "$method" > "$work/whole.json"
  "$bin" simulate --preset paper-6 --set x10=1 --transients 3 --periods 2 --json --method "$method" > "$work/after.json"
  # Odeint restarted at t0 against Odeint through it: within its tolerances.
  tolerance=$([ "$method" = exact ] && echo 1e-8 || echo 1e-6)
  /usr/bin/python3 - "$work/whole.json" "$work/after.json" "$tolerance" <<'PY'
import json, math, sys
whole = json.load(open(sys.argv[1]))["events"]
after = json.load(open(sys.argv[2]))["events"]
tol = float(sys.argv[3])
t0 = 3 * 11.0  # paper-6: omega = 2 pi / 11
shown = [e for e in whole if e["t"] > t0 + 1e-9]
assert len(after) == len(shown) > 0, (len(after), len(shown))
assert after[0]["t"] >= t0
for a, w in zip(after, shown):
    assert (a["kind"], a["mode_after"]) == (w["kind"], w["mode_after"]), (a, w)
    assert abs(a["t"] - w["t"]) < tol, (a["t"], w["t"])
    assert max(abs(x - y) for x, y in zip(a["state"], w["state"])) < tol, (a["state"], w["state"])
print("transients ok:", len(after), "events after t0 =", t0)
PY
done

# The table says what was left out; the CSV's first sample is at t0.
"$bin" simulate --preset paper-4.1 --transients 2 --periods 1 --csv "$work/a.csv" --samples-per-period 10 > "$work/table.txt"
grep -q "^after 2 transient period(s), not shown: t=" "$work/table.txt"
/usr/bin/python3 - "$work/a.csv" <<'PY'
import math, sys
rows = open(sys.argv[1]).read().split("\n")[1:-1]
t0 = 2 * 2 * math.pi / 0.6
assert len(rows) == 11, len(rows)
assert abs(float(rows[0].split(",")[0]) - t0) < 1e-12 and abs(float(rows[-1].split(",")[0]) - 1.5 * t0) < 1e-9
PY
# Without --transients the output is as before: no "after" line.
! "$bin" simulate --preset paper-4.1 --periods 1 | grep -q "^after"

for bad in -1 2.5 1000001 abc; do
  set +e
  "$bin" simulate --preset paper-4.1 --transients "$bad" > "$work/out" 2> "$work/err"
  code=$?
  set -e
  [ "$code" -eq 2 ] || { echo "--transients $bad: exit $code"; exit 1; }
  grep -q "^error: transients = " "$work/err" || { cat "$work/err"; exit 1; }
  [ ! -s "$work/out" ]
done
"$bin" simulate --help | grep -q -- "--transients"
echo "simulate --transients ok"
