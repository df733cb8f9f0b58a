#!/usr/bin/env bash
# stickslip check passes on the stored results and fails, naming the value, on a perturbed copy;
# a run's files are byte-identical between runs.
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
root=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$root/continuation-scripts/paper-5.1-omega-up.toml"
cp -r "$root/results" "$work/results"
"$bin" check --results "$work/results" "$run"

# The same run file gives byte-identical files, summary.json included (no time, no host in them).
(cd "$root" && "$bin" run --results "$work/first" continuation-scripts/paper-5.1-omega-up.toml > /dev/null)
(cd "$root" && "$bin" run --results "$work/second" continuation-scripts/paper-5.1-omega-up.toml > /dev/null)
diff -r "$work/first" "$work/second"

# Move the located fold by a relative 1e-6 (far above the 1e-8 tolerance).
file="$work/results/paper-5.1-omega-up/special-points.csv"
/usr/bin/python3 - "$file" <<'PY'
import sys
path = sys.argv[1]
lines = open(path).read().splitlines()
header = lines[0].split(",")
omega = header.index("omega")
for i, line in enumerate(lines[1:], 1):
    fields = line.split(",")
    if fields[1].startswith("LP"):
        fields[omega] = repr(float(fields[omega]) * (1 + 1e-6))
        lines[i] = ",".join(fields)
        break
else:
    sys.exit("no LP in " + path)
open(path, "w").write("\n".join(lines) + "\n")
PY
if "$bin" check --results "$work/results" "$run" > "$work/out"; then
  echo "FAIL: check passed on a perturbed file"
  exit 1
fi
cat "$work/out"
grep -q "special-points.csv *LP[0-9]* *omega" "$work/out"
echo "check fails on the perturbed fold, as it must"

# Edits one column of one labelled row of a fresh copy of the stored results:
# perturb <label prefix> <column> <python expression of the stored text v>.
perturb() {
  rm -rf "$work/results" && cp -r "$root/results" "$work/results"
  /usr/bin/python3 - "$work/results/paper-5.1-omega-up/special-points.csv" "$@" <<'PY'
import sys
path, prefix, column, expression = sys.argv[1:]
lines = open(path).read().splitlines()
k = lines[0].split(",").index(column)
for i, line in enumerate(lines[1:], 1):
    fields = line.split(",")
    if fields[1].startswith(prefix):
        fields[k] = str(eval(expression, {"v": fields[k]}))
        lines[i] = ",".join(fields)
        break
else:
    sys.exit(f"no {prefix} in {path}")
open(path, "w").write("\n".join(lines) + "\n")
PY
}

# A multiplier moved by 1e-5 (tolerance 1e-6), and the stability of a point whose multipliers are
# clear of the unit circle flipped: both are reported.
expect_difference() {  # expect_difference <pattern of the reported line>
  if "$bin" check --results "$work/results" "$run" > "$work/out"; then
    echo "FAIL: check passed, expected a difference matching '$1'"
    exit 1
  fi
  grep -q "$1" "$work/out"
}
perturb EP floquet:mu1_re "float(v) + 1e-5"
expect_difference "EP1 *multiplier"
perturb EP stable "1 - int(v)"
expect_difference "EP1 *stable"
# At the torus point the multipliers are on the unit circle and rounding decides the flag: it is
# not compared there.
perturb TR stable "1 - int(v)"
"$bin" check --results "$work/results" "$run" > /dev/null
# Multipliers are matched to the nearest, not by position or by sorting: the stored TR row's
# multipliers reversed, and its complex pair's real parts moved apart by 2e-9 against the sign
# of their imaginary parts (which would turn a sort by real part against the fresh pair), pass.
rm -rf "$work/results" && cp -r "$root/results" "$work/results"
/usr/bin/python3 - "$work/results/paper-5.1-omega-up/special-points.csv" <<'PY'
import sys
path = sys.argv[1]
lines = open(path).read().splitlines()
header = lines[0].split(",")
re_columns = [k for k, c in enumerate(header) if c.startswith("floquet:mu") and c.endswith("_re")]
for i, line in enumerate(lines[1:], 1):
    fields = line.split(",")
    if fields[1].startswith("TR"):
        mu = [[float(fields[k]), float(fields[k + 1])] for k in re_columns]
        assert any(m[1] != 0.0 for m in mu), "TR without a complex pair"
        for m in mu:
            m[0] -= 1e-9 if m[1] > 0 else -1e-9 if m[1] < 0 else 0.0
        for k, m in zip(re_columns, reversed(mu)):
            fields[k], fields[k + 1] = repr(m[0]), repr(m[1])
        lines[i] = ",".join(fields)
        break
else:
    sys.exit("no TR in " + path)
open(path, "w").write("\n".join(lines) + "\n")
PY
"$bin" check --results "$work/results" "$run" > /dev/null
echo "check compares multipliers, and the stability flag where it is decided"
