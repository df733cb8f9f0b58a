#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: installs what is missing, builds Release, and runs
# it. Until the continuation engine exists, the main job simulates the paper's section 4.1
# example and prints its stops.
set -euo pipefail
source "$(dirname "$0")/setup.sh"
stickslip_install_packages
stickslip_build "$STICKSLIP_ROOT/build/release" -DCMAKE_BUILD_TYPE=Release
"$STICKSLIP_ROOT/build/release/tools/stickslip" simulate --preset paper-4.1 --periods 2
