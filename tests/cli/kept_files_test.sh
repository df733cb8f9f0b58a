#!/usr/bin/env bash
# A trace or a map written again keeps what it did not write, at every depth, and lists it: the
# AUTO export's b., s. and d. files inside a trace's branch-<k>/, the user's notes and directories there
# and inside a map's curve-<k>/, a branch-<k> or curve-<k> the trace's or map's index does not list
# (issue 22: they were deleted). And a run or a trace written into a
# trace's own entries (--output branch-2 with --results the trace) is refused: exit 2, one line,
# the trace untouched.
source "$(dirname "$0")/expect.sh"
r="$work/out"  # expect checks that a refused command leaves the trace in it as it was
p41=(--preset paper-4.1 --parameter omega --range 0.3,0.69 --ds 0.005 --ds-max 0.05)

"$bin" trace "${p41[@]}" --results "$r" --output tr > /dev/null 2>&1
[ -s "$r/tr/branch-2/summary.json" ] && pass || fail "the first trace wrote no branch-2"
cp -r "$r/tr" "$work/first"
"$bin" export --auto "$r/tr/branch-2" > /dev/null && pass || fail "export --auto branch-2"
echo n > "$r/tr/branch-1/NOTES.md"
mkdir -p "$r/tr/branch-1/plots" && echo p > "$r/tr/branch-1/plots/omega.txt"
cp -r "$r/tr" "$work/mine"
"$bin" trace "${p41[@]}" --results "$r" --output tr > "$work/again.txt" 2>&1
for f in branch-2/b.branch-2 branch-2/s.branch-2 branch-2/d.branch-2 branch-1/NOTES.md branch-1/plots/omega.txt; do
  cmp -s "$work/mine/$f" "$r/tr/$f" && pass || fail "the trace written again lost $f"
done
grep -qF "tr: kept 5 other file(s) of $r/tr: branch-1/NOTES.md, branch-1/plots, branch-2/b.branch-2, branch-2/d.branch-2, branch-2/s.branch-2" \
  "$work/again.txt" && pass || fail "kept files not listed: $(cat "$work/again.txt")"
rm -r "$r/tr/branch-2/b.branch-2" "$r/tr/branch-2/s.branch-2" "$r/tr/branch-2/d.branch-2" "$r/tr/branch-1/NOTES.md" "$r/tr/branch-1/plots"
diff -r "$work/first" "$r/tr" > /dev/null && pass || fail "the trace written again differs from the first"

# Entries named as the trace names its branches but that its trace.json does not list are the
# user's, at any depth: a directory branch-9/ (a run's three files and notes in it), a file branch-8,
# a branch-7/ inside branch-2/ (before: the top-level ones were deleted as the trace's own).
[ ! -e "$r/tr/branch-7" ] && [ ! -e "$r/tr/branch-8" ] && [ ! -e "$r/tr/branch-9" ] || fail "the trace has 7 branches or more"
mkdir "$r/tr/branch-9" "$r/tr/branch-2/branch-7"
cp "$r/tr/branch-1/"* "$r/tr/branch-9/" && echo n > "$r/tr/branch-9/NOTES.md"
echo n > "$r/tr/branch-8" && echo n > "$r/tr/branch-2/branch-7/NOTES.md"
cp -r "$r/tr" "$work/mine-branches"
"$bin" trace "${p41[@]}" --results "$r" --output tr > "$work/again.txt" 2>&1
diff -r "$work/mine-branches" "$r/tr" > /dev/null && pass || fail "the trace written again lost the user's branch-<k>: $(ls -R "$r/tr")"
grep -qF "tr: kept 3 other file(s) of $r/tr: branch-2/branch-7, branch-8, branch-9" "$work/again.txt" && pass ||
  fail "the user's branch-<k> not listed: $(cat "$work/again.txt")"
rm -r "$r/tr/branch-9" "$r/tr/branch-8" "$r/tr/branch-2/branch-7"

# Into the trace's own entries: refused before the work, the trace as it was.
restart=(--results "$r/tr" --point branch-2:EP1 --parameter omega --range 0.3,0.69 --ds 0.005 --ds-max 0.05)
expect 2 "output = 'branch-2' is invalid: '$r/tr/branch-2' is a part of the trace '$r/tr'" \
  "$bin" trace "${restart[@]}" --output branch-2
expect 2 "output = 'branch-1' is invalid" "$bin" continue "${restart[@]}" --max-points 5 --output branch-1
expect 2 "output = 'branch-9-EP1' is invalid" "$bin" continue "${restart[@]}" --max-points 5 --output branch-9-EP1
expect 2 "output = 'trace.csv' is invalid" "$bin" continue "${restart[@]}" --max-points 5 --output trace.csv
# A name the trace does not write is a run of the user's beside the branches.
"$bin" continue "${restart[@]}" --max-points 5 --output mine > /dev/null && [ -s "$r/tr/mine/summary.json" ] && pass ||
  fail "a restart into the trace under a name of its own"

# A map: the user's files inside curve-<k>/ are kept and listed too.
cd "$root" || exit 1  # the trace's run file is named relative to the source tree
map=(--trace results/paper-5.1-omega-trace --second u_r --second-from 0.4 --second-to 0.6 --first-from 0.53 --first-to 0.6
     --raster 64 --output "$work/m")
"$bin" map "${map[@]}" > /dev/null 2>&1 && pass || fail "map"
cp -r "$work/m" "$work/m-first"
echo n > "$work/m/curve-1/NOTES.md"
mkdir "$work/m/curve-1/mine" && echo p > "$work/m/curve-1/mine/a.txt"
"$bin" map "${map[@]}" > "$work/m.txt" 2>&1 && pass || fail "map again: $(cat "$work/m.txt")"
[ "$(cat "$work/m/curve-1/NOTES.md" "$work/m/curve-1/mine/a.txt" 2>&1)" = "$(printf 'n\np')" ] && pass ||
  fail "the map written again lost the user's files in curve-1: $(ls -R "$work/m/curve-1")"
grep -qF "kept 2 other file(s): curve-1/NOTES.md, curve-1/mine" "$work/m.txt" && pass || fail "not listed: $(cat "$work/m.txt")"
rm -r "$work/m/curve-1/NOTES.md" "$work/m/curve-1/mine"
diff -r "$work/m-first" "$work/m" > /dev/null && pass || fail "the map written again differs from the first"
# And a curve-<k> its regions.json does not list, a directory or a file, is the user's.
[ ! -e "$work/m/curve-98" ] && [ ! -e "$work/m/curve-99" ] || fail "the map has 98 curves or more"
mkdir "$work/m/curve-99" && cp "$work/m/curve-1/"* "$work/m/curve-99/" && echo n > "$work/m/curve-98"
cp -r "$work/m" "$work/m-mine"
"$bin" map "${map[@]}" > "$work/m.txt" 2>&1 && pass || fail "map again: $(cat "$work/m.txt")"
diff -r "$work/m-mine" "$work/m" > /dev/null && pass || fail "the map written again lost the user's curve-<k>: $(ls "$work/m")"
grep -qF "kept 2 other file(s): curve-98, curve-99" "$work/m.txt" && pass || fail "not listed: $(cat "$work/m.txt")"
# A link the user put at a name the trace writes is never removed (no writer makes links): the
# re-run fails, saying so, and the trace stays as it was with the link and its target.
mkdir -p "$work/elsewhere" && echo mine > "$work/elsewhere/data.txt"
mv "$r/tr/branch-1" "$work/branch-1-moved" && ln -s "$work/elsewhere" "$r/tr/branch-1"
"$bin" trace "${p41[@]}" --results "$r" --output tr > "$work/link.txt" 2>&1 && fail "a trace over a link succeeded" || pass
grep -qF "cannot keep" "$work/link.txt" && pass || fail "the failure does not say why: $(cat "$work/link.txt")"
[ -L "$r/tr/branch-1" ] && [ "$(cat "$work/elsewhere/data.txt")" = mine ] && pass || fail "the link or its target was touched"
finish
