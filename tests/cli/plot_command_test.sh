#!/usr/bin/env bash
# stickslip plot: writes a valid PNG (PNG signature, 9 x 5 inches at 150 dpi: 1350 x 750) for a
# stored run and for a stored trace (default name <run>-bifurcation.png, <trace>-frequency-response.png),
# PDF and SVG by the extension, at --size and --dpi; draws a sweep's and a brute-force map's CSV
# given by its path (stickslip plot mapA.csv) and overlays several inputs; refuses a missing or
# ill-named run, every bad --output and every bad drawing option with exit 2, one line and nothing
# written; keeps a file of the user's as --output (exit 2) unless --force, which replaces it; a
# missing python3 or matplotlib is exit 1 with a message saying what to install, and nothing written.
source "$(dirname "$0")/expect.sh"

mkdir -p "$work/out/a-directory"
echo keep > "$work/out/a-directory/file"

# A diagram of a stored run: PNG signature, 800 x 600, and nothing else written.
if "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/diagram.png" > "$work/stdout"; then
  if [ "$(head -c 8 "$work/out/diagram.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] &&
     [ "$(stat -c %s "$work/out/diagram.png")" -gt 10000 ]; then pass; else fail "plot wrote no PNG"; fi
  size=$(/usr/bin/python3 -c "import matplotlib.image as i, sys; h, w = i.imread(sys.argv[1]).shape[:2]; print(w, h)" "$work/out/diagram.png")
  [ "$size" = "1350 750" ] && pass || fail "plot's PNG is $size, expected 1350 750"
  [ "$(ls -A "$work/out" | sort | tr '\n' ' ')" = "a-directory diagram.png " ] && pass || fail "plot left other files: $(ls -A "$work/out")"
else
  fail "plot of a stored run failed"
fi
# The default output name, in the current directory.
(cd "$work" && "$bin" plot paper-6-u_r-up --results "$root/results" > /dev/null) && [ -s "$work/paper-6-u_r-up-bifurcation.png" ] &&
  pass || fail "plot without --output wrote no <run>-bifurcation.png"

# A trace: its frequency response, under its default name in the current directory.
if (cd "$work" && "$bin" plot paper-4.1-omega-trace --results "$root/results" > /dev/null); then
  size=$(/usr/bin/python3 -c "import matplotlib.image as i, sys; h, w = i.imread(sys.argv[1]).shape[:2]; print(w, h)" "$work/paper-4.1-omega-trace-frequency-response.png")
  [ "$size" = "1350 750" ] && pass || fail "plot of a trace: $size, expected 1350 750"
else
  fail "plot of a stored trace failed"
fi
# A damaged trace (a branch's directory missing) is refused before any drawing.
cp -r "$root/results/paper-4.1-omega-trace" "$work/out/paper-4.1-omega-trace"
rm -r "$work/out/paper-4.1-omega-trace/branch-2"
expect 2 "branch-2" "$bin" plot paper-4.1-omega-trace --results "$work/out" --output "$work/out/trace.png"
[ ! -e "$work/out/trace.png" ] && pass || fail "plot of a damaged trace wrote a file"
rm -r "$work/out/paper-4.1-omega-trace"

# PDF and SVG by the extension; --size and --dpi.
"$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/diagram.pdf" > /dev/null &&
  [ "$(head -c 4 "$work/out/diagram.pdf")" = "%PDF" ] && pass || fail "plot wrote no PDF"
"$bin" plot paper-4.1-omega-trace --results "$root/results" --output "$work/out/trace.svg" > /dev/null &&
  grep -q "<svg" "$work/out/trace.svg" && pass || fail "plot wrote no SVG"
"$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/small.png" --size 3.5,2.5 --dpi 300 \
  --yscale log --xlim 0.57,0.59 --y peak-to-peak:x2 --title "" --legend inside > /dev/null &&
  size=$(/usr/bin/python3 -c "import matplotlib.image as i, sys; h, w = i.imread(sys.argv[1]).shape[:2]; print(w, h)" "$work/out/small.png") &&
  [ "$size" = "1050 750" ] && pass || fail "plot --size 3.5,2.5 --dpi 300: ${size:-failed}, expected 1050 750"
rm -f "$work/out/diagram.pdf" "$work/out/trace.svg" "$work/out/small.png"
# A sweep's and a brute-force map's CSV by path, in the current directory (stickslip plot mapA.csv:
# <csv name>.png); an orbit-type map's directory; several inputs overlaid.
cp "$root/results/maps/paper-6-omega-u_r-brute-force.csv" "$work/mapA.csv"
(cd "$work" && "$bin" plot mapA.csv > /dev/null) && [ "$(head -c 4 "$work/mapA.png" | tail -c 3)" = "PNG" ] &&
  pass || fail "plot mapA.csv wrote no mapA.png"
"$bin" plot "$root/results/maps/paper-5.1-omega-u_r" paper-5.1-fold-curve --results "$root/results" \
  --output "$work/map.svg" > /dev/null && grep -q "<svg" "$work/map.svg" && pass || fail "plot of an orbit-type map and a curve"
"$bin" plot paper-5.1-omega-up paper-5.1-omega-down "$root/results/sweeps/paper-5.1-omega.csv" --results "$root/results" \
  --output "$work/overlay.png" > /dev/null && [ -s "$work/overlay.png" ] && pass || fail "plot of two runs and a sweep"

png="$work/out/new.png"
# A file of the user's as --output: kept, exit 2, without --force; replaced by a figure with it.
printf 'my thesis\n' > "$work/out/thesis.pdf"
expect 2 "a new file or a figure stickslip plot wrote" "$bin" plot paper-5.1-omega-up --results "$root/results" \
  --output "$work/out/thesis.pdf"
[ "$(cat "$work/out/thesis.pdf")" = "my thesis" ] && pass || fail "plot without --force changed the user's file"
"$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/thesis.pdf" --force > /dev/null &&
  [ "$(head -c 4 "$work/out/thesis.pdf")" = "%PDF" ] && pass || fail "plot --force did not replace the user's file"
"$bin" plot --help | grep -q -- "--force.*replace --output even if stickslip plot did not write it" && pass ||
  fail "plot --help does not say what --force does"
rm "$work/out/thesis.pdf"
# Bad drawing options: the option, the value and the valid range on one line, exit 2, nothing written.
expect 2 "--dpi = '5' is invalid: valid 10 to 1200" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png" --dpi 5
expect 2 "--size = '0,3' is invalid: valid WIDTH,HEIGHT in inches, each 1 to 40" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png" --size 0,3
expect 2 "--yscale = 'logarithmic' is invalid: valid linear or log" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png" --yscale logarithmic
expect 2 "--xlim = '1,0' is invalid: valid LOW,HIGH" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png" --xlim 1,0
expect 2 "--y = 'nope' is invalid: valid a numeric column of every input" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png" --y nope
expect 2 "--legend = 'top' is invalid: valid right, inside or none" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png" --legend top
expect 2 "inputs = 'paper-5.1-omega-up' (branch) is invalid" "$bin" plot paper-5.1-omega-up "$root/results/maps/paper-6-omega-u_r" --results "$root/results" --output "$png"
expect 2 "input = '$root/results/runs.md' is invalid" "$bin" plot "$root/results/runs.md" --output "$png"
expect 2 "ending in .png, .pdf or .svg" "$bin" plot "$root/results/sweeps/paper-5.1-omega.csv" --output "$work/out/x.jpg"
expect 2 "paper-9-omega-up" "$bin" plot paper-9-omega-up --results "$root/results" --output "$png"
expect 2 "run = '" "$bin" plot $'paper-5.1\nomega-up' --results "$root/results" --output "$png"
expect 2 "run = '../results/paper-5.1-omega-up'" "$bin" plot ../results/paper-5.1-omega-up --results "$root/results" --output "$png"
expect 2 "it is a directory" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/a-directory"
expect 2 "ending in .png" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/diagram.txt"
expect 2 "it is empty" "$bin" plot paper-5.1-omega-up --results "$root/results" --output ""
expect 2 "does not exist" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/missing/x.png"
# A directory that holds no result: the message says what plot reads (before: "cannot read
# '<dir>/branch.csv'", not what a valid input is).
expect 2 "run = '$work/out/paper-5.1-omega-up' is invalid: it does not exist: valid a run or trace name under --results" \
  "$bin" plot paper-5.1-omega-up --results "$work/out" --output "$png"
mkdir "$work/not-a-run"
expect 2 "run = '$work/not-a-run' is invalid: it holds no branch.csv: valid a run or trace name under --results, or the path of a result: a run's directory (results/<run>/, holding branch.csv, special-points.csv and summary.json), a trace's (trace.json, branch-<k>/)" \
  "$bin" plot "$work/not-a-run" --output "$png"
# No interpreter, and an interpreter without matplotlib (a module of that name that fails to import).
expect 1 "apt-get install" env STICKSLIP_PYTHON=/nonexistent/python3 "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png"
mkdir -p "$work/fake/matplotlib"
echo 'raise ImportError("No module named matplotlib (test)")' > "$work/fake/matplotlib/__init__.py"
printf '#!/bin/sh\nPYTHONPATH=%s exec /usr/bin/python3 "$@"\n' "$work/fake" > "$work/python-without-matplotlib"
chmod +x "$work/python-without-matplotlib"
expect 1 "python3-matplotlib" env STICKSLIP_PYTHON="$work/python-without-matplotlib" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png"

# A run's own file given by its path (run/branch.csv) is checked as the run is, column by column:
# it went to the script unchecked, and a 1e309 was drawn without a word.
cp -r "$root/results/paper-5.1-omega-up" "$work/damaged"
/usr/bin/python3 - "$work/damaged/branch.csv" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
column = lines[0].split(",").index("amplitude:x2")
fields = lines[5].split(",")
fields[column] = "1e309"
lines[5] = ",".join(fields)
open(sys.argv[1], "w").write("\n".join(lines) + "\n")
PY
for file in branch.csv special-points.csv summary.json ""; do
  expect 2 "branch.csv:6: column 'amplitude:x2' = '1e309'" "$bin" plot "$work/damaged/$file" --output "$png"
done

# A brute-force map's CSV is read by map-sweep's reader, every column checked: the script alone drew
# a status 'weird', a run '' or a cell index past ni without a word.
map_csv="$root/results/maps/paper-6-omega-u_r-brute-force.csv"
for change in "status:weird" "run:" "i:99999" "signature:bogus"; do
  /usr/bin/python3 - "$map_csv" "$work/damaged-map.csv" "$change" <<'PY'
import sys
source, target, change = sys.argv[1:]
column, value = change.split(":", 1)
lines = open(source).read().splitlines()
fields = lines[3].split(",")
fields[lines[0].split(",").index(column)] = value
lines[3] = ",".join(fields)
open(target, "w").write("\n".join(lines) + "\n")
PY
  expect 2 "damaged-map.csv:4: column '${change%%:*}' = '${change#*:}'" "$bin" plot "$work/damaged-map.csv" --output "$png"
done

# The program copied away from its scripts (no stickslip_plot.py beside it nor in ../share/stickslip/):
# one line naming the script, exit 1 (python3's "can't open file" exited 2, as if the input were bad).
mkdir -p "$work/copy/bin"
cp "$bin" "$work/copy/bin/stickslip"
expect 1 "plot needs its drawing script stickslip_plot.py at '$work/copy/share/stickslip/stickslip_plot.py'" \
  "$work/copy/bin/stickslip" plot paper-5.1-omega-up --results "$root/results" --output "$png"
# A link to the program finds the scripts beside its target.
ln -s "$bin" "$work/copy/bin/linked"
"$work/copy/bin/linked" plot paper-5.1-omega-up --results "$root/results" --output "$work/linked.png" > /dev/null &&
  [ -s "$work/linked.png" ] && pass || fail "plot through a symbolic link to the program"

finish
