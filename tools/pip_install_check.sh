#!/usr/bin/env bash
# `pip install lib/python` as a user on Debian 12 runs it (Debian's Python refuses system-wide pip
# installs): a venv that sees Debian's packages, pip offline without build isolation, then the
# package imported by the venv's Python from a directory outside the trees. Not in the test suite:
# the install builds the library and the extension from scratch (minutes); give
# STICKSLIP_CMAKE_BUILD_DIR=<dir> to keep that build for the next run.
#   tools/pip_install_check.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
version=$(sed -n 's/^project(stickslip VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
cd "$work"
"$work/venv/bin/pip" install --no-build-isolation --no-index "$root/lib/python"
"$work/venv/bin/python" - "$work/venv" "$version" <<'PY'
import sys
venv, version = sys.argv[1:]
import stickslip
assert stickslip.__file__.startswith(venv + "/"), stickslip.__file__
assert stickslip.__version__ == version, (stickslip.__version__, version)
assert stickslip.solve(preset="paper-5.1").admissible
print(f"pip install lib/python: stickslip {stickslip.__version__} imports from {stickslip.__file__}")
PY
