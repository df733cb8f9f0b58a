#!/usr/bin/env bash
# Every bad input gets a one-line error naming the field, its value and the valid range, exit
# code 2, and leaves no output file behind (an existing one is not truncated).
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# The subcommand under test and its output option; the sweep cases below change them.
command=simulate
output_flag=--csv

expect_rejected() {  # expect_rejected <field> <expected text> <args...>
  local field=$1 text=$2
  shift 2
  local out="$work/out.csv"
  printf 'keep\n' > "$work/existing.csv"
  "$bin" "$command" "$@" "$output_flag" "$out" > "$work/stdout" 2> "$work/stderr"
  local code=$?
  local lines
  lines=$(wc -l < "$work/stderr")
  local problem=""
  [ "$code" -eq 2 ] || problem+=" exit code $code (want 2);"
  [ "$lines" -eq 1 ] || problem+=" $lines stderr lines (want 1);"
  grep -q -- "$field" "$work/stderr" || problem+=" message does not name '$field';"
  grep -q -- "$text" "$work/stderr" || problem+=" message lacks '$text';"
  [ ! -e "$out" ] || problem+=" output file was created;"
  "$bin" "$command" "$@" "$output_flag" "$work/existing.csv" > /dev/null 2>&1
  [ "$(cat "$work/existing.csv")" = "keep" ] || problem+=" existing file was changed;"
  if [ -n "$problem" ]; then
    echo "FAIL [$command $*]:$problem"
    sed 's/^/    stderr: /' "$work/stderr"
    failures=$((failures + 1))
  else
    echo "ok   [$command $*]: $(cat "$work/stderr")"
  fi
}

p=(--preset paper-4.1)
expect_rejected chi "0.01 <= chi <= 0.99" "${p[@]}" --set chi=1.5
expect_rejected chi "0.01 <= chi <= 0.99" "${p[@]}" --set chi=0
expect_rejected eta "0.01 <= eta <= 100" "${p[@]}" --set eta=-1
expect_rejected eta "0.01 <= eta <= 100" "${p[@]}" --set eta=0
expect_rejected omega "0.01 <= omega <= 100" "${p[@]}" --set omega=0
expect_rejected u_s "1e-06 <= u_s <= 1000" "${p[@]}" --set u_s=0
expect_rejected u_r "u_s = 0.1 <= u_r <= 1000" "${p[@]}" --set u_r=0.05
expect_rejected omega "finite number" "${p[@]}" --set omega=nan
expect_rejected x10 "finite number" "${p[@]}" --set x10=inf
expect_rejected phi "finite number" "${p[@]}" --set phi=1e999
expect_rejected eta "finite number" "${p[@]}" --set eta=4x
expect_rejected omega "natural frequencies" --preset paper-4.1 --set omega=0.7012301668996977
expect_rejected periods "periods" "${p[@]}" --periods -1
expect_rejected periods "periods" "${p[@]}" --periods two
expect_rejected preset "paper-4.1" --preset paper-9
expect_rejected "set = 'mu'" "valid range keys chi" "${p[@]}" --set mu=3
expect_rejected chi "missing" --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=0.3
expect_rejected point "valid RUN:LABEL" --point paper-5.1-omega-up
expect_rejected point "valid labels EP1" --point paper-5.1-omega-up:XX9 --results "${STICKSLIP_SOURCE:?}/results"
expect_rejected point "cannot read" --point no-such-run:EP1 --results "${STICKSLIP_SOURCE:?}/results"
expect_rejected point "at most one" --point paper-5.1-omega-up:TR2 --preset paper-5.1 --results "${STICKSLIP_SOURCE:?}/results"
expect_rejected point "without '/', '..'" --point ./b:EP1 --results "${STICKSLIP_SOURCE:?}/results"
expect_rejected point "not '.'" --point .:EP1 --results "${STICKSLIP_SOURCE:?}/results"

command=sweep
output_flag=--output
w=(--preset paper-4.1 --from 0.55 --to 0.6 --steps 2 --transients 1 --periods 1)
expect_rejected start "chained, fixed" "${w[@]}" --start both
expect_rejected chains "1 <= chains <= 10000" "${w[@]}" --chains 0
expect_rejected chains "1 <= chains <= 10000" "${w[@]}" --chains 2.5
expect_rejected scatter "0 <= scatter <= 1e6" "${w[@]}" --scatter -1
expect_rejected scatter "0 <= scatter <= 1e6" "${w[@]}" --scatter 1e7
expect_rejected seed "0 <= seed" "${w[@]}" --seed -3
expect_rejected threads "0 <= threads <= 1024" "${w[@]}" --threads -1
expect_rejected steps "1 <= steps" --preset paper-4.1 --from 0.55 --to 0.6 --steps 0
expect_rejected "from: omega = -0.1" "0.01 <= omega <= 100" --preset paper-4.1 --from -0.1 --to 0.6
expect_rejected "to: u_r = 0.05" "u_s = 0.1 <= u_r <= 1000" --preset paper-4.1 --parameter u_r --from 0.3 --to 0.05
expect_rejected parameter "chi, eta, omega" "${w[@]}" --parameter mu
expect_rejected "from = 'abc'" "valid range 0.01 <= chi <= 0.99" --preset paper-4.1 --parameter chi --from abc --to 0.3
expect_rejected point "run '../results' is invalid" --point ../results:EP1 --from 0.55 --to 0.6

# An unknown subcommand also exits 2 with one line.
"$bin" simulat > /dev/null 2> "$work/stderr"
code=$?
if [ "$code" -ne 2 ] || ! grep -q "simulat" "$work/stderr"; then
  echo "FAIL unknown command: exit $code, stderr: $(cat "$work/stderr")"
  failures=$((failures + 1))
fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
