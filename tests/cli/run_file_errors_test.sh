#!/usr/bin/env bash
# Run-file errors name the file, the line and the key and exit with code 2; a run that fails
# leaves results/ untouched.
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
mkdir -p "$work/results/keep"
echo "stored" > "$work/results/keep/branch.csv"

good='output = "t"
[start]
preset = "paper-5.1"
[continuation]
parameter = "omega"
direction = "up"
range = [0.3, 0.9]'

expect() {  # expect <code> <pattern> <run file text>
  local code=$1 pattern=$2
  printf '%s\n' "$3" > "$work/r.toml"
  "$bin" run --results "$work/results" "$work/r.toml" > /dev/null 2> "$work/err"
  local got=$?
  if [ "$got" -ne "$code" ] || ! grep -q -- "$pattern" "$work/err" || [ -e "$work/results/t" ] ||
     [ "$(cat "$work/results/keep/branch.csv")" != "stored" ]; then
    echo "FAIL (want $code, /$pattern/): exit $got: $(cat "$work/err")"
    failures=$((failures + 1))
  else
    echo "ok   $(cat "$work/err")"
  fi
}

expect 2 "r.toml:4:9: key 'start.prest' is unknown: did you mean 'start.preset'" "${good/preset = \"paper-5.1\"/preset = \"paper-5.1\"
prest = 1}"
expect 2 "r.toml:6:13: key 'continuation.direction' must be a string" "${good/direction = \"up\"/direction = 1}"
expect 2 "key 'start.preset' or 'start.signature': give exactly one" "${good/preset = \"paper-5.1\"/}"
expect 2 "key 'start.signatur' is unknown: did you mean 'start.signature'" "${good/preset = \"paper-5.1\"/signatur = \"slip+\"}"
expect 2 "key 'tarce' is unknown: did you mean 'trace'" "${good/direction = \"up\"/}
[tarce]"
expect 2 "key 'start' is missing" 'output = "t"
[continuation]
parameter = "omega"
direction = "up"
range = [0.3, 0.9]'
expect 2 "key 'continuation.range' = \[0.7, 0.9\] excludes the start, omega = 0.57" "${good/0.3, 0.9/0.7, 0.9}"
expect 2 "key 'output' is missing" "${good/output = \"t\"/}"
expect 2 "key 'start.preset' = 'paper-9' is unknown" "${good/paper-5.1/paper-9}"
expect 2 "key 'unknowns' is invalid: the system is not square" "$good
[unknowns]
free = [\"u_r\"]"
expect 2 "non-ASCII byte" "${good/up/üp}"
expect 2 "control character" "$(printf '%s\001' "$good")"
expect 2 "key 'start.restart.run' = '../x' is invalid: valid a run name" "${good/preset = \"paper-5.1\"/restart = { run = \"..\/x\", label = \"EP1\" \}}"
# The byte after a backslash in a string is checked like any other.
expect 2 "r.toml:1:12: control character 0x01" "$(printf 'output = "\\\001t"')"
expect 2 "r.toml:1:12: non-ASCII byte 0xc3" "$(printf 'output = "\\\303\274t"')"
expect 2 "nest at most two levels" "$good
x = [[[1]]]"
expect 2 "r.toml:1:" 'output = "t'
for bad in 0 -1; do
  expect 2 "r.toml:8:17: key 'continuation.max_amplitude' = $bad is invalid: valid range a finite continuation.max_amplitude > 0" "$good
max_amplitude = $bad"
done
for bad in nan inf; do
  expect 2 "r.toml:8:17: key 'continuation.max_amplitude' must be finite" "$good
max_amplitude = $bad"
done
for bad in -0.1 1 2; do
  expect 2 "r.toml:8:22: key 'continuation.resonance_approach' = $bad is invalid: valid range 0 <= continuation.resonance_approach < 1 (0: never)" "$good
resonance_approach = $bad"
done
expect 2 "key 'continuation.max_amplitude' is invalid with a \[trace\] table" "${good/direction = \"up\"/}
max_amplitude = 1e4
[trace]"
# Found by the fuzzer: a multi-line literal string hid a '#' from the screen, and the non-ASCII
# character after it (U+FEBF) reached toml++'s __builtin_unreachable.
expect 2 "r.toml:1:5: multi-line strings" "$(printf "a = '''/''a ''.''.0= t'# s''''\xef\xba\xbf\"\"x0\n \ng g ")"
expect 2 "r.toml:1:10: multi-line strings" 'output = """t"""'
# Found by the fuzzer: integers a double cannot hold exactly (beyond 2^53) are numbers too.
expect 2 "key 'continuation.range' = \\[9007199254740992, 1e+16\\] excludes the start" "${good/0.3, 0.9/9007199254740993, 1e16}"
expect 2 "key 'continuation.user_values_of.x' must be an array of numbers" "$good
user_values_of = {u_r = [9007199254740993], x = 1}"
expect 2 "key 'continuation.parameter' = 'u_r' is tied to u_s" "${good/omega/u_r}
[unknowns]
tie_u_r = true"
expect 2 "key 'output' = '../t' is invalid" "${good/output = \"t\"/output = \"..\/t\"}"
# A duration that was never given is refused (one given as 0 is a zero-length segment).
expect 2 "key 'start.guess' misses d2 (0 to the period)" "${good/preset = \"paper-5.1\"/signature = \"slip- slip+\"
set = { chi = 0.3, eta = 4.0, omega = 0.6, u_s = 0.1, u_r = 0.3 \}
guess = { d1 = 0.0 \}}"
expect 2 "key 'unknowns.fix' = 'u_r' is released by free as well" "$good
[unknowns]
free = [\"u_r\"]
fix = [\"u_r\"]"
# A start that does not converge fails the run (exit 3) and writes nothing.
expect 3 "does not converge" "$good
[start.guess]
x10 = 40.0
d1 = 0.01"

# switch_branch (the branch leaving a PD or SB): at another label, and with multiple shooting.
"$bin" run --results "$work/results" "$(dirname "$0")/../../continuation-scripts/paper-5.2-omega-to-pd.toml" > /dev/null ||
  { echo "FAIL: the run to switch from"; failures=$((failures + 1)); }
switched='output = "t"
[start]
restart = { run = "paper-5.2-omega-to-pd", label = "PD2", switch_branch = true }
[continuation]
parameter = "omega"
direction = "up"
range = [0.6, 0.8]'
expect 2 "key 'start.restart.switch_branch' = true is invalid at 'EP1' (type EP): valid at a period doubling (PD) or a symmetry breaking (SB)" "${switched/PD2/EP1}"
expect 2 "key 'continuation.shooting' = \"multiple\" is invalid with start.restart.switch_branch" "$switched
shooting = \"multiple\""
expect 2 "key 'start.restart.switch_branch' = 1 is invalid: valid true or false (a boolean; its type is integer)" "${switched/switch_branch = true/switch_branch = 1}"
# With a [trace] (no direction: the switch would take one side, the trace's down chain come back up it).
expect 2 "key 'start.restart.switch_branch' = true is invalid with a .trace. table" "${switched/direction = \"up\"/}
[trace]"

# boundary (a type boundary in two parameters): at a label that is no such change, in the continued
# parameter, with switch_branch.
"$bin" run --results "$work/results" "$(dirname "$0")/../../continuation-scripts/paper-4.1-omega-down.toml" > /dev/null ||
  { echo "FAIL: the run to start a boundary from"; failures=$((failures + 1)); }
bounded='output = "t"
[start]
restart = { run = "paper-4.1-omega-down", label = "SK2", boundary = "u_r" }
[continuation]
parameter = "omega"
direction = "down"
range = [0.3, 0.69]'
expect 2 "key 'start.restart.boundary' = 'u_r' is invalid at 'EP1' (EP): valid LP, SB or TR for an antisymmetric orbit" "${bounded/SK2/EP1}"
expect 2 "key 'start.restart.boundary' = 'omega' is invalid at 'SK2' (margin:reversal:1): valid a parameter the model varies, not the continued omega" "${bounded/boundary = \"u_r\"/boundary = \"omega\"}"
expect 2 "key 'start.restart.boundary' cannot go with start.restart.switch_branch" "${bounded/boundary = \"u_r\"/boundary = \"u_r\", switch_branch = true}"
# With a [trace]: a trace follows branches in one parameter, not a curve in two.
expect 2 "key 'start.restart.boundary' = 'u_r' is invalid with a .trace. table: valid left out" "${bounded/direction = \"down\"/}
[trace]"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
