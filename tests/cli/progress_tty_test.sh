#!/usr/bin/env bash
# The progress line: drawn on stderr when it is a terminal (a pseudo-terminal made by script(1)),
# with '\r' and erased at the end; absent when stderr is a file or a pipe. The output files are
# the same either way.
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v script > /dev/null || { echo "script(1) not found: skipped"; exit 0; }

# Long enough (2.5 s and more) to pass the line's half-second delay on an idle fast machine too.
# The sanitized build's program is 2 to 4 times slower (less since the root finder stopped
# allocating: a fifth of find's work took 0.43 s there), so half of the work lasts as long.
scale=1
[ "${STICKSLIP_SANITIZED:-0}" = 1 ] && scale=2
sweep="sweep --preset paper-6 --from 0.55 --to 0.57 --steps 30 --transients $((1500 / scale)) --periods 5 --chains 2 --threads 1"
script -qec "'$bin' $sweep --output '$work/tty.csv' > '$work/tty.out'" /dev/null > "$work/terminal"
grep -q $'\rsweep: [0-9]*/124 points (' "$work/terminal" || { od -c "$work/terminal" | head; exit 1; }
# Erased at the end: the last thing on the terminal is a blanked line.
tail -c 2 "$work/terminal" | od -c | grep -q '\\r'

"$bin" $sweep --output "$work/piped.csv" > "$work/piped.out" 2> "$work/stderr"
[ ! -s "$work/stderr" ] || { echo "progress in a file:"; od -c "$work/stderr" | head; exit 1; }
"$bin" $sweep --output "$work/pipe.csv" 2>&1 > /dev/null | cat > "$work/pipe"
[ ! -s "$work/pipe" ]
cmp "$work/tty.csv" "$work/piped.csv"
sed "s|$work/tty.csv|X|" "$work/tty.out" | cmp - <(sed "s|$work/piped.csv|X|" "$work/piped.out")

# simulate and find draw theirs too.
script -qec "'$bin' simulate --preset paper-5.1 --transients $((500000 / scale)) --periods 1 > /dev/null" /dev/null > "$work/sim"
grep -q $'\rsimulate: [0-9.e+]*/'$((500000 / scale + 1))' periods' "$work/sim" || { od -c "$work/sim" | head; exit 1; }
"$bin" simulate --preset paper-5.1 --transients $((500000 / scale)) --periods 1 2> "$work/sim-stderr" > /dev/null
[ ! -s "$work/sim-stderr" ]
script -qec "'$bin' find --preset paper-4.1 --transients $((500000 / scale)) > /dev/null" /dev/null > "$work/find"
grep -q $'\rfind: transient: [0-9.e+]*/'$((500000 / scale))' periods' "$work/find" || { od -c "$work/find" | head; exit 1; }
# map-sweep: cells done. 4 x 3 cells, 3 runs each of 8000 (/ scale) + 4 periods, on one thread (2 s and more).
map="map-sweep --preset paper-6 --first omega --first-from 0.55 --first-to 0.57 --first-steps 3 --second u_r"
map+=" --second-from 1.3 --second-to 1.4 --second-steps 2 --transients $((8000 / scale)) --periods 4 --starts 1 --threads 1"
script -qec "'$bin' $map --output '$work/map.csv' > /dev/null" /dev/null > "$work/map"
grep -q $'\rmap-sweep: [0-9]*/12 cells (' "$work/map" || { od -c "$work/map" | head; exit 1; }
"$bin" $map --output "$work/map-piped.csv" 2> "$work/map-stderr" > /dev/null
[ ! -s "$work/map-stderr" ]
cmp "$work/map.csv" "$work/map-piped.csv"
echo "progress line ok"
