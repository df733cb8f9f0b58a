#!/usr/bin/env bash
# stickslip map from a [model]'s trace: Den Hartog's oscillator (one mass, k = m = 1, forcing 1)
# with the kinetic level beta = 0.2, traced in omega at F_s = 0.5 and mapped over (omega, F_s). Its
# non-sticking orbit does not depend on F_s, and its turning points stick where the force that
# holds them, r^2 X(r, beta) (Den Hartog's amplitude X), is at most F_s: every curve point lies on
# F_s = r^2 X. The files are the same bytes twice, a curve's label restarts (its run names the
# model's file), a user's comparison.md stays; then the refusals: exit 2, one line, nothing written.
source "$(dirname "$0")/expect.sh"
sed 's/parameters = { omega = 1.5, F_k = 0.25, F_s = 0.25 }/parameters = { omega = 0.7, F_k = 0.2, F_s = 0.5 }/' \
  "$root/continuation-scripts/models/den-hartog.toml" > "$work/dh.toml"
cd "$work" || exit 1
"$bin" find --model dh.toml --trace 0.55,0.8 --results "$work" --output dh > /dev/null 2>&1 && pass || fail "the trace"
map() { "$bin" map --trace "$work/dh" --second F_s --second-from 0.25 --second-to 0.8 "$@"; }
map --output "$work/out/m" > "$work/map.txt" 2>&1 && pass || fail "the map: $(cat "$work/map.txt")"

/usr/bin/python3 - "$work/out/m" <<'PY' && pass ||
import csv, json, math, sys
beta = 0.2
def holding(r):  # r^2 X(r, beta): Den Hartog (1931), V = 1/(1 - r^2), U = tan(pi/(2r))/r
    v, u = 1 / (1 - r * r), math.tan(math.pi / (2 * r)) / r
    return r * r * math.sqrt(v * v - beta * beta * u * u)
rows = list(csv.DictReader(open(sys.argv[1] + "/curves.csv")))
assert len(rows) > 10, len(rows)
assert "m1_0" in rows[0] and "F_k" in rows[0], list(rows[0])
worst = max(abs(float(r["F_s"]) - holding(float(r["omega"]))) for r in rows)
assert worst <= 1e-9, worst
regions = json.load(open(sys.argv[1] + "/regions.json"))["regions"]
labels = sorted(r["label"] for r in regions)
assert len(labels) == 2 and any("stick" in l for l in labels) and any("slip+ / antisymmetric (stable)" == l for l in labels), labels
assert json.load(open(sys.argv[1] + "/curve-1/summary.json"))["units"]["force"] == "N"
PY
  fail "the map's curves are not on F_s = r^2 X(r, 0.2), or its regions are not the two sides"

map --output "$work/again" > /dev/null 2>&1 && diff -r "$work/out/m" "$work/again" > /dev/null && pass ||
  fail "a second map gives other bytes"
# (on the type boundary its margin is zero to rounding: exit 4, not a motion, but solved and verified)
"$bin" solve --point curve-1:EP1 --results "$work/out/m" > "$work/solve.txt" 2>&1
grep -q "^verification passed" "$work/solve.txt" && pass || fail "solve from a curve's label: $(cat "$work/solve.txt")"
echo mine > "$work/again/comparison.md"
map --output "$work/again" > /dev/null 2>&1 && [ "$(cat "$work/again/comparison.md")" = mine ] && pass ||
  fail "a map over a map removed the user's comparison.md"

expect 2 "brute-force = 'x.csv' is invalid" map --brute-force x.csv --output "$work/out/x"
expect 2 "second = 'u_r' is invalid: valid range omega, F_k, F_s, v_b" \
  "$bin" map --trace "$work/dh" --second u_r --second-from 0.3 --second-to 0.6 --output "$work/out/x"
expect 2 "second = 'omega' is invalid: valid range a parameter other than omega" \
  "$bin" map --trace "$work/dh" --second omega --second-from 0.3 --second-to 0.6 --output "$work/out/x"
expect 2 "second-from = 0.5 is invalid: valid range < second_max (0.500000000001) by more than 1e-08" \
  "$bin" map --trace "$work/dh" --second F_s --second-from 0.5 --second-to 0.500000000001 --output "$work/out/x"
expect 2 "second-to = 0.9 is invalid: valid range one with which the trace's F_s" \
  "$bin" map --trace "$work/dh" --second F_k --second-from 0.1 --second-to 0.9 --output "$work/out/x"
expect 2 "second = 'v_b' is invalid: valid range a parameter other than v_b: the trace's branch-1 holds the antisymmetric" \
  "$bin" map --trace "$work/dh" --second v_b --second-from 0 --second-to 0.1 --output "$work/out/x"
finish
