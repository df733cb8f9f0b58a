#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: installs what is missing, builds Release, runs every
# run file of continuation-scripts/ into results/, the brute-force sweeps into results/sweeps/,
# the orbit-type maps into results/maps/, the atlases into results/atlases/, the example models of
# continuation-scripts/models/ into results/models/, and regenerates the
# tables (results/paper-table.md, results/atlases/atlases.md,
# results/runs.md, results/trace-intervals.md, results/maps/maps.md) and figures, and writes
# results/README.md from its text in tools/results_readme.md with those tables spliced in (each table's
# script runs tools/splice_readme.py; README.md itself holds no generated table).
set -euo pipefail
source "$(dirname "$0")/setup.sh"
# Only what this job runs: the program, its MPI front end and the Python module (the figures'
# scripts), not the tests and benchmarks, nor the packages they need.
started=$SECONDS
stickslip_install_packages "${STICKSLIP_PACKAGES[@]}"
installed=$SECONDS
stickslip_build "$STICKSLIP_ROOT/build/release" -DCMAKE_BUILD_TYPE=Release -DSTICKSLIP_BUILD_TESTS=OFF \
  -DSTICKSLIP_BUILD_BENCHMARKS=OFF
built=$SECONDS
bin="$STICKSLIP_ROOT/build/release/tools/stickslip"
cd "$STICKSLIP_ROOT"
"$bin" run --results results continuation-scripts/*.toml
# Brute-force diagrams over the forcing frequency, beside the continued branches: four chains
# (the preset state and three scattered around it), in parallel.
mkdir -p results/sweeps
"$bin" sweep --preset paper-4.1 --from 0.55 --to 0.69 --steps 56 --chains 4 --output results/sweeps/paper-4.1-omega.csv
"$bin" sweep --preset paper-5.1 --from 0.55 --to 0.6 --steps 50 --chains 4 --output results/sweeps/paper-5.1-omega.csv
"$bin" sweep --preset paper-6 --from 0.54 --to 0.58 --steps 40 --chains 4 --output results/sweeps/paper-6-omega.csv
# Section 5.1's stable stretch (TR to LP) coexists with other motions that the chains above
# fall into; a chain started on the continued orbit at TR2 follows it.
"$bin" sweep --point paper-5.1-omega-up:TR2 --from 0.5785 --to 0.5865 --steps 16 --chains 1 \
  --output results/sweeps/paper-5.1-omega-from-TR2.csv
# Over the traces' ranges (the frequency responses, results/figures/*-frequency-response.png), at
# the data the traces hold (not section 4.2's, whose trace solves u_s = u_r).
mkdir -p results/sweeps/traces
"$bin" sweep --preset paper-4.1 --from 0.3 --to 0.69 --steps 78 --chains 4 --output results/sweeps/traces/paper-4.1-omega.csv
"$bin" sweep --preset paper-5.1 --from 0.53 --to 0.59 --steps 60 --chains 4 --output results/sweeps/traces/paper-5.1-omega.csv
"$bin" sweep --preset paper-5.2 --from 0.57 --to 0.68 --steps 55 --chains 4 --output results/sweeps/traces/paper-5.2-omega.csv
"$bin" sweep --preset paper-6 --from 0.55 --to 0.575 --steps 50 --chains 4 --output results/sweeps/traces/paper-6-omega.csv
# Section 5.2's stable stretch of 'slip- slip+ stick' coexists with the larger motion the chains
# above settle on; a chain started on the trace at its crossing-sliding (SK3) follows it.
"$bin" sweep --results results/paper-5.2-omega-trace --point branch-1:SK3 --from 0.6045 --to 0.6585 --steps 27 \
  --chains 1 --output results/sweeps/traces/paper-5.2-omega-from-SK3.csv
# Orbit-type maps in (omega, u_r) from the traces (stickslip map), each against a brute-force map of
# the same rectangle (stickslip map-sweep): the curves through the traces' special points, the
# regions they cut, and the agreement, cell by cell (results/maps/<name>/comparison.md).
mkdir -p results/maps
"$bin" map-sweep --preset paper-5.1 --first omega --first-from 0.5 --first-to 0.62 --first-steps 120 --second u_r \
  --second-from 0.3 --second-to 0.8 --second-steps 10 --output results/maps/paper-5.1-omega-u_r-brute-force.csv
"$bin" map --trace results/paper-5.1-omega-trace --second u_r --second-from 0.3 --second-to 0.8 --first-from 0.5 \
  --first-to 0.62 --brute-force results/maps/paper-5.1-omega-u_r-brute-force.csv --output results/maps/paper-5.1-omega-u_r
"$bin" map-sweep --preset paper-6 --first omega --first-from 0.54 --first-to 0.59 --first-steps 50 --second u_r \
  --second-from 1.2 --second-to 1.6 --second-steps 8 --output results/maps/paper-6-omega-u_r-brute-force.csv
"$bin" map --trace results/paper-6-omega-trace --second u_r --second-from 1.2 --second-to 1.6 --first-from 0.54 \
  --first-to 0.59 --brute-force results/maps/paper-6-omega-u_r-brute-force.csv --output results/maps/paper-6-omega-u_r
for m in paper-5.1-omega-u_r paper-6-omega-u_r; do
  "$bin" plot results/maps/$m results/maps/$m-brute-force.csv --output results/figures/$m-map.png
done
# ... and the brute-force map of an oscillator of your own ([model]): five masses over (omega, F_s).
"$bin" map-sweep --model continuation-scripts/models/five-mass-chain.toml --first omega --first-from 0.2 --first-to 1.6 \
  --first-steps 28 --second F_s --second-from 0.3 --second-to 0.6 --second-steps 6 \
  --output results/maps/five-mass-chain-omega-F_s-brute-force.csv
"$bin" plot results/maps/five-mass-chain-omega-F_s-brute-force.csv --output results/figures/five-mass-chain-omega-F_s-map.png
# Atlases: every periodic motion over a range of omega (stickslip atlas), and their frequency responses.
mkdir -p results/atlases
"$bin" atlas --preset paper-4.1 --range 0.3,0.95 --steps 65 --results results/atlases --output paper-4.1-omega
"$bin" atlas --preset paper-5.1 --range 0.4,0.8 --steps 40 --results results/atlases --output paper-5.1-omega
"$bin" atlas --preset paper-6 --range 0.4,0.75 --steps 35 --results results/atlases --output paper-6-omega
# ... and of oscillators of your own ([model]): the paper's two masses written as a chain (the same
# motions as paper-4.1-omega, by the general model's code), five masses, and a belt (no forcing).
"$bin" atlas --model continuation-scripts/models/paper-4.1-as-a-chain.toml --range 0.3,0.95 --steps 65 \
  --results results/atlases --output paper-4.1-as-a-chain-omega
"$bin" atlas --model continuation-scripts/models/five-mass-chain.toml --range 0.2,2.0 --steps 60 \
  --results results/atlases --output five-mass-chain-omega
"$bin" atlas --model continuation-scripts/models/belt-damped.toml --parameter v_b --range 0.1,1.0 --steps 18 --transients 100 \
  --results results/atlases --output belt-damped-v_b
for a in paper-4.1-omega paper-5.1-omega paper-6-omega paper-4.1-as-a-chain-omega five-mass-chain-omega; do
  "$bin" plot results/atlases/$a --yscale log --output results/figures/$a-atlas.png
done
"$bin" plot results/atlases/belt-damped-v_b --output results/figures/belt-damped-v_b-atlas.png
# Oscillators of your own (continuation-scripts/models/: a chain, matrices in Matrix Market files, a
# belt): each described, and the periodic orbit its motion from rest settles on found and verified.
mkdir -p results/models
for f in continuation-scripts/models/*.toml; do
  { "$bin" describe "$f"; echo; "$bin" find --model "$f"; } > "results/models/$(basename "$f" .toml).txt"
done
# Two of them traced from there through their changes of orbit type, written as stickslip trace writes a
# trace: the five-mass chain over a decade of omega, the damped belt in its speed up to the fold where
# the slip grazes the belt.
"$bin" find --model continuation-scripts/models/five-mass-chain.toml --trace 0.2,2.0 --results results/models \
  --output five-mass-chain-omega-trace
"$bin" find --model continuation-scripts/models/belt-damped.toml --trace 0.1,1.0 --results results/models \
  --output belt-damped-v_b-trace
# The README's quick start: two masses in SI units (section 4.1's data) traced over omega, and drawn.
"$bin" find --model continuation-scripts/models/two-masses.toml --trace 30,69 --results results/models \
  --output two-masses-omega-trace
"$bin" plot results/models/two-masses-omega-trace --output results/figures/two-masses-omega-trace-frequency-response.png
# Its crossing-sliding boundary in (omega, F_s) from the trace's SK2 (continuation-scripts/curves/): the
# paper's paper-4.1-sk-boundary in SI units, continued through the general model.
"$bin" run --results results/models/two-masses-omega-trace continuation-scripts/curves/two-masses-sk-boundary.toml
"$bin" plot results/models/two-masses-omega-trace/two-masses-sk-boundary \
  --output results/figures/two-masses-sk-boundary.png
# Its orbit-type map in (omega, F_s) from the trace (stickslip map): section 4.1's regions in SI units,
# cut by the torus, grazing and crossing-sliding curves through the trace's special points.
"$bin" map --trace results/models/two-masses-omega-trace --second F_s --second-from 7.5 --second-to 20 \
  --output results/maps/two-masses-omega-F_s
"$bin" plot results/maps/two-masses-omega-F_s --output results/figures/two-masses-omega-F_s-map.png
# The five-mass chain's brute-force diagram over the same decade, from rest and a start scattered around
# it, up and back down: its resonances, and the permanent sticks below omega = 0.4; and its figure with
# the trace's branches over it.
"$bin" sweep --model continuation-scripts/models/five-mass-chain.toml --from 0.2 --to 2.0 --steps 60 --transients 300 \
  --periods 6 --chains 2 --output results/models/five-mass-chain-omega-sweep.csv
"$bin" plot results/models/five-mass-chain-omega-trace results/models/five-mass-chain-omega-sweep.csv \
  --output results/figures/five-mass-chain-omega-sweep.png
# The damped belt's brute-force diagram in its speed, read on its stick entries: the stick-slip cycle from
# rest up to its fold near v_b = 0.549 (the trace's), steady sliding (max |x| = F_k/k) at every speed.
"$bin" sweep --model continuation-scripts/models/belt-damped.toml --parameter v_b --from 0.1 --to 1.0 --steps 45 \
  --transients 100 --periods 6 --chains 2 --output results/models/belt-damped-v_b-sweep.csv
"$bin" plot results/models/belt-damped-v_b-trace results/models/belt-damped-v_b-sweep.csv \
  --output results/figures/belt-damped-v_b-sweep.png
/usr/bin/python3 tools/atlas_summary.py results
/usr/bin/python3 tools/map_summary.py results
tools/paper_table.sh "$bin"
/usr/bin/python3 tools/plot_figures.py --stickslip "$bin" --results results
/usr/bin/python3 tools/summarize_runs.py results
/usr/bin/python3 tools/trace_intervals.py results
stickslip_print_times tools/run.sh install $((installed - started)) build $((built - installed)) run $((SECONDS - built))
