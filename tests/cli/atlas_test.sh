#!/usr/bin/env bash
# stickslip atlas: every periodic motion over a range in one command. The files are written and
# consistent (every solved attractor on a branch whose directory holds that point; every interval on
# a written branch), the same bytes for 1 and 2 threads, the user's files in an atlas kept at any
# depth on a re-run, its figure drawn; bad input refused with exit 2 and nothing written.
source "$(dirname "$0")/expect.sh"
r="$work/out"
data=(--preset paper-4.1 --range 0.58,0.62 --steps 2 --starts 2 --transients 300)
small=("${data[@]}" --results "$r")

"$bin" atlas "${small[@]}" --output a --threads 2 > "$work/a.txt" 2> "$work/a.err"
code=$?
[ "$code" -eq 0 ] && pass || fail "atlas exit $code, want 0: $(cat "$work/a.err")"
grep -q "^a: .* attractor(s) at 3 value(s) of omega: " "$work/a.txt" && pass || fail "no summary: $(cat "$work/a.txt")"
for f in atlas.json atlas-intervals.csv brute-force.csv trace-1/trace.json trace-1/branch-1/branch.csv; do
  [ -s "$r/a/$f" ] && pass || fail "a/$f missing"
done
/usr/bin/python3 - "$r/a" <<'PY' && pass || fail "atlas.json / atlas-intervals.csv of a"
import csv, json, os, sys
d = sys.argv[1]
a = json.load(open(d + "/atlas.json"))
assert a["parameter"] == "omega" and a["range"] == [0.58, 0.62] and a["grid_points"] == 3, a
assert [round(g["value"], 12) for g in a["grid"]] == [0.58, 0.6, 0.62]
placed = 0
for g in a["grid"]:
    for x in g["attractors"]:
        # Every exact orbit lies on a branch, named with a point of that branch's file.
        if x["find"] == "found":
            assert x["fate"] == "on-branch", x
        if x["fate"] == "on-branch":
            placed += 1
            rows = list(csv.DictReader(open(os.path.join(d, x["branch"], "branch.csv"))))
            assert 1 <= x["point"] <= len(rows), x
            assert x["branch"] in g["stable_on"], g
        else:
            assert x["reason"], x
assert placed == a["counts"]["on_branches"] > 0, a["counts"]
assert a["counts"]["traces"] == len(a["traces"]) == len([n for n in os.listdir(d) if n.startswith("trace-")])
for t in a["traces"]:
    json.load(open(os.path.join(d, t["name"], "trace.json")))
rows = list(csv.DictReader(open(d + "/atlas-intervals.csv")))
assert rows and all(os.path.isdir(os.path.join(d, r["trace"], r["branch"])) for r in rows)
PY

# The same bytes with one thread.
"$bin" atlas "${data[@]}" --results "$work/one" --output a --threads 1 > /dev/null 2>&1
diff -r "$r/a" "$work/one/a" > "$work/diff.txt" && pass || fail "1 and 2 threads differ: $(head -5 "$work/diff.txt")"

# A re-run keeps the user's files at any depth, and lists them.
echo mine > "$r/a/NOTES.md"
echo mine > "$r/a/trace-1/branch-1/NOTES.md"
mkdir -p "$r/a/trace-9" && echo mine > "$r/a/trace-9/kept.txt"
"$bin" atlas "${small[@]}" --output a --threads 2 > "$work/again.txt" 2>&1
for f in NOTES.md trace-1/branch-1/NOTES.md trace-9/kept.txt; do
  [ "$(cat "$r/a/$f" 2>/dev/null)" = mine ] && pass || fail "the re-run lost a/$f"
done
grep -q "kept 3 other file(s)" "$work/again.txt" && pass || fail "the kept files are not listed: $(cat "$work/again.txt")"

# A run file's names directly in a trace-<t>/ are the user's there (an atlas's trace never replaced a
# run), and a re-run after a re-run keeps everything (trace-9/ now the atlas's, holding the user's).
echo mine > "$r/a/trace-1/summary.json"
"$bin" atlas "${small[@]}" --output a --threads 2 > /dev/null 2>&1 && pass || fail "the second re-run failed"
for f in NOTES.md trace-1/branch-1/NOTES.md trace-9/kept.txt trace-1/summary.json; do
  [ "$(cat "$r/a/$f" 2>/dev/null)" = mine ] && pass || fail "the second re-run lost a/$f"
done

# A brute-force state find does not take as a start (|x| > 1e6, from scattered starts of the
# documented largest spread) is that attractor's reason, not bad input.
"$bin" atlas --preset paper-4.1 --range 0.55,0.65 --steps 1 --starts 2 --scatter 1e6 --transients 50 \
  --results "$work/scatter" --output s > "$work/scatter.txt" 2>&1 && pass || fail "a scattered atlas: $(cat "$work/scatter.txt")"
grep -q "not-solved: find cannot start from its state" "$work/scatter.txt" && pass ||
  fail "the attractor out of find's range is not listed: $(cat "$work/scatter.txt")"

# Its figure.
"$bin" plot "$r/a" --output "$work/a.svg" > /dev/null 2> "$work/plot.err" && [ -s "$work/a.svg" ] && pass ||
  fail "plot of an atlas: $(cat "$work/plot.err")"

# Bad input: one line, exit 2, nothing written.
expect 2 "range" "$bin" atlas --preset paper-4.1 --results "$r" --output b
expect 2 "range = '0.62,0.58'" "$bin" atlas --preset paper-4.1 --range 0.62,0.58 --results "$r" --output b
expect 2 "max-multiple" "$bin" atlas "${small[@]}" --output b --max-multiple 0
expect 2 "max-multiple" "$bin" atlas "${small[@]}" --output b --max-multiple 1000000
expect 2 "steps" "$bin" atlas "${small[@]}" --output b --steps 100000000
expect 2 "output" "$bin" atlas --preset paper-4.1 --range 0.58,0.62 --results "$r"
# omega1 = 0.70121... of the section 4.1 data (eq. 56) as a grid value.
omega1=$(/usr/bin/python3 -c "import math; c, e = 0.3, 4.0; b = 1 + c * e; print(repr(math.sqrt((b - math.sqrt(b * b - 4 * c * e * (1 - c))) / 2)))")
expect 2 "away from the natural frequencies" "$bin" atlas --preset paper-4.1 --range "0.6,$omega1" --steps 1 --results "$r" --output b
expect 2 "resonance-approach = 1 is invalid" "$bin" atlas "${small[@]}" --output b --resonance-approach 1
# The traces' branches that never stick end where they approach omega1 to within --resonance-approach
# (default 1 %), below it; with 0, never so.
near=(--preset paper-4.1 --range 0.66,0.7 --steps 1 --starts 1 --transients 300 --results "$r")
"$bin" atlas "${near[@]}" --output near > /dev/null && "$bin" atlas "${near[@]}" --output never --resonance-approach 0 > /dev/null &&
/usr/bin/python3 - "$r" "$omega1" <<'PY' && pass || fail "atlas --resonance-approach"
import glob, re, sys
r, omega1 = sys.argv[1], float(sys.argv[2])
def ends(name):
    text = "".join(open(f).read() for f in glob.glob(f"{r}/{name}/trace-*/trace.json"))
    return [(float(a), float(b)) for a, b in re.findall(r"resonance: at omega_1 = ([0-9.]+)[^\"]*at omega = ([0-9.]+)", text)]
near = ends("near")
assert near, "no branch ended at the resonance"
for at, omega in near:
    assert abs(at - omega1) < 1e-9 and 0.99 * omega1 <= omega < omega1, (at, omega)
assert not ends("never"), ends("never")
PY
# An existing directory that is not an atlas is the user's, a run's included; a link to an atlas is
# refused (its target's entries would move); the output is one name.
mkdir -p "$r/mine" && echo data > "$r/mine/data.txt"
expect 2 "output = 'mine'" "$bin" atlas "${small[@]}" --output mine
"$bin" continue --preset paper-4.1 --parameter omega --range 0.59,0.61 --results "$r" --output run1 > /dev/null 2>&1
expect 2 "output = 'run1'" "$bin" atlas "${small[@]}" --output run1
ln -s a "$r/link"
expect 2 "is a symbolic link" "$bin" atlas "${small[@]}" --output link
for name in ../x . a/b; do expect 2 "output = '$name'" "$bin" atlas "${small[@]}" --output "$name"; done
# Both ends of the range are values of the parameter, whatever the steps.
expect 2 "range = '-1,0.65'" "$bin" atlas --preset paper-4.1 --range -1,0.65 --steps 0 --results "$r" --output b
# A link the user put at a name the atlas writes is refused before any work; it and its target stay.
mkdir -p "$work/elsewhere" && echo mine > "$work/elsewhere/data.txt"
mv "$r/a/trace-1" "$work/trace-1-moved" && ln -s "$work/elsewhere" "$r/a/trace-1"
expect 2 "'trace-1', a symbolic link at a name the atlas writes" "$bin" atlas "${small[@]}" --output a
[ -L "$r/a/trace-1" ] && [ "$(cat "$work/elsewhere/data.txt")" = mine ] && pass || fail "the link or its target was touched"
finish
