#!/usr/bin/env bash
# stickslip export --auto: AUTO-07p's own Python parsers (Debian's auto-07p) read the b., s. and d.
# files, and what they read equals the branch files: the b. file's measure columns (column 1, AUTO's
# default y axis, is max |x1|), the d. file's point numbers, labels and Floquet multipliers.
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
    from auto import parseB, parseD, parseS
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
measures = ["amplitude:x1", "amplitude:x2", "peak-to-peak:x2", "stick-fraction", "stops", "sticks",
            "friction-work", "equivalent-damping"]
assert b.coordnames[:9] == [parameter] + measures, b.coordnames
for n, row in enumerate(rows):
    for name in measures:
        expected = float(row[name])
        assert abs(b[name][n] - expected) <= 1e-9 * max(1.0, abs(expected)), (n, name, b[name][n], expected)
d = parseD.parseD(os.path.join(directory, "d." + run))
assert len(d) == len(rows), (len(d), len(rows))
for n, row in enumerate(rows):
    point = d[n]
    assert point["Point number"] == int(row["pt"]), (n, point["Point number"])
    label = int(row["label"].lstrip("ABCDEFGHIJKLMNOPQRSTUVWXYZ")) if row["label"] else 0
    assert point["Label"] == label, (n, point["Label"], row["label"])
    expected = sorted((float(row[f"floquet:mu{k}_re"]), float(row[f"floquet:mu{k}_im"])) for k in range(1, 5))
    got = sorted(tuple(mu) for mu in point["Multipliers"])
    assert all(abs(g - e) <= 1e-9 * max(1.0, abs(e)) for gm, em in zip(got, expected) for g, e in zip(gm, em)), \
        (n, got, expected)
    br, pt, it, value, step = point["Text"].splitlines()[1].split()  # the line after "BR PT IT"
    assert int(it) == int(row["newton_iterations"]), (n, it, row["newton_iterations"])
    assert abs(float(step) - float(row["step_size"])) <= 1e-9 * float(row["step_size"]), (n, step, row["step_size"])
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
print(f"{run}: AUTO reads {len(b)} points, {len(s)} labelled solutions, {len(d)} diagnostics")
PY
done
