#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest.
#   tools/test.sh             Release build in build/release
#   tools/test.sh --sanitize  AddressSanitizer + UndefinedBehaviorSanitizer build in build/asan
set -euo pipefail
source "$(dirname "$0")/setup.sh"
started=$SECONDS
stickslip_install_packages "${STICKSLIP_PACKAGES[@]}" "${STICKSLIP_TEST_PACKAGES[@]}"
installed=$SECONDS
if [ "${1:-}" = "--sanitize" ]; then
  dir="$STICKSLIP_ROOT/build/asan"
  # -O1 and line tables only (-g1): the sanitizers' reports keep their function names and lines,
  # and the build costs about half the CPU of RelWithDebInfo's -O2 -g (floquet_gradients.cpp:
  # 43 s against 81 s). clang (installed for the fuzzers) compiles it in about half of g++'s time
  # (linear_oscillator_test.cpp: 173 s against 326 s, the same flags on the same loaded machine).
  stickslip_build "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    -DSTICKSLIP_SANITIZE=ON -DSTICKSLIP_BUILD_TESTS=ON -DSTICKSLIP_BUILD_BENCHMARKS=OFF -DSTICKSLIP_BUILD_PYTHON=OFF
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
  dir="$STICKSLIP_ROOT/build/release"
  # The tests and benchmarks on explicitly: tools/run.sh turns them off in the same tree.
  stickslip_build "$dir" -DCMAKE_BUILD_TYPE=Release -DSTICKSLIP_BUILD_TESTS=ON -DSTICKSLIP_BUILD_BENCHMARKS=ON
fi
built=$SECONDS
# Open MPI is one of the packages installed above: the MPI checks of the map-sweep tests must run
# here (they fail, not skip, when stickslip-mpi or mpirun is missing).
export STICKSLIP_REQUIRE_MPI=1
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)"
stickslip_print_times "tools/test.sh${1:+ $1}" install $((installed - started)) build $((built - installed)) test $((SECONDS - built))
