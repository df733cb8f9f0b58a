#!/usr/bin/env bash
# stickslip solve: JSON shape and values for a preset, the paper's own choices through
# --free/--fix, and every kind of bad input with its message and exit code.
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

"$bin" solve --preset paper-5.1 --json > "$work/s.json" || fail "paper-5.1 exit $?"
/usr/bin/python3 - "$work/s.json" <<'PY' || failures=$((failures + 1))
import json, sys
o = json.load(open(sys.argv[1]))
for key in ("signature", "parameters", "phi", "x10", "x20", "v10", "segments", "converged",
            "residual_norm", "family_dimension", "margins", "verification"):
    assert key in o, key
assert o["signature"] == "slip- slip+ stick slip+"
assert set(o["parameters"]) == {"chi", "eta", "omega", "u_s", "u_r"}
assert o["converged"] is True and o["residual_norm"] < 1e-11 and o["family_dimension"] == 0
assert [s["mode"] for s in o["segments"]] == ["slip-", "slip+", "stick", "slip+"]
assert abs(o["segments"][1]["duration"] - 2) < 2e-4 and abs(o["segments"][3]["duration"] - 3) < 2e-4
assert min(v for v in o["margins"].values() if v is not None) > 0
assert o["verification"]["passed"] is True
# The orbit's measures by the branch columns' names; the counts of section 5.1 per period: three
# slips ending at stops, one stick.
m = o["measures"]
assert list(m) == ["amplitude:x1", "amplitude:x2", "peak-to-peak:x2", "stick-fraction", "stops", "sticks",
                   "friction-work", "equivalent-damping"], m
assert m["stops"] == 3 and m["sticks"] == 1 and isinstance(m["stops"], int)
assert abs(m["stick-fraction"] - o["segments"][2]["duration"] * o["parameters"]["omega"] / (2 * 3.141592653589793)) < 1e-15
assert 0 < m["peak-to-peak:x2"] <= 2 * m["amplitude:x2"]
print("solve json ok")
PY
# The report lists the same measures.
"$bin" solve --preset paper-5.1 > "$work/s.txt" || fail "paper-5.1 report exit $?"
grep -q "^measures over one period" "$work/s.txt" || fail "paper-5.1 report has no measures"
grep -Eq "^  stops +3$" "$work/s.txt" || fail "paper-5.1 report: stops not 3"
grep -Eq "^  sticks +1$" "$work/s.txt" || fail "paper-5.1 report: sticks not 1"

# Newton converges past section 4.2's family end (u_s < 0 at omega = 0.63): the verification says
# the orbit is no motion of the system (it used to read an empty simulation: SIGSEGV).
"$bin" solve --preset paper-4.2 --set omega=0.63 --json > "$work/42.json"
code=$?
[ "$code" -lt 128 ] || fail "paper-4.2 omega=0.63 crashed with exit $code"
[ "$code" -eq 4 ] || fail "paper-4.2 omega=0.63, no motion of the system: exit $code (want 4)"
/usr/bin/python3 -c "
import json
v = json.load(open('$work/42.json'))['verification']
assert v['passed'] is False and 'u_s = -' in v['not_simulated'], v
assert v['exact']['max_mismatch'] is None, v
print('not simulated ok')" || failures=$((failures + 1))

# Section 5.2's printed data solve to an orbit whose stick ends early (G:3 < 0): exit 4 in every
# output format, the output printed all the same and the reason in one line on stderr.
for format in "" --json --compare-paper; do
  "$bin" solve --preset paper-5.2 $format > "$work/52-printed" 2> "$work/err"
  code=$?
  [ "$code" -eq 4 ] || fail "paper-5.2 $format: exit $code (want 4)"
  [ -s "$work/52-printed" ] || fail "paper-5.2 $format: nothing printed"
  [ "$(cat "$work/err")" = "error: the solution is not a motion of the system: margin G:3 = -0.0072388 <= 0" ] ||
    fail "paper-5.2 $format: stderr $(cat "$work/err")"
done
"$bin" solve --preset paper-5.2 > "$work/52-printed" 2> /dev/null
grep -q "^smallest   G:3 = -0.0072388: NOT a motion of the system" "$work/52-printed" || fail "paper-5.2 report changed"
/usr/bin/python3 -c "
import json, subprocess, sys
o = json.loads(subprocess.run(['$bin', 'solve', '--preset', 'paper-5.2', '--json'], capture_output=True).stdout)
assert o['converged'] is True and o['verification']['passed'] is False, o['verification']
print('paper-5.2 json ok')" || failures=$((failures + 1))
# The paper's own choice for section 5.2 is a motion: exit 0.
"$bin" solve --preset paper-5.2 --paper-choice > /dev/null || fail "paper-5.2 --paper-choice exit $?"

# Section 5.2 with phi = pi/2 held and u_r released (the paper's choice, ERRATA: u_r = 0.478).
"$bin" solve --preset paper-5.2 --fix phi=1.5707963267948966 --free u_r --json > "$work/52.json" ||
  fail "paper-5.2 --fix phi --free u_r exit $?"
/usr/bin/python3 -c "
import json, sys
o = json.load(open('$work/52.json'))
assert abs(o['parameters']['u_r'] - 0.478) < 1e-3, o['parameters']
assert o['phi'] == 1.5707963267948966
print('paper choice ok')" || failures=$((failures + 1))

# A signature given by hand, from the section 6 printed values.
"$bin" solve --signature "slip- stick slip- / antisymmetric" --set chi=0.7 --set eta=3.8 \
  --set omega=0.5711986642890533 --set u_s=0.06 --set u_r=1.4041 --set x10=2.8901 \
  --set x20=5.1306 --set v10=-0.8108 --set phi=3 --guess d1=2.175 --guess d2=1.56 \
  --guess d3=1.765 > /dev/null || fail "hand-made signature exit $?"

expect_error() {  # expect_error <code> <text> <args...>
  local code=$1 text=$2
  shift 2
  "$bin" solve "$@" > /dev/null 2> "$work/err"
  local got=$?
  if [ "$got" -ne "$code" ] || ! grep -q -- "$text" "$work/err" || [ "$(wc -l < "$work/err")" -ne 1 ]; then
    fail "[$*]: exit $got (want $code), stderr: $(cat "$work/err")"
  else
    echo "ok   [$*]: $(cat "$work/err")"
  fi
}
expect_error 2 "preset = 'paper-7'" --preset paper-7
expect_error 2 "token 2 'stik'" --signature "slip- stik" --set chi=0.3 --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=0.3
expect_error 2 "not square" --preset paper-5.1 --free u_r
expect_error 2 "free = 'mu'" --preset paper-5.1 --free mu --fix phi
expect_error 2 "misses d1" --signature "slip- slip+" --set chi=0.3 --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=0.3 --set x10=1
expect_error 2 "exactly one" --preset paper-5.1 --signature "slip-"
expect_error 3 "did not converge" --preset paper-5.1 --guess d1=0.01 --guess x10=40 --guess phi=5
# A choice of unknowns one equation short (d1 = pi/omega fixed): the released parameter could take
# any value, a family through the parameters, not of orbits at fixed parameters; Newton's singular
# Jacobian stands (not 'not isolated', never an arbitrary parameter value with exit 0). Releasing
# u_r, which a slip-only orbit's equations do not hold, is the same.
expect_error 3 "singular" --preset paper-4.1 --free u_s --fix d1
expect_error 3 "singular" --preset paper-4.1 --free chi --fix d1
expect_error 3 "singular" --preset paper-4.1 --free u_r --fix d1

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
