#!/usr/bin/env bash
# A signal while a trace is written (SIGTERM, SIGHUP, SIGINT): the process ends by that signal, its
# temporary directory is gone and the earlier trace is intact. A later run removes a temporary only
# where it proves it its own kind and dead (this host, this boot, the process gone), keeps the
# user's files in it, and lists each temporary it removed or left, one line each on stderr. The
# writer is stopped at a known point (STICKSLIP_TEST_PAUSE_BEFORE_RENAME, test-only), not signalled
# at a guessed time.
source "$(dirname "$0")/expect.sh"
source "$(dirname "$0")/paused_writer.sh"
r="$work/r"
args=(trace --preset paper-4.1 --parameter omega --range 0.55,0.65 --results "$r" --output tr)
"$bin" "${args[@]}" > /dev/null 2>&1 && pass || fail "first trace"
cp -a "$r/tr" "$work/before"

temporaries() { (cd "$r" && ls -A | grep '^\.tr\.tmp\.') }

for signal in TERM HUP INT; do
  start_paused || continue
  [ -n "$(temporaries)" ] && pass || fail "SIG$signal: no temporary while paused"
  signal_paused $signal
  [ -z "$(ls -A "$r" | grep -v '^tr$')" ] && pass || fail "SIG$signal: left $(ls -A "$r")"
  diff -r "$work/before" "$r/tr" > /dev/null && pass || fail "SIG$signal: the earlier trace changed"
done

# SIGKILL cannot be caught: the writer's temporary stays, named with this host's tag and its pid.
start_paused && kill -s KILL $writer
wait $writer 2> /dev/null
dead=$(temporaries)
if [[ "$dead" =~ ^\.tr\.tmp\.([0-9a-f]{16})\.([0-9]+)$ ]]; then pass; else fail "SIGKILL left '$dead'"; fi
tag=${BASH_REMATCH[1]:-none} dead_pid=${BASH_REMATCH[2]:-0}
# Beside it: a dead writer's temporary holding a file of the user's (moved in before it ended) as
# well as its own; one of a running process (this shell); one of another host or an earlier boot;
# one an earlier version named without its host; a file of the user's.
(exit 0) &
other_dead=$!
wait $other_dead
mkdir -p "$r/.tr.tmp.$tag.$other_dead/branch-1" "$r/.tr.tmp.$tag.$$" "$r/.tr.tmp.0123456789abcdef.$dead_pid" "$r/.tr.tmp.99999" \
  "$r/.tr.tmp.$tag.4294967296"
echo mine > "$r/.tr.tmp.$tag.$other_dead/NOTES.md"
cp "$r/tr/branch-1/branch.csv" "$r/.tr.tmp.$tag.$other_dead/branch-1/"
echo mine > "$r/.tr.tmp.$tag.$$/notes.txt"
echo mine > "$r/.tr.notes"
"$bin" "${args[@]}" > /dev/null 2> "$work/stale.err" && pass || fail "trace beside stale temporaries: $(cat "$work/stale.err")"
[ ! -e "$r/$dead" ] && pass || fail "the dead writer's temporary stays"
[ ! -e "$r/.tr.tmp.$tag.$other_dead/branch-1" ] && pass || fail "the dead writer's own files in a temporary stay"
for kept in ".tr.tmp.$tag.$other_dead/NOTES.md" ".tr.tmp.$tag.$$/notes.txt" ".tr.tmp.0123456789abcdef.$dead_pid" \
            ".tr.tmp.99999" ".tr.tmp.$tag.4294967296" ".tr.notes"; do
  [ -e "$r/$kept" ] && pass || fail "$kept was removed"
done
diff -r "$work/before" "$r/tr" > /dev/null && pass || fail "the trace written beside them differs"
expect_notes "$work/stale.err" \
  "note: removed '$r/$dead': a temporary of process $dead_pid on this host, which has ended" \
  "note: left '$r/.tr.tmp.$tag.$other_dead': its process $other_dead has ended, but it holds files stickslip did not write" \
  "note: left '$r/.tr.tmp.$tag.$$': its process $$ is running" \
  "note: left '$r/.tr.tmp.0123456789abcdef.$dead_pid': written on another host or before this host's last boot" \
  "note: left '$r/.tr.tmp.99999': its name does not say its host (an earlier version of stickslip wrote it)" \
  "note: left '$r/.tr.tmp.$tag.4294967296': 4294967296 is no process id of this system: no stickslip process wrote it"
finish
