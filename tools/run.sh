#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: installs what is missing, builds Release, runs every
# run file of continuation-scripts/ into results/, and regenerates results/paper-table.md.
set -euo pipefail
source "$(dirname "$0")/setup.sh"
stickslip_install_packages
stickslip_build "$STICKSLIP_ROOT/build/release" -DCMAKE_BUILD_TYPE=Release
bin="$STICKSLIP_ROOT/build/release/tools/stickslip"
cd "$STICKSLIP_ROOT"
"$bin" run --results results continuation-scripts/*.toml
tools/paper_table.sh "$bin"
/usr/bin/python3 tools/summarize_runs.py results
