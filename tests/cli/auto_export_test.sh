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
# A [model]'s run (a branch of the five-mass chain's trace): the b. file's columns are the model's
# (omega, amplitude:m1 .. m5, ...), the s. file holds its ten-component state sampled by the closed
# forms from the stored start over one period, which comes back to it, and PAR(1..4) = omega,
# F_k, F_s, v_b with PAR(11) = 2 pi/omega. The model is read from the run file the summary names,
# relative to where the run was made (the source tree).
model_run="$work/chain/branch-3"
mkdir -p "$work/chain"
cp -r "$root/results/models/five-mass-chain-omega-trace/branch-3" "$model_run"
(cd "$root" && "$bin" export --auto "$model_run")
/usr/bin/python3 - "$model_run" <<'PY'
import csv, math, os, sys
sys.path.insert(0, "/usr/lib/auto-07p/python")
import numpy
numpy.bool = bool
import io, contextlib
with contextlib.redirect_stdout(io.StringIO()):
    from auto import parseB, parseS
directory = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(directory, "branch.csv"))))
labelled = [r for r in rows if r["label"]]
b = parseB.parseB(os.path.join(directory, "b.branch-3"))
assert len(b) == len(rows) and b.coordnames[:7] == ["omega"] + [f"amplitude:m{k}" for k in range(1, 6)] + ["peak-to-peak:m5"], b.coordnames
s = parseS.parseS(os.path.join(directory, "s.branch-3"))
assert len(s) == len(labelled), (len(s), len(labelled))
names = [f"m{k}_0" for k in range(1, 6)] + [f"v_m{k}_0" for k in range(1, 5)]
for solution, row in zip(s, labelled):
    omega = float(row["omega"])
    par = [solution[f"PAR({k})"] for k in range(1, 5)]
    assert all(abs(a - e) <= 1e-9 * max(1.0, abs(e)) for a, e in zip(par, [omega, float(row["F_k"]), float(row["F_s"]), 0.0])), par
    assert abs(solution["PAR(11)"] - 2 * math.pi / omega) <= 1e-9 * 2 * math.pi / omega
    u = solution.coordarray
    assert u.shape == (10, 101), u.shape
    start = [float(row[n]) for n in names] + [0.0]
    assert all(abs(u[i][0] - start[i]) <= 1e-9 for i in range(10)), (u[:, 0], start)
    assert all(abs(u[i][-1] - u[i][0]) <= 1e-8 for i in range(10)), "not periodic"
print(f"five-mass chain: AUTO reads {len(b)} points, {len(s)} labelled solutions of 10 components")
PY
# Every branch of every [model] trace in results/ exports, labels at grazings (GR), crossings (SK)
# and tori (NS) included: their orbits are sampled by the closed forms, which a simulator may not
# follow where a margin vanishes (it took the other side at 15 of them).
mkdir -p "$work/all"
count=0
for branch in "$root"/results/models/*-trace/branch-* "$root"/results/atlases/*/trace-*/branch-*; do
  grep -q '"model": "linear-oscillator"' "$branch/summary.json" 2> /dev/null || continue
  count=$((count + 1))
  copy="$work/all/$count/$(basename "$branch")"
  mkdir -p "$(dirname "$copy")" && cp -r "$branch" "$copy"
  (cd "$root" && "$bin" export --auto "$copy" > /dev/null) || { echo "FAIL: export --auto of $branch"; exit 1; }
done
[ "$count" -ge 50 ] || { echo "FAIL: only $count [model] branches found in results/"; exit 1; }
echo "every [model] branch in results exports: $count"
# A run stored before the friction measures existed: read with them nan, exported with every value
# its own right-aligned field (NaN too), which AUTO's parser reads, the measures read back as NaN.
old=paper-5.1-omega-old
mkdir "$work/$old"
cp "$root/results/paper-5.1-omega-up/summary.json" "$work/$old/"
for f in branch.csv special-points.csv; do
  /usr/bin/python3 - "$root/results/paper-5.1-omega-up/$f" "$work/$old/$f" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
header = lines[0].split(",")
drop = {header.index("friction-work"), header.index("equivalent-damping")}
with open(sys.argv[2], "w") as out:
    for line in lines:
        out.write(",".join(x for i, x in enumerate(line.split(",")) if i not in drop) + "\n")
PY
done
"$bin" export --auto "$work/$old"
/usr/bin/python3 - "$work/$old" <<'PY'
import math, os, sys
sys.path.insert(0, "/usr/lib/auto-07p/python")
import numpy
numpy.bool = bool
import io, contextlib
with contextlib.redirect_stdout(io.StringIO()):
    from auto import parseB
directory = sys.argv[1]
b = parseB.parseB(os.path.join(directory, "b.paper-5.1-omega-old"))
assert "friction-work" in b.coordnames and "equivalent-damping" in b.coordnames, b.coordnames
assert all(math.isnan(v) for v in b["friction-work"]) and all(math.isnan(v) for v in b["equivalent-damping"])
assert all(v > 0 for v in b["amplitude:x1"])
lines = [l for l in open(os.path.join(directory, "b.paper-5.1-omega-old")) if not l.startswith("   0")]
assert len({len(l.split()) for l in lines}) == 1, {len(l.split()) for l in lines}
print("old-format run: AUTO reads the friction measures as NaN, every line its fields")
PY
