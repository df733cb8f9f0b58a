#!/usr/bin/env bash
# export --auto writes the b., s. and d. files all or none (issue 22: on a full disk b. stayed
# without s.), and a write that fails names the user's path and the system's reason, not an
# internal temporary file. The failure is a real one from the kernel: a file size limit (ulimit
# -f, SIGXFSZ ignored, so write(2) fails with EFBIG) between the sizes of the two files, the same
# path through the writer as ENOSPC.
source "$(dirname "$0")/expect.sh"
# The run is $work/out itself (its name "out"), so that expect sees every file of it.
run=out
mkdir -p "$work/probe/$run" && cp "$root/results/paper-5.1-omega-up/"* "$work/probe/$run/"
"$bin" export --auto "$work/probe/$run" > /dev/null && pass || fail "export --auto"
b=$(stat -c %s "$work/probe/$run/b.$run") s=$(stat -c %s "$work/probe/$run/s.$run")
limit=$((b / 1024 + 1))  # KiB: room for b., not for s.
[ $((limit * 1024)) -lt "$s" ] && pass || fail "the test needs s. ($s bytes) larger than b. ($b bytes) by a KiB"

cp "$root/results/paper-5.1-omega-up/"* "$work/out/"
expect 1 "cannot write '$work/out/s.$run': File too large" \
  bash -c 'ulimit -f "$1"; trap "" XFSZ; exec "$2" export --auto "$3"' limited "$limit" "$bin" "$work/out"
[ ! -e "$work/out/b.$run" ] && [ ! -e "$work/out/s.$run" ] && [ ! -e "$work/out/d.$run" ] && pass ||
  fail "part of an export: $(ls "$work/out")"
grep -q "\.tmp\." "$work/stderr" && fail "the message names a temporary file: $(cat "$work/stderr")" || pass
finish
