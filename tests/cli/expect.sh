# Shared by the command-line test scripts (sourced): the program and source tree from the
# environment, a scratch directory $work with an output directory $work/out, pass/fail counters,
# and `expect CODE TEXT COMMAND...`: the command exits with CODE, prints one line on stderr that
# holds TEXT, and leaves what $work/out holds as it was (no file created, changed or removed; a
# probe file created and removed again, as CheckOutputFile does, changes only the directory's
# mtime). `finish` prints "N passed, M failed" and fails the script on any failure.
set -uo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
root=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/out"
failures=0 passes=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passes=$((passes + 1)); }

listing() { (cd "$work/out" && find . -mindepth 1 | sort | xargs -r stat -c '%n %s %Y.%y') }

expect() {
  local code=$1 text=$2
  shift 2
  local before after got
  before=$(listing)
  "$@" > "$work/stdout" 2> "$work/stderr"
  got=$?
  after=$(listing)
  if [ "$got" -ne "$code" ]; then fail "[$*] exit $got, want $code: $(cat "$work/stderr")"; return; fi
  if [ "$(wc -l < "$work/stderr")" -ne 1 ]; then fail "[$*] stderr is not one line: $(cat "$work/stderr")"; return; fi
  if ! grep -qF -- "$text" "$work/stderr"; then fail "[$*] stderr lacks '$text': $(cat "$work/stderr")"; return; fi
  if [ "$before" != "$after" ]; then fail "[$*] changed $work/out"; return; fi
  pass
}

finish() {
  echo "$passes passed, $failures failed"
  [ "$failures" -eq 0 ]
}
