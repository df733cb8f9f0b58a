#!/usr/bin/env bash
# stickslip simulate: the JSON has the documented shape; the CSV has a header and the expected
# number of rows; the exact and odeint methods report the same events; output is deterministic.
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$bin" simulate --preset paper-5.1 --periods 2 --json > "$work/exact.json"
"$bin" simulate --preset paper-5.1 --periods 2 --json --method odeint > "$work/odeint.json"
/usr/bin/python3 - "$work/exact.json" "$work/odeint.json" <<'PY'
import json, sys
exact = json.load(open(sys.argv[1]))
odeint = json.load(open(sys.argv[2]))
assert set(exact) == {"events"}, exact.keys()
assert len(exact["events"]) == len(odeint["events"]) > 0
for e, o in zip(exact["events"], odeint["events"]):
    assert set(e) == {"t", "kind", "mode_after", "state"}, e
    assert e["kind"] in ("stop", "stick-exit") and e["mode_after"] in ("slip-", "slip+", "stick")
    assert len(e["state"]) == 4 and e["state"][3] == 0.0
    assert (e["kind"], e["mode_after"]) == (o["kind"], o["mode_after"])
    assert abs(e["t"] - o["t"]) < 1e-6, (e["t"], o["t"])
print("json ok:", len(exact["events"]), "events")
PY

"$bin" simulate --preset paper-4.1 --periods 1 --csv "$work/a.csv" --samples-per-period 100 > /dev/null
"$bin" simulate --preset paper-4.1 --periods 1 --csv "$work/b.csv" --samples-per-period 100 > /dev/null
head -n 1 "$work/a.csv" | grep -qx "t,x1,x2,v1,v2,mode"
rows=$(($(wc -l < "$work/a.csv") - 1))
[ "$rows" -eq 101 ] || { echo "expected 101 rows, got $rows"; exit 1; }
cmp "$work/a.csv" "$work/b.csv"
echo "csv ok: $rows rows, deterministic"

# Sample i at i T/N for both methods (issue 22: odeint wrote 3,000 samples where exact wrote 3,001,
# a rounding boundary of the sample count): the same count and the same times.
for method in exact odeint; do
  "$bin" simulate --preset paper-4.1 --periods 3 --samples-per-period 1000 --method $method --csv "$work/$method.csv" > /dev/null
done
rows=$(($(wc -l < "$work/odeint.csv") - 1))
[ "$rows" -eq 3001 ] || { echo "odeint: expected 3001 rows, got $rows"; exit 1; }
cmp <(cut -d, -f1 "$work/exact.csv") <(cut -d, -f1 "$work/odeint.csv")
echo "csv ok: exact and odeint sample the same $rows times"

"$bin" simulate --preset paper-4.1 | grep -q "stop"
echo "table ok"

# --point: a labelled point of a stored run. Started on the continued section 5.1 orbit at TR2,
# the motion's events fall at the cumulative segment durations d1, d1 + d2, ... of that orbit.
root=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
"$bin" simulate --point paper-5.1-omega-up:TR2 --results "$root/results" --periods 1 --json > "$work/point.json"
/usr/bin/python3 - "$work/point.json" "$root/results/paper-5.1-omega-up/special-points.csv" <<'PY'
import csv, json, sys
events = json.load(open(sys.argv[1]))["events"]
row = next(r for r in csv.DictReader(open(sys.argv[2])) if r["label"] == "TR2")
ends, total = [], 0.0
for k in range(1, 5):
    total += float(row[f"d{k}"])
    ends.append(total)
times = [e["t"] for e in events]
assert len(times) >= 3, times
for t, end in zip(times, ends):
    assert abs(t - end) < 1e-8, (times, ends)
print("point ok:", len(times), "events at the orbit's segment ends")
PY
