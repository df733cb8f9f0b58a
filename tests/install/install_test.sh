#!/usr/bin/env bash
# cmake --install into a temporary prefix, then, from the prefix alone: the installed command runs
# (--version, a small solve, a figure drawn by the scripts it finds relative to itself, also after the
# prefix is moved), a project of the user's own (tests/install/consumer/) configures and builds with
# find_package(stickslip) and runs, and the installed Python package imports from a Python whose
# path does not include the build tree.
# Environment: BUILD (the build tree), SOURCE (the source tree), VERSION (the project's, from
# CMakeLists.txt), PYTHON_DIR (the package's directory under the prefix; empty without the Python
# module), GENERATOR (CMake's generator for the consumer).
set -uo pipefail
build=${BUILD:?} source_dir=${SOURCE:?} version=${VERSION:?} cmake=${CMAKE:-cmake}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

prefix="$work/prefix"
"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; exit 1; }
for f in bin/stickslip share/stickslip/stickslip_plot.py \
         include/stickslip/version.hpp include/stickslip/orbits/orbit_solver.hpp \
         lib/cmake/stickslip/stickslipConfig.cmake lib/cmake/stickslip/stickslipConfigVersion.cmake \
         lib/cmake/stickslip/stickslipTargets.cmake lib/cmake/stickslip/FindSuiteSparse.cmake; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
ls "$prefix"/lib/libstickslip.a > /dev/null 2>&1 || ls "$prefix"/lib/*/libstickslip.a > /dev/null 2>&1 || fail "no libstickslip.a"
if [ -x "$build/tools/stickslip-mpi" ]; then [ -x "$prefix/bin/stickslip-mpi" ] || fail "stickslip-mpi not installed"; fi

# The command, from a directory that is neither tree.
cd "$work"
[ "$("$prefix/bin/stickslip" --version)" = "stickslip $version" ] || fail "--version: $("$prefix/bin/stickslip" --version)"
"$prefix/bin/stickslip" solve --preset paper-5.1 > "$work/solve.txt" 2>&1 || fail "installed solve exits $?: $(cat "$work/solve.txt")"
grep -q "^signature  slip- slip+ stick slip+$" "$work/solve.txt" || fail "installed solve: $(head -3 "$work/solve.txt")"
# plot finds its scripts in <prefix>/share/stickslip, wherever the prefix is.
mv "$prefix" "$work/moved"
prefix="$work/moved"
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  "$prefix/bin/stickslip" plot paper-5.1-omega-up --results "$source_dir/results" --output "$work/up.png" > "$work/plot.txt" 2>&1 ||
    fail "installed plot exits $?: $(cat "$work/plot.txt")"
  [ -s "$work/up.png" ] || fail "installed plot wrote no figure"
fi

# A consumer project: find_package(stickslip), stickslip::stickslip.
"$cmake" -S "$source_dir/tests/install/consumer" -B "$work/consumer" -G "${GENERATOR:-Ninja}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$work/consumer.log" 2>&1 || fail "consumer configure: $(tail -20 "$work/consumer.log")"
"$cmake" --build "$work/consumer" > "$work/consumer-build.log" 2>&1 || fail "consumer build: $(tail -30 "$work/consumer-build.log")"
out=$("$work/consumer/consumer" 2>&1)
[ "$out" = "stickslip $version
slip- slip+ stick slip+
admissible" ] || fail "consumer output: $out"
out=$("$work/consumer/own_oscillator" 2>&1)
expected="fixed size: 'stick slip-' up to v_b = 0.549: no-adjacent-type
sized at run time: 'stick slip-' up to v_b = 0.549: no-adjacent-type"
[ "$out" = "$expected" ] || fail "own_oscillator output: $out"

# The Python package, from the prefix only: no PYTHONPATH but the prefix's, no user site, run
# outside both trees; it is the installed copy and its version is the command's.
if [ -n "${PYTHON_DIR:-}" ]; then
  env -u PYTHONPATH PYTHONPATH="$prefix/$PYTHON_DIR" /usr/bin/python3 -s - "$prefix" "$build" "$source_dir" "$version" <<'PY' ||
import sys
prefix, build, source, version = sys.argv[1:]
assert not any(p.startswith((build, source)) for p in sys.path if p), sys.path
import stickslip
assert stickslip.__file__.startswith(prefix + "/"), stickslip.__file__
assert stickslip.__version__ == version, stickslip.__version__
assert stickslip.Parameters.preset("paper-6").chi == 0.7
assert stickslip.solve(preset="paper-5.1").admissible
PY
    fail "the installed Python package"
fi

[ "$failures" -eq 0 ] && echo "install test passed" || { echo "$failures failure(s)"; exit 1; }
