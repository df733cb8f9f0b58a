#!/usr/bin/env bash
# stickslip map: the orbit-type map of a rectangle from a stored trace; the same bytes from run to
# run; a curve's directory an ordinary run that `run` restarts from; bad input refused with exit 2,
# one line naming the option, and nothing written.
source "$(dirname "$0")/expect.sh"
cd "$root" || exit 1  # the trace's run file is named relative to the source tree
t51=(--trace results/paper-5.1-omega-trace --second u_r)
rect=(--second-from 0.4 --second-to 0.6 --first-from 0.53 --first-to 0.6 --raster 64)

"$bin" map --help > "$work/help.txt" && pass || fail "map --help"
for word in --trace --second-from --first-to --brute-force --output --raster; do
  grep -q -- "$word" "$work/help.txt" && pass || fail "help lacks $word"
done

"$bin" map "${t51[@]}" "${rect[@]}" --output "$work/m1" > "$work/m1.txt" 2> "$work/m1.err" && pass || fail "map: $(cat "$work/m1.err")"
for f in curves.csv regions.json curve-1/branch.csv curve-1/special-points.csv curve-1/summary.json; do
  [ -s "$work/m1/$f" ] && pass || fail "m1/$f missing"
done
"$bin" map "${t51[@]}" "${rect[@]}" --output "$work/m2" > /dev/null 2>&1 && pass || fail "second map"
diff -r "$work/m1" "$work/m2" > /dev/null && pass || fail "a second run gives other bytes"
# Over the map just written: it is replaced, with the same bytes, and the user's files in it (named
# like a curve's directory or not) move into the new one and are listed.
echo "mine" > "$work/m2/curve-notes.md"
mkdir "$work/m2/curve-1-continued" && echo "mine" > "$work/m2/curve-1-continued/notes.txt"
"$bin" map "${t51[@]}" "${rect[@]}" --output "$work/m2" > "$work/m2.txt" 2>&1 && pass || fail "map over a map"
[ "$(cat "$work/m2/curve-notes.md" "$work/m2/curve-1-continued/notes.txt" 2>&1)" = "$(printf 'mine\nmine')" ] && pass ||
  fail "a map written over a map lost the user's files: $(ls "$work/m2")"
grep -q "kept 2 other file(s): curve-1-continued, curve-notes.md" "$work/m2.txt" && pass || fail "kept files not listed: $(cat "$work/m2.txt")"
rm -r "$work/m2/curve-notes.md" "$work/m2/curve-1-continued"
diff -r "$work/m1" "$work/m2" > /dev/null && pass || fail "a map written over a map gives other bytes"
/usr/bin/python3 - "$work/m1" <<'PY' && pass || fail "regions.json and curves.csv of m1"
import csv, json, sys
d = sys.argv[1]
m = json.load(open(d + "/regions.json"))
assert m["first"] == "omega" and m["second"] == "u_r", m["first"]
assert len(m["curves"]) >= 2 and m["regions"], (len(m["curves"]), len(m["regions"]))
rows = list(csv.DictReader(open(d + "/curves.csv")))
for r in rows:  # every point in the rectangle (its edges to rounding)
    assert 0.53 - 1e-9 <= float(r["omega"]) <= 0.6 + 1e-9 and 0.4 - 1e-9 <= float(r["u_r"]) <= 0.6 + 1e-9, r
assert {c["id"] for c in m["curves"]} == {int(r["curve"]) for r in rows}
last = {}
for r in rows:
    last[int(r["curve"])] = r
for c in m["curves"]:
    assert c["end"] in ("parameter-bound", "terminal-event", "max-points"), c
    # The special points under the labels a run restarts from (two at one point have two labels).
    stored = [(r["label"], r["type"]) for r in csv.DictReader(open(f"{d}/curve-{c['id']}/special-points.csv"))]
    assert [(p["label"], p["type"]) for p in c["special_points"]] == stored, (c["special_points"], stored)
    # A curve that leaves the rectangle through its second parameter ends on the edge (located EP),
    # the message naming the parameter and the edge's value ("reached u_r = 0.4").
    for bound in (0.4, 0.6):
        if c["message"] == f"reached u_r = {bound}":
            assert abs(float(last[c["id"]]["u_r"]) - bound) <= 1e-9, (c, last[c["id"]]["u_r"])
            assert c["special_points"][-1]["type"] == "EP", c
    assert "lambda" not in c["message"] and "_min" not in c["message"] and "_max" not in c["message"], c
PY

# A later run restarts from a curve's labelled point (results root: the map's directory).
cat > "$work/restart.toml" <<'TOML'
output = "from-curve"
[start]
restart = { run = "curve-1", label = "EP1" }
[continuation]
parameter = "omega"
direction = "down"
range = [0.5, 0.6]
max_points = 5
TOML
"$bin" run --results "$work/m1" "$work/restart.toml" > "$work/restart.txt" 2>&1 && pass || fail "restart from curve-1:EP1: $(cat "$work/restart.txt")"
rm -rf "$work/m1/from-curve"

# A trace whose preset chooses its unknowns (paper-4.2: u_s released, u_r tied to it): the map
# continues its orbits with them (with the defaults the system is not square).
"$bin" map --trace results/paper-4.2-omega-trace --second chi --second-from 0.65 --second-to 0.75 --first-from 0.5 --first-to 0.6 \
  --raster 16 --output "$work/m42" > "$work/m42.txt" 2>&1 && pass || fail "map of the paper-4.2 trace: $(cat "$work/m42.txt")"

# Bad input: exit 2, one line naming the option, nothing written into $work/out.
expect 2 "second-from" "$bin" map "${t51[@]}" --second-from 0.6 --second-to 0.4 --output "$work/out/m"
expect 2 "second-from" "$bin" map "${t51[@]}" --second-from 1e300 --second-to 0.4 --output "$work/out/m"
expect 2 "second-to" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 1e300 --output "$work/out/m"
expect 2 "second-from" "$bin" map "${t51[@]}" --second-from nan --second-to 0.6 --output "$work/out/m"
expect 2 "second-from = 0.001 is invalid: valid range a valid u_r: u_s = 0.0138 <= u_r <= 1000" \
  "$bin" map "${t51[@]}" --second-from 0.001 --second-to 0.6 --output "$work/out/m"
# u_s given above the trace's u_r: u_s is named, with its range given u_r (before the fix: "a valid
# u_r: u_s = 1000 <= u_r <= 1000", a range that holds the value).
expect 2 "second-to = 1000 is invalid: valid range a valid u_s: 1e-06 <= u_s <= u_r = 0.4962" \
  "$bin" map --trace results/paper-5.1-omega-trace --second u_s --second-from 1e-6 --second-to 1000 --output "$work/out/m"
# A damaged trace (chi = 5 in a branch file) is named by its file, line and column, not blamed on
# the rectangle's bounds.
cp -r results/paper-5.1-omega-trace "$work/damaged"
sed -i '2s/^1,EP1,0.22,/1,EP1,5,/' "$work/damaged/branch-1/branch.csv"
expect 2 "$work/damaged/branch-1/branch.csv:2: column 'chi' = '5' is invalid: valid 0.01 <= chi <= 0.99" \
  "$bin" map --trace "$work/damaged" --second u_s --second-from 0.01 --second-to 0.02 --output "$work/out/m"
expect 2 "first-from" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --first-from 0.7 --first-to 0.6 --output "$work/out/m"
# A rectangle the trace does not pass through (no curve starts in it; no orbit is continued from it).
expect 2 "second-from = 0.7 is invalid: valid range <= 0.4962" "$bin" map "${t51[@]}" --second-from 0.7 --second-to 0.8 --output "$work/out/m"
expect 2 "second-to = 0.45 is invalid: valid range >= 0.4962" "$bin" map "${t51[@]}" --second-from 0.3 --second-to 0.45 --output "$work/out/m"
expect 2 "first-from = 0.8 is invalid" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --first-from 0.8 --first-to 0.9 --output "$work/out/m"
expect 2 "first-to = 0.52 is invalid" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --first-from 0.5 --first-to 0.52 --output "$work/out/m"
# From another directory (the trace's run file, named relative to the source tree, not found): the
# same one line.
expect 2 "second-from = 0.7 is invalid" env -C "$work" "$bin" map --trace "$root/results/paper-5.1-omega-trace" --second u_r \
  --second-from 0.7 --second-to 0.8 --output "$work/out/m"
# A second parameter the trace does not hold (paper-4.2 releases u_s and ties u_r to it).
expect 2 "second = u_r is invalid: valid range a parameter the trace holds" \
  "$bin" map --trace results/paper-4.2-omega-trace --second u_r --second-from 0.2 --second-to 0.3 --output "$work/out/m"
expect 2 "first-to" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --first-to -1e300 --output "$work/out/m"
expect 2 "second" "$bin" map --trace results/paper-5.1-omega-trace --second omega --second-from 0.4 --second-to 0.6 --output "$work/out/m"
expect 2 "second" "$bin" map --trace results/paper-5.1-omega-trace --second stiffness --second-from 0.4 --second-to 0.6 --output "$work/out/m"
expect 2 "second" "$bin" map --trace results/paper-5.1-omega-trace --second-from 0.4 --second-to 0.6 --output "$work/out/m"
expect 2 "trace" "$bin" map --trace "$work/none" --second u_r --second-from 0.4 --second-to 0.6 --output "$work/out/m"
expect 2 "trace" "$bin" map --trace results/paper-5.1-omega-up --second u_r --second-from 0.4 --second-to 0.6 --output "$work/out/m"
# A trace without branches (it read as one, and the map took its first point: a crash).
mkdir -p "$work/empty-trace"
/usr/bin/python3 - results/paper-5.1-omega-trace "$work/empty-trace" <<'PY'
import json, sys
t = json.load(open(sys.argv[1] + "/trace.json"))
t["branches"] = []
t["directions"] = [dict(d, branches=[]) for d in t["directions"]]
json.dump(t, open(sys.argv[2] + "/trace.json", "w"), indent=2)
open(sys.argv[2] + "/trace.csv", "w").write(open(sys.argv[1] + "/trace.csv").readline())
PY
expect 2 "trace = '$work/empty-trace' is invalid: valid range a trace with points" \
  "$bin" map --trace "$work/empty-trace" --second u_r --second-from 0.4 --second-to 0.6 --first-from 0.5 --first-to 0.6 --output "$work/out/m"
expect 2 "raster" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --raster 5 --output "$work/out/m"
expect 2 "min-region" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --min-region 1e300 --output "$work/out/m"
expect 2 "brute-force" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --brute-force "$work/none.csv" --output "$work/out/m"
expect 2 "brute-force = ''" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --brute-force "" --output "$work/out/m"
# Brute-force maps that cannot be compared: no cell in the rectangle (the §6 grid), no cell at all,
# a shard (some rows of a grid: the grid steps are not the cells' spacing).
bf51=results/maps/paper-5.1-omega-u_r-brute-force.csv
expect 2 "valid range a map with cells in the rectangle" \
  "$bin" map "${t51[@]}" "${rect[@]}" --brute-force results/maps/paper-6-omega-u_r-brute-force.csv --output "$work/out/m"
head -n 1 "$bf51" > "$work/header-only.csv"
expect 2 "brute-force = '$work/header-only.csv' (0 cells)" \
  "$bin" map "${t51[@]}" "${rect[@]}" --brute-force "$work/header-only.csv" --output "$work/out/m"
awk -F, 'NR == 1 || $2 == 3' "$bf51" > "$work/shard.csv"
expect 2 "valid range a whole map, every cell of its grid" \
  "$bin" map "${t51[@]}" "${rect[@]}" --brute-force "$work/shard.csv" --output "$work/out/m"
echo "not a map" > "$work/out/file"
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output "$work/out/file"
mkdir -p "$work/out/mine" && echo "mine" > "$work/out/mine/notes.txt"
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output "$work/out/mine"
# A regions.json of the user's (not a map's) does not make the directory a map's.
mkdir -p "$work/out/geo" && echo '{"type": "FeatureCollection", "features": []}' > "$work/out/geo/regions.json"
expect 2 "output" "$bin" map "${t51[@]}" "${rect[@]}" --output "$work/out/geo"
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output ""
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output "$work/out/file/sub"
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output "$work/out/.."
# Refused before the work, not after it: a control character, a name too long for the temporary
# directory beside it, a directory where nothing can be created (as root, permissions do not tell: /proc).
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output "$work/out/a
b"
expect 2 "output" "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output "$work/out/$(printf 'x%.0s' {1..250})"
if [ -d /proc/self ]; then
  expect 2 "output = '/proc/m' is invalid: valid range a directory that can be created" \
    "$bin" map "${t51[@]}" --second-from 0.4 --second-to 0.6 --output /proc/m
fi

finish
