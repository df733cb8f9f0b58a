# Shared by tools/run.sh and tools/test.sh (sourced, not run): installs the Debian 12 packages
# stickslip needs when they are missing, then configures and builds one build tree.
# Idempotent: installed packages, a tree configured with the same options and up-to-date targets
# are skipped.

STICKSLIP_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# What the main job (tools/run.sh) needs: the compiler, the libraries, Open MPI for stickslip-mpi,
# the Python module and the figures' and tables' scripts (pandas: for Branch.to_pandas()).
STICKSLIP_PACKAGES=(
  cmake ninja-build g++
  libeigen3-dev libsuitesparse-dev libboost-dev libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libopenmpi-dev openmpi-bin
  python3-dev pybind11-dev python3-numpy python3-matplotlib python3-pandas
)
# What only the tests (tools/test.sh) need besides: GoogleTest, Google Benchmark, clang and its
# sanitizer runtimes for the libFuzzer targets, AUTO-07p for the export's test, pytest.
STICKSLIP_TEST_PACKAGES=(
  libgtest-dev libbenchmark-dev
  clang libclang-rt-14-dev
  auto-07p python3-pytest
)

# stickslip_install_packages <package...>: installs those of the packages that are missing.
stickslip_install_packages() {
  local missing=() package
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "== installing: ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
}

# stickslip_build <build dir> [cmake options...]: configures when the tree is new or was configured
# with other options (tools/run.sh and tools/test.sh share build/release with different ones; the
# options are kept in stickslip-options), then builds. A tree configured with the same options is
# not configured again (ninja reruns cmake itself when a CMakeLists.txt changes).
stickslip_build() {
  local dir=$1
  shift
  local options
  options=$(printf '%s\n' "$@")
  if [ ! -f "$dir/build.ninja" ] || [ "$(cat "$dir/stickslip-options" 2>/dev/null)" != "$options" ]; then
    cmake -S "$STICKSLIP_ROOT" -B "$dir" -G Ninja "$@"
    printf '%s\n' "$options" > "$dir/stickslip-options"
  fi
  cmake --build "$dir" -j "$(nproc)"
}

# stickslip_print_times <script> <phase> <seconds> [<phase> <seconds>...]: the script's wall time,
# phase by phase, on one line (tools/fresh_install_check.sh reports it for a fresh machine).
stickslip_print_times() {
  local script=$1 line=""
  shift
  while [ $# -ge 2 ]; do
    line+="${line:+, }$1: $2 s"
    shift 2
  done
  echo "== $script wall time: $line"
}
