#!/usr/bin/env bash
# File outputs replace only a file their command wrote, known by the marker its format already has
# on line 1 (the CSV's exact header, the run file's first comment), or one named with --force; any
# other existing file (a committed run file, the user's data, an empty file) is refused before the
# work: exit 2, one line naming the option and the path, nothing written (issue 22: find
# --write-run destroyed continuation-scripts/paper-5.1-omega-up.toml).
source "$(dirname "$0")/expect.sh"
o="$work/out"
printf 'my data\n' > "$o/mine.csv"
: > "$o/empty.csv"
cp "$root/continuation-scripts/paper-5.1-omega-up.toml" "$o/committed.toml"
why="it exists and was not written by"

# simulate --csv
sim=(simulate --preset paper-4.1 --periods 1 --samples-per-period 20)
for f in mine.csv empty.csv committed.toml; do
  expect 2 "csv = '$o/$f' is invalid: $why stickslip simulate" "$bin" "${sim[@]}" --csv "$o/$f"
done
"$bin" "${sim[@]}" --csv "$work/sim.csv" > /dev/null && "$bin" "${sim[@]}" --csv "$work/sim.csv" > /dev/null && pass ||
  fail "simulate over its own CSV"
# sweep --output (a CSV of another command is not its own)
sweep=(sweep --preset paper-4.1 --from 0.55 --to 0.56 --steps 1 --transients 5 --periods 2)
expect 2 "output = '$o/mine.csv' is invalid: $why stickslip sweep" "$bin" "${sweep[@]}" --output "$o/mine.csv"
cp "$work/sim.csv" "$o/sim.csv"
expect 2 "output = '$o/sim.csv' is invalid: $why stickslip sweep" "$bin" "${sweep[@]}" --output "$o/sim.csv"
"$bin" "${sweep[@]}" --output "$work/sweep.csv" > /dev/null && "$bin" "${sweep[@]}" --parameter omega --output "$work/sweep.csv" \
  > /dev/null && pass || fail "sweep over its own CSV"
# map-sweep --output and --merge OUT
source "$(dirname "$0")/map_sweep_common.sh"
map_args --first-steps 1 --second-steps 1 --transients 5 --periods 2 --starts 1
expect 2 "output = '$o/mine.csv' is invalid: $why stickslip map-sweep" "$bin" "${args[@]}" --output "$o/mine.csv"
expect 2 "output = '$o/sim.csv' is invalid: $why stickslip map-sweep" "$bin" "${args[@]}" --output "$o/sim.csv"
"$bin" "${args[@]}" --output "$work/map.csv" > /dev/null && "$bin" "${args[@]}" --output "$work/map.csv" > /dev/null && pass ||
  fail "map-sweep over its own map"
cp "$work/map.csv" "$o/shard.csv"
expect 2 "merge = '$o/mine.csv' is invalid: $why stickslip map-sweep" "$bin" map-sweep --merge "$o/mine.csv" "$o/shard.csv"
"$bin" map-sweep --merge "$work/map.csv" "$o/shard.csv" > /dev/null && cmp -s "$work/map.csv" "$o/shard.csv" && pass ||
  fail "merge over a map file"
# find --write-run: the committed run file is refused; a run file find wrote is replaced.
data=(--set chi=0.5 --set eta=2 --set u_s=0.1 --set u_r=0.3 --set omega=0.27 --set x10=1)
expect 2 "write-run = '$o/committed.toml' is invalid: $why stickslip find" "$bin" find "${data[@]}" --write-run "$o/committed.toml"
cmp -s "$o/committed.toml" "$root/continuation-scripts/paper-5.1-omega-up.toml" && pass || fail "the run file changed"
"$bin" find "${data[@]}" --write-run "$work/p4.toml" > /dev/null && cp "$work/p4.toml" "$work/p4-first.toml" &&
  "$bin" find "${data[@]}" --write-run "$work/p4.toml" > /dev/null && cmp -s "$work/p4.toml" "$work/p4-first.toml" && pass ||
  fail "find over its own run file"
# --force replaces any file.
cp "$o/mine.csv" "$work/forced.csv"
"$bin" "${sim[@]}" --csv "$work/forced.csv" --force > /dev/null && cmp -s "$work/forced.csv" "$work/sim.csv" && pass ||
  fail "simulate --force"
cp "$o/mine.csv" "$work/forced.csv"
"$bin" "${sweep[@]}" --output "$work/forced.csv" --force > /dev/null && cmp -s "$work/forced.csv" "$work/sweep.csv" && pass ||
  fail "sweep --force"
cp "$o/mine.csv" "$work/forced.csv"
"$bin" map-sweep --merge "$work/forced.csv" "$o/shard.csv" --force > /dev/null && cmp -s "$work/forced.csv" "$o/shard.csv" &&
  pass || fail "map-sweep --merge --force"
mkdir "$work/f" && cp "$o/committed.toml" "$work/f/p4.toml"  # the same name: the run file names its output after it
"$bin" find "${data[@]}" --write-run "$work/f/p4.toml" --force > /dev/null && cmp -s "$work/f/p4.toml" "$work/p4.toml" &&
  pass || fail "find --force"
finish
