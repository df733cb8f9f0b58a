#!/usr/bin/env bash
# stickslip map-sweep: bad input (one line naming the field, exit 2, nothing written); the file
# the same bytes for 1 and 2 threads; shards merged give the unsharded file; a merge of shards of
# different grids, with a cell twice or one missing, is refused; with the MPI front end
# (STICKSLIP_MPI), 1 and 2 ranks write the threaded run's bytes.
source "$(dirname "$0")/expect.sh"
map=(map-sweep --preset paper-6 --first omega --first-from 0.55 --first-to 0.6 --first-steps 3
     --second u_r --second-from 1.2 --second-to 1.5 --second-steps 2 --transients 30 --periods 6 --starts 2)

expect 2 "first-steps = '2.5' is invalid" "$bin" "${map[@]}" --first-steps 2.5 --output "$work/out/m.csv"
expect 2 "second = 'omega' is invalid" "$bin" "${map[@]}" --second omega --output "$work/out/m.csv"
expect 2 "first = 'mu' is invalid" "$bin" "${map[@]}" --first mu --output "$work/out/m.csv"
expect 2 "shard = '3/2' is invalid" "$bin" "${map[@]}" --shard 3/2 --output "$work/out/m.csv"
expect 2 "shard = '0/2' is invalid" "$bin" "${map[@]}" --shard 0/2 --output "$work/out/m.csv"
expect 2 "periods = 1 is invalid" "$bin" "${map[@]}" --periods 1 --output "$work/out/m.csv"
expect 2 "tolerance = '0' is invalid" "$bin" "${map[@]}" --tolerance 0 --output "$work/out/m.csv"
expect 2 "grid cell (i, j) = (0, 0)" "$bin" "${map[@]}" --second-from 0.01 --output "$work/out/m.csv"
expect 2 "output = (not given) is invalid" "$bin" "${map[@]}"
expect 2 "output" "$bin" "${map[@]}" --output "$work/out/missing/m.csv"

# Threads, shards and merge.
"$bin" "${map[@]}" --threads 1 --output "$work/one.csv" > /dev/null || fail "1 thread"
"$bin" "${map[@]}" --threads 2 --output "$work/two.csv" > /dev/null || fail "2 threads"
cmp -s "$work/one.csv" "$work/two.csv" && pass || fail "1 and 2 threads differ"
head -1 "$work/one.csv" | grep -qx "i,j,ni,nj,omega,u_r,section_phase,attractors,attractor,status,period,stops_per_period,sticks_per_period,starts,signature,k,x1,x2,v1,v2" \
  && pass || fail "header"
for k in 1 2; do "$bin" "${map[@]}" --shard $k/2 --output "$work/shard$k.csv" > /dev/null || fail "shard $k"; done
"$bin" map-sweep --merge "$work/merged.csv" "$work/shard2.csv" "$work/shard1.csv" > /dev/null || fail "merge"
cmp -s "$work/one.csv" "$work/merged.csv" && pass || fail "merged shards differ from the whole run"

cp "$work/shard1.csv" "$work/out/"
expect 2 "is in no shard" "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/shard1.csv"
expect 2 "is in '$work/out/shard1.csv' and in '$work/out/shard1.csv'" \
  "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/shard1.csv" "$work/out/shard1.csv"
"$bin" "${map[@]}" --first-to 0.61 --shard 2/2 --output "$work/out/other.csv" > /dev/null
expect 2 "at omega" "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/shard1.csv" "$work/out/other.csv"
rm "$work/out/other.csv"
expect 2 "merge = '$work/out/none.csv' is invalid" "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/none.csv"

if [ -n "${STICKSLIP_MPI:-}" ]; then
  mpi=("${MPIEXEC:-mpirun}" --allow-run-as-root --oversubscribe)
  "${mpi[@]}" -np 1 "$STICKSLIP_MPI" "${map[@]}" --output "$work/rank1.csv" > /dev/null || fail "mpirun -np 1"
  "${mpi[@]}" -np 2 "$STICKSLIP_MPI" "${map[@]}" --threads 1 --output "$work/rank2.csv" > /dev/null || fail "mpirun -np 2"
  cmp -s "$work/one.csv" "$work/rank1.csv" && pass || fail "1 rank differs from the threaded run"
  cmp -s "$work/one.csv" "$work/rank2.csv" && pass || fail "2 ranks differ from the threaded run"
  # Bad input on every rank: one line, exit 2.
  "${mpi[@]}" -np 2 "$STICKSLIP_MPI" "${map[@]}" --periods 1 --output "$work/out/m.csv" > "$work/stdout" 2> "$work/stderr"
  code=$?
  [ "$code" -eq 2 ] && [ "$(grep -c 'periods = 1 is invalid' "$work/stderr")" -eq 1 ] && [ ! -e "$work/out/m.csv" ] \
    && pass || fail "MPI bad input: exit $code, $(cat "$work/stderr")"
else
  echo "the MPI front end is not built: MPI checks skipped"
fi
finish
