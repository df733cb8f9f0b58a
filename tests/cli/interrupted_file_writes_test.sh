#!/usr/bin/env bash
# A signal while a single result file is written (sweep --output x.csv; SIGTERM, SIGHUP, SIGINT):
# the process ends by that signal, its temporary file is gone and the earlier file is intact. A
# later write of the file removes a temporary file only where it proves it its own kind and dead
# (this host, this boot, the process gone), and lists each one it removed or left, one line each on
# stderr (before: a killed writer's ".x.csv.tmp.<tag>.<pid>" stayed for good, unlisted). The writer
# is stopped at a known point (STICKSLIP_TEST_PAUSE_BEFORE_RENAME, test-only), not signalled at a
# guessed time; interrupted_writes_test.sh does the same for a trace's directory.
source "$(dirname "$0")/expect.sh"
source "$(dirname "$0")/paused_writer.sh"
r="$work/r"
mkdir -p "$r"
args=(sweep --preset paper-5.1 --from 0.55 --to 0.56 --steps 1 --transients 0 --periods 2 --threads 1 --output "$r/x.csv")
"$bin" "${args[@]}" > /dev/null 2>&1 && pass || fail "first sweep"
cp "$r/x.csv" "$work/before.csv"

temporaries() { (cd "$r" && ls -A | grep '^\.x\.csv\.tmp\.') }

for signal in TERM HUP INT; do
  start_paused --force || continue
  [ -n "$(temporaries)" ] && pass || fail "SIG$signal: no temporary file while paused"
  signal_paused $signal
  [ "$(ls -A "$r")" = x.csv ] && pass || fail "SIG$signal: left $(ls -A "$r")"
  cmp -s "$work/before.csv" "$r/x.csv" && pass || fail "SIG$signal: the earlier file changed"
done

# SIGKILL cannot be caught: the writer's temporary file stays, named with this host's tag and its pid.
start_paused --force && kill -s KILL $writer
wait $writer 2> /dev/null
dead=$(temporaries)
if [[ "$dead" =~ ^\.x\.csv\.tmp\.([0-9a-f]{16})\.([0-9]+)$ ]]; then pass; else fail "SIGKILL left '$dead'"; fi
tag=${BASH_REMATCH[1]:-none} dead_pid=${BASH_REMATCH[2]:-0}
# Beside it: a temporary file of a running process (this shell); one of another host or an earlier
# boot; one an earlier version named without its host; a directory of a dead writer's name (a
# directory's temporary is not a file's: the directory writers clean those); files of the user's
# whose names come near.
(exit 0) &
other_dead=$!
wait $other_dead
for mine in ".x.csv.tmp.$tag.$$" ".x.csv.tmp.0123456789abcdef.$dead_pid" ".x.csv.tmp.99999" ".x.csv.notes" \
            ".x.csv.tmp.$tag.${dead_pid}x" ".y.csv.tmp.$tag.$dead_pid"; do
  echo mine > "$r/$mine"
done
mkdir "$r/.x.csv.tmp.$tag.$other_dead"
"$bin" "${args[@]}" --force > /dev/null 2> "$work/stale.err" && pass || fail "sweep beside stale temporaries: $(cat "$work/stale.err")"
[ ! -e "$r/$dead" ] && pass || fail "the dead writer's temporary file stays"
for kept in ".x.csv.tmp.$tag.$$" ".x.csv.tmp.0123456789abcdef.$dead_pid" ".x.csv.tmp.99999" ".x.csv.notes" \
            ".x.csv.tmp.$tag.${dead_pid}x" ".y.csv.tmp.$tag.$dead_pid" ".x.csv.tmp.$tag.$other_dead"; do
  [ -e "$r/$kept" ] && pass || fail "$kept was removed"
done
cmp -s "$work/before.csv" "$r/x.csv" && pass || fail "the file written beside them differs"
expect_notes "$work/stale.err" \
  "note: removed '$r/$dead': a temporary of process $dead_pid on this host, which has ended" \
  "note: left '$r/.x.csv.tmp.$tag.$$': its process $$ is running" \
  "note: left '$r/.x.csv.tmp.0123456789abcdef.$dead_pid': written on another host or before this host's last boot" \
  "note: left '$r/.x.csv.tmp.99999': its name does not say its host (an earlier version of stickslip wrote it)"
finish
