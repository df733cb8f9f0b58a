#!/usr/bin/env bash
# The runs of one `run` command go sources first: a run that restarts from another run of the same
# command runs after it, whatever order the files are given in, and so starts from what this command
# writes, not from a source's earlier results. Runs that restart from each other in a cycle are
# refused (exit 2, nothing written); a run whose source this command failed to write is not run
# (exit 3).
source "$(dirname "$0")/expect.sh"
o="$work/out"
# write_run FILE OUTPUT START_LINES: a short continuation in omega up, from 0.6 (§4.1's orbit).
write_run() {
  printf 'output = "%s"\n[start]\n%s\n[continuation]\nparameter = "omega"\ndirection = "up"\nrange = [0.6, 0.7]\nmax_points = 3\n' \
    "$2" "$3" > "$work/$1.toml"
}
# omega of the first point of RESULTS_DIR/branch.csv.
first_omega() { awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "omega") c = i } NR == 2 { print $c }' "$1/branch.csv"; }

write_run a-restarts b 'restart = { run = "z-source", label = "EP1" }'
write_run z-source z-source 'preset = "paper-4.1"'
# The source's earlier results start at omega = 0.65; this command's at 0.6.
write_run z-source-earlier z-source $'preset = "paper-4.1"\n[start.set]\nomega = 0.65'
"$bin" run --results "$o" "$work/z-source-earlier.toml" > /dev/null || fail "the earlier source run"
"$bin" run --results "$o" "$work/a-restarts.toml" "$work/z-source.toml" > "$work/stdout" 2> "$work/stderr" \
  && pass || fail "a restart given before its source: $(cat "$work/stderr")"
[ "$(head -1 "$work/stdout" | cut -d: -f1)" = z-source ] && pass || fail "the source runs first: $(cat "$work/stdout")"
[ "$(first_omega "$o/b")" = 0.6 ] && pass || fail "the restart starts at its source's fresh EP1: omega = $(first_omega "$o/b")"

# A cycle: nothing runs.
write_run c1 c1 'restart = { run = "c2", label = "EP1" }'
write_run c2 c2 'restart = { run = "c1", label = "EP1" }'
expect 2 "c2.toml:3:19: key 'start.restart.run' = 'c1' is invalid: valid a run that does not restart" \
  "$bin" run --results "$o" "$work/c2.toml" "$work/c1.toml"
expect 2 "key 'start.restart.run' = 'c2' is invalid" "$bin" run --results "$o" "$work/c1.toml" "$work/c2.toml" "$work/z-source.toml"
# The run named is one on the cycle, not one that restarts from it, and the cycle is spelled out.
write_run c3 c3 'restart = { run = "c1", label = "EP1" }'
write_run d d 'restart = { run = "c3", label = "EP1" }'
expect 2 "c1.toml:3:19: key 'start.restart.run' = 'c2' is invalid: valid a run that does not restart from this one \
through the command's other run files (c1 restarts from c2, which restarts from c1)" \
  "$bin" run --results "$o" "$work/d.toml" "$work/c2.toml" "$work/c1.toml" "$work/c3.toml"

# A trace's output holds no label of its own: a restart from a trace of the command is refused
# before the trace runs.
printf 'output = "tr"\n[start]\npreset = "paper-4.1"\n[continuation]\nparameter = "omega"\nrange = [0.6, 0.7]\nmax_points = 3\n[trace]\n' \
  > "$work/tr.toml"
write_run after-tr after-tr 'restart = { run = "tr", label = "EP1" }'
expect 2 "key 'start.restart.run' = 'tr' is invalid: valid a run that is no trace" \
  "$bin" run --results "$o" "$work/after-tr.toml" "$work/tr.toml"

# A run whose input the setup refuses (a label its source does not have) fails the command before
# any run is computed: the good run given first is not written either.
write_run good good 'preset = "paper-4.1"'
write_run no-label no-label 'restart = { run = "z-source", label = "LP99" }'
expect 2 "no-label.toml:3:11: key 'start.restart' = 'z-source:LP99' cannot be used" \
  "$bin" run --results "$o" "$work/good.toml" "$work/no-label.toml"

# A source that does not converge: its dependant is not run, and neither writes.
write_run far far $'preset = "paper-4.1"\n[start.guess]\nx10 = 40.0\nd1 = 0.01'
write_run after-far after-far 'restart = { run = "far", label = "EP1" }'
before=$(listing)
"$bin" run --results "$o" "$work/after-far.toml" "$work/far.toml" > /dev/null 2> "$work/stderr"
[ $? -eq 3 ] && pass || fail "a failed source: exit code"
grep -qF "after-far.toml: not run: it restarts from 'far', which this command did not write" "$work/stderr" && pass \
  || fail "a failed source: $(cat "$work/stderr")"
[ "$before" = "$(listing)" ] && pass || fail "a failed source: $o changed"
finish
