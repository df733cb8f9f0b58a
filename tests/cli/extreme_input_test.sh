#!/usr/bin/env bash
# Extreme input on every numerical path of the command line (simulate exact and odeint, solve, a
# short continuation with its margins, a sweep): at each end of each valid range it ends within
# a time bound with exit 0, or with a numerical outcome (1: simulation incomplete, 3: no
# convergence) reported in one line; just outside, and at the values that once hung or exited 0
# with a wrong answer, it is bad input (exit 2, one line naming the field and the valid range).
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
limit=20  # seconds: generous, each case takes well under one

run() {  # run <args...>: sets code and seconds
  local start=$SECONDS
  timeout "$limit" "$bin" "$@" > "$work/stdout" 2> "$work/stderr"
  code=$?
  seconds=$((SECONDS - start))
}

report() {  # report <problem> <args...>
  local problem=$1
  shift
  if [ -n "$problem" ]; then
    echo "FAIL [$*]:$problem"
    sed 's/^/    stderr: /' "$work/stderr" | head -3
    failures=$((failures + 1))
  else
    echo "ok   [$*]: exit $code in ${seconds}s $(head -c 160 "$work/stderr")"
  fi
}

expect_ends() {  # expect_ends <allowed exit codes, e.g. "0 3"> <args...>
  local allowed=$1
  shift
  run "$@"
  local problem=""
  [ "$code" -ne 124 ] || problem+=" no end within ${limit}s;"
  [[ " $allowed " == *" $code "* ]] || problem+=" exit code $code (want one of $allowed);"
  [ "$code" -eq 0 ] || [ "$(wc -l < "$work/stderr")" -eq 1 ] || problem+=" not one stderr line;"
  ! grep -qi "nan" "$work/stdout" || problem+=" NaN in the output;"
  report "$problem" "$@"
}

expect_rejected() {  # expect_rejected <field> <valid range text> <args...>
  local field=$1 text=$2
  shift 2
  run "$@"
  local problem=""
  [ "$code" -eq 2 ] || problem+=" exit code $code (want 2);"
  [ "$(wc -l < "$work/stderr")" -eq 1 ] || problem+=" not one stderr line;"
  grep -q -- "$field = " "$work/stderr" || problem+=" message does not name '$field';"
  grep -q -- "$text" "$work/stderr" || problem+=" message lacks '$text';"
  report "$problem" "$@"
}

# The cases of the issue: each hung with no output, or exited 0 with a wrong answer.
p=(--preset paper-5.1)
c=(continue --preset paper-5.1 --parameter omega --range 0.01,100 --max-points 5 --results "$work" --output run)
expect_rejected omega "0.01 <= omega <= 100" simulate "${p[@]}" --set omega=1e-300
expect_rejected u_s "1e-06 <= u_s <= 1000" simulate "${p[@]}" --set u_s=1e308 --set u_r=1e308
expect_rejected u_r "u_r <= 1000" simulate "${p[@]}" --set u_r=1e308
expect_rejected x10 "|value| <= 1e+06" simulate "${p[@]}" --set x10=1e308
expect_rejected u_s "1e-06 <= u_s <= 1000" solve "${p[@]}" --set u_s=1e-16
expect_rejected d1 "the orbit's period" "${c[@]}" --guess d1=1e308
expect_rejected d1 "the orbit's period" "${c[@]}" --guess d1=1e7
expect_rejected x10 "|value| <= 1e+06" "${c[@]}" --set x10=1e308
[ ! -e "$work/run" ] || { echo "FAIL: a rejected continuation wrote results"; failures=$((failures + 1)); }

# Each end of each range, and just beyond it.
ends=(chi=0.01 chi=0.99 eta=0.01 eta=100 omega=0.01 omega=100 u_s=1e-06 "u_s=1000 --set u_r=1000" u_r=1000
      x10=1e6 x10=-1e6 x20=1e6 x20=-1e6 v10=1e6 v10=-1e6 v20=1e6 v20=-1e6 phi=1e6 phi=-1e6)
for end in "${ends[@]}"; do
  read -r -a set <<< "--set $end"
  expect_ends "0" simulate "${p[@]}" "${set[@]}" --method exact
  exact_events=$(grep "event(s)" "$work/stdout")
  # Odeint may not see a slip of microseconds (x1' = 1e6 drags x2 at once): it says so (exit 1).
  expect_ends "0 1" simulate "${p[@]}" "${set[@]}" --method odeint
  if [ "$code" -eq 0 ] && [ "$(grep "event(s)" "$work/stdout")" != "$exact_events" ]; then
    echo "FAIL [simulate --set $end]: exact '$exact_events', odeint '$(grep "event(s)" "$work/stdout")'"
    failures=$((failures + 1))
  fi
  orbit=("${set[@]}")
  case $end in
    v20=*) continue ;;  # an orbit starts at a stop: v20 is not an orbit variable
    omega=*)  # the preset's durations last longer than the period at omega = 100: a quarter each
      quarter=$(awk -v w="${end#omega=}" 'BEGIN { printf "%.17g", 2 * atan2(0, -1) / w / 4 }')
      for i in 1 2 3 4; do orbit+=(--guess "d$i=$quarter"); done
      ;;
  esac
  expect_ends "0 3" solve "${p[@]}" "${orbit[@]}"
  if [ "$code" -eq 0 ] && ! grep -q "^verification passed" "$work/stdout"; then
    echo "FAIL [solve --set $end]: converged, but the verification did not pass"
    failures=$((failures + 1))
  fi
  rm -rf "$work/run"
  expect_ends "0 3" "${c[@]}" "${orbit[@]}"
done
beyond=("chi|0.01 <= chi <= 0.99|0.0099" "chi|0.01 <= chi <= 0.99|0.9901" "eta|0.01 <= eta <= 100|0.0099"
        "eta|0.01 <= eta <= 100|100.01" "omega|0.01 <= omega <= 100|0.0099" "omega|0.01 <= omega <= 100|100.01"
        "u_s|1e-06 <= u_s <= 1000|9.9e-07" "u_r|u_r <= 1000|1000.1" "x10||value| <= 1e+06|1.000001e6"
        "x20||value| <= 1e+06|-1.000001e6" "v10||value| <= 1e+06|1e7" "v20||value| <= 1e+06|-1e7"
        "phi||value| <= 1e+06|1e300")
for case in "${beyond[@]}"; do
  field=${case%%|*}
  value=${case##*|}
  range=${case#"$field|"}
  range=${range%"|$value"}
  expect_rejected "$field" "$range" simulate "${p[@]}" --set "$field=$value"
done

# A sweep whose interior grid point (step 1 of 2, the midpoint) lies within rounding of the
# natural frequency omega1 of the 5.1 data (eq. 56).
read -r from to <<< "$(awk 'BEGIN { chi = 0.22; eta = 4.2; trace = 1 + chi * eta;
  root = sqrt((1 - chi * eta) ^ 2 + 4 * chi * chi * eta); w1 = sqrt(chi * eta * (1 - chi) / (0.5 * (trace + root)));
  printf "%.17g %.17g", w1 - 0.01, w1 + 0.01 }')"
expect_rejected steps "natural frequencies" sweep "${p[@]}" --from "$from" --to "$to" --steps 2 --transients 1 \
  --periods 1 --output "$work/sweep.csv"
[ ! -e "$work/sweep.csv" ] || { echo "FAIL: a rejected sweep wrote its output"; failures=$((failures + 1)); }

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all cases passed"
