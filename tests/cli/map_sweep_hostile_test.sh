#!/usr/bin/env bash
# stickslip map-sweep against hostile files and names: a shard that is a device (read without end),
# a pipe (would block), a directory; --merge OUT that is one of its shards (directly or through a
# link: the merge would replace it); an output name that its directory takes but whose temporary
# name beside it is too long (refused before the work, not after it); shards of other runs; with the MPI front end
# (STICKSLIP_MPI), a grid too large for one computation that two ranks split is not refused.
source "$(dirname "$0")/expect.sh"
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

if [ -n "${STICKSLIP_MPI:-}" ]; then
  export OMPI_MCA_btl_vader_single_copy_mechanism=none
  mpi=("${MPIEXEC:-mpirun}" --allow-run-as-root --oversubscribe)
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
else
  echo "the MPI front end is not built: MPI checks skipped"
fi
finish
