# Shared by tools/run.sh and tools/test.sh (sourced, not run): installs the Debian 12 packages
# stickslip needs when they are missing, then configures and builds one build tree.
# Idempotent: installed packages, a configured tree and up-to-date targets are skipped.

STICKSLIP_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
STICKSLIP_PACKAGES=(
  cmake ninja-build g++
  libeigen3-dev libsuitesparse-dev libboost-dev libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
  clang libclang-rt-14-dev
  auto-07p python3-numpy python3-matplotlib
  python3-dev pybind11-dev python3-pybind11 python3-pytest
)

stickslip_install_packages() {
  local missing=() package
  for package in "${STICKSLIP_PACKAGES[@]}"; do
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

# stickslip_build <build dir> [cmake options...]
stickslip_build() {
  local dir=$1
  shift
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S "$STICKSLIP_ROOT" -B "$dir" -G Ninja "$@"
  fi
  cmake --build "$dir" -j "$(nproc)"
}
