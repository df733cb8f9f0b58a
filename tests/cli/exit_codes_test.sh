#!/usr/bin/env bash
# The exit-code table of tools/README.md, row by row, command by command: each code from the commands the
# table names, with the one-line reason on stderr where there is one. A trace that ran to its ends
# exits 0 whatever they were (issue 25); one whose start is not a motion is refused as solve
# refuses it (4, nothing written) unless it is allowed.
source "$(dirname "$0")/expect.sh"
r="$work/r"
# code <want> <what> <command...>: the command exits with <want>.
code() {
  local want=$1 what=$2
  shift 2
  "$@" > "$work/stdout" 2> "$work/stderr"
  local got=$?
  [ "$got" -eq "$want" ] && pass || fail "$what: exit $got, want $want: $(head -c 400 "$work/stderr")"
}

# ---- 0: success.
code 0 "solve an orbit that is a motion" "$bin" solve --preset paper-5.1
code 0 "--version" "$bin" --version
# Section 6 traced: both directions end at their first change of type, which switches nowhere
# (no-adjacent-type down, not-confirmed up): results, written and printed, exit 0.
p6=(--preset paper-6 --parameter omega --range 0.49,1.8 --ds 0.005 --ds-max 0.05 --results "$r")
code 0 "trace whose directions end at changes that switch nowhere" "$bin" trace "${p6[@]}" --output t6
grep -q "^  down: no-adjacent-type: " "$work/stdout" && grep -q "^  up: not-confirmed: " "$work/stdout" && pass ||
  fail "the trace's ends are not printed: $(cat "$work/stdout")"
[ ! -s "$work/stderr" ] && pass || fail "a trace that ran to its ends wrote on stderr: $(cat "$work/stderr")"
[ -s "$r/t6/trace.json" ] && pass || fail "t6/trace.json missing"
# The same trace from a run file, for `run`.
cat > "$work/t6.toml" <<'TOML'
output = "t6r"
[start]
preset = "paper-6"
[continuation]
parameter = "omega"
range = [0.49, 1.8]
ds = 0.005
ds_max = 0.05
[trace]
max_branches = 20
TOML
code 0 "run with a [trace] whose ends switch nowhere" "$bin" run --results "$r" "$work/t6.toml"

# ---- 1: failure (here: plot cannot start its interpreter).
code 1 "plot without python" env STICKSLIP_PYTHON=/nonexistent/python3 "$bin" plot paper-5.1-omega-up \
  --results "$root/results" --output "$work/p.png"
[ ! -e "$work/p.png" ] && pass || fail "plot failed but wrote its file"

# ---- 2: bad input, one line naming the field, nothing written.
expect 2 "max-branches = 0 is invalid" "$bin" trace --preset paper-6 --parameter omega --range 0.49,1.8 \
  --results "$work/out" --max-branches 0 --output bad
sed 's/^max_branches = 20/allow_inadmissible = 1/' "$work/t6.toml" > "$work/bad.toml"
expect 2 "trace.allow_inadmissible" "$bin" run --results "$work/out" "$work/bad.toml"
# The value is named with the type (the message said only "must be true or false").
sed 's/^max_branches = 20/allow_inadmissible = "yes"/' "$work/t6.toml" > "$work/bad.toml"
expect 2 "key 'trace.allow_inadmissible' = 'yes' is invalid: valid true or false (a boolean; its type is string)" \
  "$bin" run --results "$work/out" "$work/bad.toml"
sed 's/^max_branches = 20/allow_inadmissible = 1e300/' "$work/t6.toml" > "$work/bad.toml"
expect 2 "key 'trace.allow_inadmissible' = 1.0000000000000001e+300 is invalid: valid true or false" \
  "$bin" run --results "$work/out" "$work/bad.toml"

# ---- 3: no convergence (a start far from any orbit), nothing written.
cat > "$work/far.toml" <<'TOML'
output = "far"
[start]
preset = "paper-5.1"
[start.guess]
x10 = 40.0
d1 = 0.01
[continuation]
parameter = "omega"
direction = "up"
range = [0.5, 0.6]
TOML
expect 3 "does not converge" "$bin" run --results "$work/out" "$work/far.toml"
sed '/^direction = /d; s/^range = .*/&\n[trace]/' "$work/far.toml" > "$work/far-trace.toml"
expect 3 "did not start" "$bin" run --results "$work/out" "$work/far-trace.toml"
# A branch whose corrector fails before its end (steps of at least 1.9 in u_r from 1.4041): its
# points are written and the code is 3, for continue and run as for a trace's failed branch.
steps=(--preset paper-6 --parameter u_r --direction down --range 0.5,3 --ds 2 --ds-min 1.9 --ds-max 2 --results "$r")
code 3 "continue whose corrector failed" "$bin" continue "${steps[@]}" --output failed
grep -q '"termination": "step-too-small"' "$r/failed/summary.json" && pass || fail "the failed branch is not written"
printf '%s\n' 'output = "failed-run"' '[start]' 'preset = "paper-6"' '[continuation]' 'parameter = "u_r"' \
  'direction = "down"' 'range = [0.5, 3]' 'ds = 2' 'ds_min = 1.9' 'ds_max = 2' > "$work/failed.toml"
code 3 "run whose corrector failed" "$bin" run --results "$r" "$work/failed.toml"

# ---- 4: not a motion. Section 5.2's printed data solve to an orbit whose stick ends early
# (G:3 < 0): solve prints it and exits 4; a trace from it is refused the same way, with nothing
# written, unless asked to follow it.
code 4 "solve paper-5.2" "$bin" solve --preset paper-5.2
p52=(--preset paper-5.2 --parameter omega --range 0.3,0.68 --ds 0.005 --ds-max 0.05 --max-branches 1 --max-points 30)
expect 4 "the start is not a motion of the system: margin G:3 = -0.0072388 < 0 at omega = 0.66" \
  "$bin" trace "${p52[@]}" --results "$work/out" --output t52
cat > "$work/t52.toml" <<'TOML'
output = "t52r"
[start]
preset = "paper-5.2"
[continuation]
parameter = "omega"
range = [0.3, 0.68]
ds = 0.005
ds_max = 0.05
max_points = 30
[trace]
max_branches = 1
TOML
expect 4 "the start is not a motion of the system" "$bin" run --results "$work/out" "$work/t52.toml"
code 0 "trace paper-5.2 --allow-inadmissible" "$bin" trace "${p52[@]}" --results "$r" --output t52 --allow-inadmissible
[ -s "$r/t52/trace.json" ] && pass || fail "t52/trace.json missing"
sed 's/^max_branches = 1/&\nallow_inadmissible = true/' "$work/t52.toml" > "$work/t52-allowed.toml"
code 0 "run paper-5.2 trace with allow_inadmissible" "$bin" run --results "$r" "$work/t52-allowed.toml"
# A start on a type boundary (a restart from a change of type, a margin zero to rounding) is no
# refusal: section 4.1's trace restarted from its crossing-sliding.
cp -r "$root/results/paper-4.1-omega-trace" "$work/t41"
code 0 "trace from a change of type" "$bin" trace --results "$work/t41" --point branch-1:SK2 --parameter omega \
  --range 0.55,0.65 --ds 0.005 --ds-max 0.05 --max-branches 1 --max-points 10 --output from-sk2

# ---- 5: find: the motion is not periodic (a permanent stick has no orbit type).
code 5 "find at a permanent stick" "$bin" find --set chi=0.3 --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=10
# A flag takes no value: --allow-inadmissible=2 or =1e300 traced as if true and =-1 was refused
# with exit 4 as if false (CLI11's flag counts); now bad input naming the flag and the value.
for value in 2 1e300 -1 no maybe; do
  expect 2 "--allow-inadmissible = '$value' is invalid: valid no value" "$bin" trace "${p52[@]}" --results "$work/out" \
    --output t52 --allow-inadmissible="$value"
done
expect 2 "--tie-u_r = '5' is invalid: valid no value" "$bin" solve --preset paper-4.2 --tie-u_r=5

finish
