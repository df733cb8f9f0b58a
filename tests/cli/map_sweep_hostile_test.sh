#!/usr/bin/env bash
# stickslip map-sweep against hostile files and names: a shard that is a device (read without end),
# a pipe (would block), a directory; --merge OUT that is one of its shards (directly or through a
# link: the merge would replace it); an output name that its directory takes but whose temporary
# name beside it is too long (refused before the work, not after it); shards of other runs; grids over
# the bound on the runs, ranges of 1e300, shards 0/0 and k > N, merges of overlapping or missing
# shards, outputs in a missing directory or over a directory (each one line, exit 2, nothing
# written, within a timeout); with the MPI front end (STICKSLIP_MPI), the same refusals from
# stickslip-mpi, a help that offers no --shard or --merge (which it has not), and a grid too large
# for one computation that two ranks split is not refused.
source "$(dirname "$0")/expect.sh"
source "$(dirname "$0")/map_sweep_common.sh"
map=(map-sweep --preset paper-6 --first omega --first-from 0.55 --first-to 0.6 --first-steps 3 --second u_r
     --second-from 1.2 --second-to 1.5 --second-steps 2 --transients 30 --periods 6 --starts 2)
for k in 1 2; do "$bin" "${map[@]}" --shard $k/2 --output "$work/s$k.csv" > /dev/null || fail "shard $k"; done
m="$work/out/m.csv"

expect 2 "shards = '/dev/zero' is invalid" timeout 20 "$bin" map-sweep --merge "$m" /dev/zero
mkfifo "$work/fifo"
expect 2 "shards = '$work/fifo' is invalid" timeout 20 "$bin" map-sweep --merge "$m" "$work/fifo"
expect 2 "shards = '$work' is invalid" "$bin" map-sweep --merge "$m" "$work"

# The output is one of the shards: refused, the shard kept.
cp "$work/s1.csv" "$work/out/s1.csv"
ln -s "$work/out/s1.csv" "$work/out/link.csv"
expect 2 "merge = '$work/out/s1.csv' is invalid: it is the shard '$work/out/s1.csv'" \
  "$bin" map-sweep --merge "$work/out/s1.csv" "$work/out/s1.csv" "$work/s2.csv"
expect 2 "merge = '$work/out/link.csv' is invalid: it is the shard '$work/out/s1.csv'" \
  "$bin" map-sweep --merge "$work/out/link.csv" "$work/out/s1.csv" "$work/s2.csv"
"$bin" map-sweep --merge "$work/merged.csv" "$work/s1.csv" "$work/s2.csv" > /dev/null && pass || fail "the merge"

# Shards of the same grid from other runs (other data, another seed of the scattered starts): refused,
# where they merged into a map of mixed runs.
for other in "--set chi=0.69" "--seed 2"; do
  "$bin" "${map[@]}" $other --shard 2/2 --output "$work/foreign.csv" > /dev/null || fail "foreign shard $other"
  expect 2 "merge: '$work/foreign.csv' is of run" "$bin" map-sweep --merge "$m" "$work/s1.csv" "$work/foreign.csv"
done

# A run fingerprint edited in one row.
awk -F, -v OFS=, 'NR == 3 { $8 = "00000000000000zz" } { print }' "$work/s1.csv" > "$work/edited.csv"
expect 2 "$work/edited.csv:3: column 'run' = '00000000000000zz' is invalid" "$bin" map-sweep --merge "$m" "$work/edited.csv"
awk -F, -v OFS=, 'NR == 3 { $8 = "0000000000000000" } { print }' "$work/s1.csv" > "$work/edited.csv"
expect 2 "$work/edited.csv:3: column 'run' = '0000000000000000' differs from the first row's" "$bin" map-sweep --merge "$m" "$work/edited.csv"

# A name of 250 bytes (a file may have 255): its temporary name is longer.
long="$work/out/$(printf 'a%.0s' $(seq 246)).csv"
expect 2 "output = '$long' is invalid: its name is too long" "$bin" "${map[@]}" --output "$long"

# Bad input given to a map computation (map_args' options replaced), here and across MPI ranks below.
refusals() {
  # The bound on the runs is one computation's (a shard's, an MPI rank's: 10001 or 5001 rows).
  expect_map 2 "rows of 10001 cells, 1002 runs a cell) is invalid: valid range at most 10000000 runs in one shard" \
    --first-steps 10000 --second-steps 10000 --starts 1000 --output "$m"
  expect_map 2 "grid cell (i, j) = (0, 0) at omega = -1e+300, u_r = 1.2 is invalid" \
    --first-from -1e300 --first-to 1e300 --output "$m"
  expect_map 2 "grid cell (i, j) = (1, 0) at omega = 3.3333333333333335e+299, u_r = 1.2 is invalid" \
    --first-from 0.55 --first-to 1e300 --output "$m"
  expect_map 2 "grid cell (i, j) = (0, 0) at omega = 0.55, u_r = 1e+300 is invalid" \
    --second-from 1e300 --second-to 1e300 --output "$m"
  expect_map 2 "first-from = '1e999' is not a finite number" --first-from 1e999 --output "$m"
  expect_map 2 "scatter = 1e+300 is invalid" --scatter 1e300 --output "$m"
  # stickslip's --shard (stickslip-mpi has none: below).
  if [ ${#map_runner[@]} -eq 0 ]; then
    for shard in 0/0 3/2 1/0 -1/2 1/2/3 1/100001 /; do
      expect_map 2 "shard = '$shard' is invalid: valid range k/N with whole numbers 1 <= k <= N <= 100000" \
        --shard "$shard" --output "$m"
    done
  fi
  expect_map 2 "output = '$work/out/missing/m.csv' is invalid: directory '$work/out/missing' does not exist" \
    --output "$work/out/missing/m.csv"
  expect_map 2 "output = '$work/out' is invalid: it is a directory" --output "$work/out"
  expect_map 2 "output = '$work/out/' is invalid: it is a directory" --output "$work/out/"
  expect_map 2 "output = '' is invalid: it is empty" --output ""
}
m="$work/out/m.csv"
refusals
# The bound is one computation's: 10001 rows of 1 cell with 1002 runs a cell (MPI ranks split it).
expect_map 2 "grid = 10021002 runs (10001 rows of 1 cells, 1002 runs a cell) is invalid" \
  --first-steps 0 --second-steps 10000 --starts 1000 --output "$m"

# Merges: shards that overlap (1/2 and 1/3 both hold row 0), shards that miss a row (1/3 and 2/3),
# an output over a directory or in a missing one.
for k in 1 2 3; do "$bin" "${map[@]}" --shard $k/3 --output "$work/t$k.csv" > /dev/null || fail "shard $k/3"; done
expect 2 "merge: cell (i, j) = (0, 0) is in '$work/s1.csv' and in '$work/t1.csv'" \
  timeout 20 "$bin" map-sweep --merge "$m" "$work/s1.csv" "$work/s2.csv" "$work/t1.csv"
expect 2 "merge: cell (i, j) = (0, 2) is in no shard" timeout 20 "$bin" map-sweep --merge "$m" "$work/t1.csv" "$work/t2.csv"
expect 2 "merge = '$work/out' is invalid: it is a directory" "$bin" map-sweep --merge "$work/out" "$work/s1.csv" "$work/s2.csv"
expect 2 "merge = '$work/out/missing/m.csv' is invalid: directory '$work/out/missing' does not exist" \
  "$bin" map-sweep --merge "$work/out/missing/m.csv" "$work/s1.csv" "$work/s2.csv"
expect 2 "merge = '$m' is invalid: valid range --merge OUT SHARD.csv... with at least one shard file" "$bin" map-sweep --merge "$m"
"$bin" map-sweep --merge "$work/merged3.csv" "$work/t2.csv" "$work/t3.csv" "$work/t1.csv" > /dev/null && cmp -s "$work/merged.csv" "$work/merged3.csv" \
  && pass || fail "3 shards merged differ from 2"

if mpi_ready; then
  # The same refusals from stickslip-mpi on 2 ranks (rank 0 prints the one line, every rank exits 2).
  map_runner=("${mpi[@]}" -np 2 "$STICKSLIP_MPI")
  refusals
  # Its help offers neither --shard nor --merge, which it would refuse (both were offered before).
  "${mpi[@]}" -np 1 "$STICKSLIP_MPI" map-sweep --help > "$work/mpi-help.txt" 2>&1 && grep -q -- "--output" "$work/mpi-help.txt" &&
    pass || fail "stickslip-mpi map-sweep --help: $(cat "$work/mpi-help.txt")"
  ! grep -E -- "--shard|--merge" "$work/mpi-help.txt" && pass || fail "stickslip-mpi map-sweep --help offers --shard or --merge"
  expect_map 2 "The following arguments were not expected: 1/2 --shard" --shard 1/2 --output "$m"
  map_args --output "$m"
  expect 2 "The following arguments were not expected" "${map_runner[@]}" "${args[@]}" --merge "$m" "$work/s1.csv"
  map_runner=()
  # 2 rows of 5001 cells and 1002 runs a cell: 10022 thousand runs, over the bound of one computation
  # (1e7), 5011 thousand a rank. One rank refuses it; two start computing (stopped after 10 s).
  big=(map-sweep --preset paper-6 --first omega --first-from 0.55 --first-to 0.6 --first-steps 5000 --second u_r
       --second-from 1.2 --second-to 1.5 --second-steps 1 --transients 0 --periods 2 --starts 1000 --output "$work/big.csv")
  "${mpi[@]}" -np 1 "$STICKSLIP_MPI" "${big[@]}" > "$work/stdout" 2> "$work/stderr"
  code=$?
  [ "$code" -eq 2 ] && [ "$(grep -c 'grid = 10022004 runs' "$work/stderr")" -eq 1 ] && pass ||
    fail "1 rank: exit $code, $(cat "$work/stderr")"
  timeout 10 "${mpi[@]}" -np 2 "$STICKSLIP_MPI" "${big[@]}" > "$work/stdout" 2> "$work/stderr"
  code=$?
  [ "$code" -ne 2 ] && ! grep -q "grid = " "$work/stderr" && pass || fail "2 ranks refused the grid: exit $code, $(cat "$work/stderr")"
fi
finish
