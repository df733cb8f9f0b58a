#!/usr/bin/env bash
# stickslip export --auto: AUTO-07p's own Python parsers (Debian's auto-07p) read the b. and s.
# files, and what they read equals the branch files.
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
root=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for run in paper-5.1-omega-up paper-6-omega-up; do
  cp -r "$root/results/$run" "$work/$run"
  "$bin" export --auto "$work/$run"
  /usr/bin/python3 - "$work/$run" "$run" <<'PY'
import csv, json, math, os, sys
sys.path.insert(0, "/usr/lib/auto-07p/python")
import numpy
numpy.bool = bool  # AUTO-07p 0.9.2's parsers predate numpy 1.24
import io, contextlib
with contextlib.redirect_stdout(io.StringIO()):
    from auto import parseB, parseS
directory, run = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(os.path.join(directory, "branch.csv"))))
parameter = json.load(open(os.path.join(directory, "summary.json")))["parameter"]
b = parseB.parseB(os.path.join(directory, "b." + run))
assert len(b) == len(rows), (len(b), len(rows))
codes = {"EP": "EP", "LP": "LP", "BP": "BP", "UZ": "UZ", "PD": "PD", "TR": "TR"}
labelled = [r for r in rows if r["label"]]
assert b.getLabels() == list(range(1, len(labelled) + 1)), b.getLabels()
for k, row in enumerate(labelled, 1):
    point = b.getLabel(k)
    kind = row["label"].rstrip("0123456789")
    assert point["TY name"] == codes.get(kind, "UZ"), (k, point["TY name"], kind)
    assert abs(point[parameter] - float(row[parameter])) <= 1e-9 * abs(float(row[parameter]))
    assert (point["PT"] < 0) == (row["stable"] == "1"), (k, point["PT"], row["stable"])
s = parseS.parseS(os.path.join(directory, "s." + run))
assert len(s) == len(labelled)
for solution, row in zip(s, labelled):
    omega = float(row["omega"])
    assert abs(solution["PAR(3)"] - omega) <= 1e-9 * omega
    assert abs(solution["PAR(11)"] - 2 * math.pi / omega) <= 1e-9
    u = solution.coordarray
    start = [float(row["x10"]), float(row["x20"]), float(row["v10"]), 0.0]
    assert all(abs(u[i][0] - start[i]) <= 1e-9 for i in range(4)), (u[:, 0], start)
    assert all(abs(u[i][-1] - u[i][0]) <= 1e-8 for i in range(4)), "not periodic"
print(f"{run}: AUTO reads {len(b)} points, {len(s)} labelled solutions")
PY
done
