# Shared by the signal tests (sourced after expect.sh): a writer run with "${args[@]}" and stopped at
# the test-only pause just before its temporary moves into place (STICKSLIP_TEST_PAUSE_BEFORE_RENAME),
# so that signals are sent there rather than timed.

# Starts "$bin" "${args[@]}" "$@" in the background, paused; $writer is its pid. SIGINT at its
# default (bash ignores it in a background job).
start_paused() {
  rm -f "$work/paused"
  STICKSLIP_TEST_PAUSE_BEFORE_RENAME="$work/paused" /usr/bin/python3 -c \
    'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
    "$bin" "${args[@]}" "$@" > /dev/null 2> "$work/paused.err" &
  writer=$!
  for _ in $(seq 600); do [ -e "$work/paused" ] && return 0; sleep 0.1; done
  fail "the writer did not reach its pause: $(cat "$work/paused.err")"
  return 1
}

# Sends the signal to the paused writer: it must end by it (exit status 128 + signal).
signal_paused() {  # signal_paused SIGNAL
  kill -s "$1" "$writer"
  wait "$writer" 2> /dev/null
  local code=$? want=$((128 + $(kill -l "$1")))
  [ $code -eq $want ] && pass || fail "SIG$1: exit $code, want $want: $(cat "$work/paused.err")"
}

# The notes a later run printed on stderr about the temporaries it found: exactly these lines.
expect_notes() {  # expect_notes STDERR-FILE LINE...
  local file=$1 line
  shift
  for line in "$@"; do
    grep -qxF "$line" "$file" && pass || fail "stderr lacks [$line]: $(cat "$file")"
  done
  [ "$(wc -l < "$file")" -eq $# ] && pass || fail "not one line per temporary: $(cat "$file")"
}
