#!/usr/bin/env bash
# stickslip plot RUN: writes a valid PNG (PNG signature, 800 x 600) for a stored run, and the
# frequency response (1150 x 600, default name <trace>-frequency-response.png) for a stored trace; refuses a
# missing or ill-named run and every bad --output with exit 2 and nothing written; a missing
# python3 or matplotlib is exit 1 with a message saying what to install, and nothing written.
source "$(dirname "$0")/expect.sh"

mkdir -p "$work/out/a-directory"
echo keep > "$work/out/a-directory/file"

# A diagram of a stored run: PNG signature, 800 x 600, and nothing else written.
if "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/diagram.png" > "$work/stdout"; then
  if [ "$(head -c 8 "$work/out/diagram.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] &&
     [ "$(stat -c %s "$work/out/diagram.png")" -gt 10000 ]; then pass; else fail "plot wrote no PNG"; fi
  size=$(/usr/bin/python3 -c "import matplotlib.image as i, sys; h, w = i.imread(sys.argv[1]).shape[:2]; print(w, h)" "$work/out/diagram.png")
  [ "$size" = "800 600" ] && pass || fail "plot's PNG is $size, expected 800 600"
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
  [ "$size" = "1150 600" ] && pass || fail "plot of a trace: $size, expected 1150 600"
else
  fail "plot of a stored trace failed"
fi
# A damaged trace (a branch's directory missing) is refused before any drawing.
cp -r "$root/results/paper-4.1-omega-trace" "$work/out/paper-4.1-omega-trace"
rm -r "$work/out/paper-4.1-omega-trace/branch-2"
expect 2 "branch-2" "$bin" plot paper-4.1-omega-trace --results "$work/out" --output "$work/out/trace.png"
[ ! -e "$work/out/trace.png" ] && pass || fail "plot of a damaged trace wrote a file"
rm -r "$work/out/paper-4.1-omega-trace"

png="$work/out/new.png"
expect 2 "paper-9-omega-up" "$bin" plot paper-9-omega-up --results "$root/results" --output "$png"
expect 2 "run = '" "$bin" plot $'paper-5.1\nomega-up' --results "$root/results" --output "$png"
expect 2 "run = '../results/paper-5.1-omega-up'" "$bin" plot ../results/paper-5.1-omega-up --results "$root/results" --output "$png"
expect 2 "it is a directory" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/a-directory"
expect 2 "ending in .png" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/diagram.txt"
expect 2 "it is empty" "$bin" plot paper-5.1-omega-up --results "$root/results" --output ""
expect 2 "does not exist" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$work/out/missing/x.png"
expect 2 "cannot read" "$bin" plot paper-5.1-omega-up --results "$work/out" --output "$png"
# No interpreter, and an interpreter without matplotlib (a module of that name that fails to import).
expect 1 "apt-get install" env STICKSLIP_PYTHON=/nonexistent/python3 "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png"
mkdir -p "$work/fake/matplotlib"
echo 'raise ImportError("No module named matplotlib (test)")' > "$work/fake/matplotlib/__init__.py"
printf '#!/bin/sh\nPYTHONPATH=%s exec /usr/bin/python3 "$@"\n' "$work/fake" > "$work/python-without-matplotlib"
chmod +x "$work/python-without-matplotlib"
expect 1 "python3-matplotlib" env STICKSLIP_PYTHON="$work/python-without-matplotlib" "$bin" plot paper-5.1-omega-up --results "$root/results" --output "$png"

finish
