#!/usr/bin/env bash
# stickslip find: a new user's period-4 motion found and verified (exit 0), the solve command line
# it prints gives the same orbit, the run file it writes is one `stickslip run` takes; exit 5 for
# a motion that is not periodic within --max-multiple or has no orbit type; and a table of bad
# input: exit 2, one line naming the option and its range, no file created or changed.
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

data=(--set chi=0.5 --set eta=2 --set u_s=0.1 --set u_r=0.3 --set omega=0.27 --set x10=1)
"$bin" find "${data[@]}" --write-run "$work/p4.toml" > "$work/p4.txt" 2> "$work/p4.err"
code=$?
[ "$code" -eq 0 ] || fail "period-4 case: exit $code (want 0): $(cat "$work/p4.err")"
grep -q "k = 4 forcing period(s)" "$work/p4.txt" || fail "period-4 case: no 'k = 4' in the output"
grep -q "^signature  slip- stick slip+ stick slip- stick slip+ stick slip- stick slip+ stick slip- stick slip+ stick / period 4$" \
  "$work/p4.txt" || fail "period-4 case: not slip- stick slip+ stick x4 / period 4"
grep -q "^verification passed" "$work/p4.txt" || fail "period-4 case: verification did not pass"

# The printed solve command gives the same solution line.
command=$(grep "^  stickslip solve " "$work/p4.txt" | sed 's/^  stickslip //')
eval "\"\$bin\" $command" > "$work/solve.txt" 2>&1 || fail "the printed solve command exits $?"
[ "$(grep '^solution' "$work/solve.txt")" = "$(grep '^solution' "$work/p4.txt")" ] ||
  fail "the printed solve command gives another solution: $(grep '^solution' "$work/solve.txt")"

# The run file is one stickslip run accepts.
"$bin" run --results "$work/results" "$work/p4.toml" > "$work/run.txt" 2>&1 ||
  fail "stickslip run on the written run file exits $?: $(cat "$work/run.txt")"
[ -f "$work/results/p4/branch.csv" ] || fail "the run of the written run file left no branch.csv"

# Not periodic within --max-multiple 2 (the motion repeats after 4): exit 5, one line, no run file.
"$bin" find "${data[@]}" --max-multiple 2 --write-run "$work/none.toml" > /dev/null 2> "$work/np.err"
code=$?
[ "$code" -eq 5 ] || fail "max-multiple 2: exit $code (want 5)"
[ "$(wc -l < "$work/np.err")" -eq 1 ] && grep -q "not periodic with k <= 2" "$work/np.err" ||
  fail "max-multiple 2: message $(cat "$work/np.err")"
[ ! -e "$work/none.toml" ] || fail "max-multiple 2 wrote a run file"

# A permanent stick (at rest, u_r far above the forcing) has no orbit type: exit 5.
"$bin" find --set chi=0.3 --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=10 > /dev/null 2> "$work/stick.err"
code=$?
[ "$code" -eq 5 ] && grep -q "permanent stick" "$work/stick.err" || fail "permanent stick: exit $code, $(cat "$work/stick.err")"

expect_rejected() {  # expect_rejected <field> <expected text> <args...>
  local field=$1 text=$2
  shift 2
  local out="$work/out.toml"
  printf 'keep\n' > "$work/existing.toml"
  "$bin" find "$@" --write-run "$out" > "$work/stdout" 2> "$work/stderr"
  local code=$?
  local problem=""
  [ "$code" -eq 2 ] || problem+=" exit code $code (want 2);"
  [ "$(wc -l < "$work/stderr")" -eq 1 ] || problem+=" $(wc -l < "$work/stderr") stderr lines (want 1);"
  grep -q -- "$field" "$work/stderr" || problem+=" message does not name '$field';"
  grep -q -- "$text" "$work/stderr" || problem+=" message lacks '$text';"
  [ ! -e "$out" ] || problem+=" output file was created;"
  "$bin" find "$@" --write-run "$work/existing.toml" > /dev/null 2>&1
  [ "$(cat "$work/existing.toml")" = "keep" ] || problem+=" existing file was changed;"
  if [ -n "$problem" ]; then
    fail "[find $*]:$problem"
    sed 's/^/    stderr: /' "$work/stderr"
  else
    echo "ok   [find $*]: $(cat "$work/stderr")"
  fi
}

p=(--preset paper-4.1)
expect_rejected transients "0 <= transients <= 1000000" "${p[@]}" --transients -1
expect_rejected transients "0 <= transients <= 1000000" "${p[@]}" --transients 2000000
expect_rejected transients "0 <= transients <= 1000000" "${p[@]}" --transients 2.5
expect_rejected transients "finite number" "${p[@]}" --transients many
expect_rejected transients "finite number" "${p[@]}" --transients 1e999
expect_rejected max-multiple "1 <= max-multiple <= 999" "${p[@]}" --max-multiple 0
expect_rejected max-multiple "1 <= max-multiple <= 999" "${p[@]}" --max-multiple 1000
expect_rejected max-multiple "finite number" "${p[@]}" --max-multiple nan
expect_rejected tolerance "1e-12 <= tolerance <= 0.01" "${p[@]}" --tolerance 0
expect_rejected tolerance "1e-12 <= tolerance <= 0.01" "${p[@]}" --tolerance 0.5
expect_rejected tolerance "finite number" "${p[@]}" --tolerance -inf
expect_rejected confirmations "1 <= confirmations <= 100" "${p[@]}" --confirmations 0
expect_rejected omega "0.01 <= omega <= 100" "${p[@]}" --set omega=0
expect_rejected omega "finite number" "${p[@]}" --set omega=1e-300x
expect_rejected x10 "1e+06" "${p[@]}" --set x10=1e308
expect_rejected u_r "u_r" "${p[@]}" --set u_r=1e308
expect_rejected preset "paper-4.1" --preset paper-9
expect_rejected chi "missing" --set eta=4 --set omega=0.6 --set u_s=0.1 --set u_r=0.3

# An output path that cannot be written: exit 2 naming --write-run, before the work.
"$bin" find "${p[@]}" --write-run "$work" > /dev/null 2> "$work/dir.err"
code=$?
[ "$code" -eq 2 ] && grep -q "write-run" "$work/dir.err" || fail "--write-run a directory: exit $code, $(cat "$work/dir.err")"
"$bin" find "${p[@]}" --write-run "$work/no/such/dir/x.toml" > /dev/null 2> "$work/nodir.err"
code=$?
[ "$code" -eq 2 ] && grep -q "write-run" "$work/nodir.err" || fail "--write-run in a missing directory: exit $code"
[ ! -e "$work/no" ] || fail "--write-run in a missing directory created it"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "find: all cases ok"
