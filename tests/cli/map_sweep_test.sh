#!/usr/bin/env bash
# stickslip map-sweep: bad input (one line naming the field, exit 2, nothing written); the file
# the same bytes for 1 and 2 threads; shards merged give the unsharded file; a merge of shards of
# different grids, with a cell twice or one missing, is refused; with the MPI front end
# (STICKSLIP_MPI; required where STICKSLIP_REQUIRE_MPI is set, as tools/test.sh sets it), 1, 2 and 3
# ranks write the single process's bytes. The grid has 5 rows: 2 and 3 ranks or shards split it
# unevenly (3 + 2, 2 + 2 + 1).
source "$(dirname "$0")/expect.sh"
source "$(dirname "$0")/map_sweep_common.sh"
m="$work/out/m.csv"
expect_map 2 "first-steps = 2.5 is invalid" --first-steps 2.5 --output "$m"
expect_map 2 "first-steps = 10001 is invalid" --first-steps 10001 --output "$m"
expect_map 2 "second = 'omega' is invalid" --second omega --output "$m"
expect_map 2 "first = 'mu' is invalid" --first mu --output "$m"
expect_map 2 "shard = '3/2' is invalid" --shard 3/2 --output "$m"
expect_map 2 "shard = '0/2' is invalid" --shard 0/2 --output "$m"
expect_map 2 "shard = '1' is invalid" --shard 1 --output "$m"
expect_map 2 "periods = 1 is invalid" --periods 1 --output "$m"
expect_map 2 "tolerance = 0 is invalid" --tolerance 0 --output "$m"
expect_map 2 "scatter = -1 is invalid" --scatter -1 --output "$m"
expect_map 2 "first-from = '0.6x' is not a finite number" --first-from 0.6x --output "$m"
expect_map 2 "grid cell (i, j) = (0, 0)" --second-from 0.01 --output "$m"
expect_map 2 "grid = 12024012 runs (1001 rows of 1001 cells, 12 runs a cell) is invalid" \
  --first-steps 1000 --second-steps 1000 --starts 10 --output "$m"
expect_map 2 "output = (not given) is invalid"
expect_map 2 "output" --output "$work/out/missing/m.csv"

# Threads, shards and merge.
map_args
map=("${args[@]}")
expect 2 "shards = '$work/out/stray.csv' is invalid" "$bin" "${map[@]}" --output "$m" "$work/out/stray.csv"
"$bin" "${map[@]}" --threads 1 --output "$work/one.csv" > /dev/null || fail "1 thread"
"$bin" "${map[@]}" --threads 2 --output "$work/two.csv" > /dev/null || fail "2 threads"
cmp -s "$work/one.csv" "$work/two.csv" && pass || fail "1 and 2 threads differ"
head -1 "$work/one.csv" | grep -qx "i,j,ni,nj,omega,u_r,section_phase,run,attractors,attractor,status,period,stops_per_period,sticks_per_period,starts,signature,k,x1,x2,v1,v2" \
  && pass || fail "header"
for k in 1 2; do "$bin" "${map[@]}" --shard $k/2 --output "$work/shard$k.csv" > /dev/null || fail "shard $k"; done
"$bin" map-sweep --merge "$work/merged.csv" "$work/shard2.csv" "$work/shard1.csv" > /dev/null || fail "merge"
cmp -s "$work/one.csv" "$work/merged.csv" && pass || fail "merged shards differ from the whole run"
for k in 1 2 3; do "$bin" "${map[@]}" --shard $k/3 --output "$work/third$k.csv" > /dev/null || fail "shard $k/3"; done
"$bin" map-sweep --merge "$work/merged3.csv" "$work/third3.csv" "$work/third1.csv" "$work/third2.csv" > /dev/null || fail "merge of 3"
cmp -s "$work/one.csv" "$work/merged3.csv" && pass || fail "3 merged shards differ from the whole run"

cp "$work/shard1.csv" "$work/out/"
expect 2 "is in no shard" "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/shard1.csv"
expect 2 "is in '$work/out/shard1.csv' and in '$work/out/shard1.csv'" \
  "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/shard1.csv" "$work/out/shard1.csv"
map_args --first-to 0.61 --shard 2/2 --output "$work/out/other.csv"
"$bin" "${args[@]}" > /dev/null || fail "other grid"
expect 2 "at omega" "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/shard1.csv" "$work/out/other.csv"
rm "$work/out/other.csv"
expect 2 "shards = '$work/out/none.csv' is invalid" "$bin" map-sweep --merge "$work/out/m.csv" "$work/out/none.csv"

# The figure (stickslip plot, tools/stickslip_plot.py, python3-matplotlib): a PNG.
"$bin" plot "$work/one.csv" --output "$work/map.png" > /dev/null && [ "$(head -c 4 "$work/map.png" | tail -c 3)" = "PNG" ] \
  && pass || fail "the map's figure"

if mpi_ready; then
  # 1 rank on 2 threads, 2 and 3 ranks on 1 thread each (rows 3 + 2 and 2 + 2 + 1): the bytes of the
  # single process, hence of the merged shards too.
  for np in 1 2 3; do
    threads=1
    [ "$np" -eq 1 ] && threads=2
    "${mpi[@]}" -np $np "$STICKSLIP_MPI" "${map[@]}" --threads $threads --output "$work/rank$np.csv" > /dev/null ||
      fail "mpirun -np $np"
    cmp -s "$work/one.csv" "$work/rank$np.csv" && pass || fail "$np rank(s) differ from the single process"
    cmp -s "$work/merged3.csv" "$work/rank$np.csv" && pass || fail "$np rank(s) differ from the merged shards"
  done
  # More ranks than rows: 2 rows over 3 ranks (rank 2 computes nothing), the single process's bytes.
  map_args --second-steps 1
  "$bin" "${args[@]}" --output "$work/two-rows.csv" > /dev/null || fail "2 rows"
  "${mpi[@]}" -np 3 "$STICKSLIP_MPI" "${args[@]}" --output "$work/two-rows-3.csv" > /dev/null || fail "2 rows on 3 ranks"
  cmp -s "$work/two-rows.csv" "$work/two-rows-3.csv" && pass || fail "2 rows on 3 ranks differ from the single process"
  # Bad input on every rank: one line, exit 2, nothing written (more in map_sweep_hostile_test.sh).
  map_runner=("${mpi[@]}" -np 2 "$STICKSLIP_MPI")
  expect_map 2 "periods = 1 is invalid" --periods 1 --output "$work/out/m.csv"
  map_runner=()
  # An oscillator of your own ([model]) on 2 ranks: the single process's bytes.
  model=(map-sweep --model "$root/continuation-scripts/models/den-hartog.toml" --first-from 1.2 --first-to 2
         --first-steps 4 --second F_k --second-from 0.15 --second-to 0.25 --second-steps 2 --set F_s=0.3 --starts 2)
  "$bin" "${model[@]}" --output "$work/model.csv" > /dev/null &&
    "${mpi[@]}" -np 2 "$STICKSLIP_MPI" "${model[@]}" --output "$work/model-2.csv" > /dev/null &&
    cmp -s "$work/model.csv" "$work/model-2.csv" && pass || fail "map-sweep --model on 2 ranks differs from one process"
fi
finish
