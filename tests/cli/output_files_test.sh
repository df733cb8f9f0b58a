#!/usr/bin/env bash
# No lost file: a run replaces only the directory of an earlier stickslip run, and keeps the other
# files in it; any other output path (a directory or file of the user's, a --results that cannot
# be a directory, an output file's path that is a directory or lies in no directory) is refused
# with exit 2 before anything is computed, and nothing is touched, byte for byte.
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
root=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
work=$(mktemp -d)
scratch=$(mktemp -d)
trap 'rm -rf "$work" "$scratch"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# The user's files beside the runs, as in results/.
results="$work/results"
mkdir -p "$results/sweeps" "$results/figures" "$results/mine"
cp -r "$root/results/paper-5.1-omega-up" "$results/paper-5.1-omega-up"
printf 'chain,pass\n0,up\n' > "$results/sweeps/paper-5.1-omega.csv"
printf '\x89PNG\r\n' > "$results/figures/paper-5.1-phase.png"
printf '# benchmark\n' > "$results/benchmark.md"
printf 'notes\n' > "$results/mine/notes.txt"
ln -s paper-5.1-omega-up "$results/link"
printf 'not a directory\n' > "$work/file"

# Every entry under $work with its type, link target and, for files, its bytes' checksum.
snapshot() {
  (cd "$work" && find . -printf '%y %p %l\n' | sort && find . -type f -print0 | sort -z | xargs -0 sha1sum)
}
before=$(snapshot)

# expect_refused <text on stderr> <stickslip arguments...>: exit 2, one line, nothing touched.
expect_refused() {
  local text=$1
  shift
  (cd "$work" && "$bin" "$@" > "$scratch/out" 2> "$scratch/err")
  local got=$?
  if [ "$got" -ne 2 ] || ! grep -qF -- "$text" "$scratch/err" || [ "$(wc -l < "$scratch/err")" -ne 1 ]; then
    fail "[$*]: exit $got (want 2, '$text'), stderr: $(cat "$scratch/err")"
  elif [ "$(snapshot)" != "$before" ]; then
    fail "[$*]: files changed: $(diff <(echo "$before") <(snapshot))"
  else
    echo "ok   [$*]: $(cat "$scratch/err")"
  fi
}

# A short continuation of section 5.1.
cont="continue --preset paper-5.1 --parameter omega --range 0.5,0.6 --max-points 3"

expect_refused "output = 'sweeps' is invalid: 'results/sweeps' holds no stickslip run" $cont --results results --output sweeps
expect_refused "output = 'figures' is invalid: 'results/figures' holds no stickslip run" $cont --results results --output figures
expect_refused "output = 'benchmark.md' is invalid: 'results/benchmark.md' is not a directory" $cont --results results --output benchmark.md
expect_refused "output = 'mine' is invalid: 'results/mine' holds no stickslip run" $cont --results results --output mine
expect_refused "output = 'link' is invalid: 'results/link' is a symbolic link" $cont --results results --output link
# The output is checked before the continuation: a start that does not converge (exit 3 with a
# good output) gives exit 2 here.
expect_refused "output = 'sweeps' is invalid" $cont --results results --output sweeps --guess d1=0.01 --guess x10=40 --guess phi=5

# run checks every run file's output before running any: the good first file writes nothing.
run_file() {  # run_file <path> <output>
  printf 'output = "%s"\n[start]\npreset = "paper-5.1"\n[continuation]\nparameter = "omega"\ndirection = "up"\nrange = [0.5, 0.6]\nmax_points = 3\n' \
    "$2" > "$1"
}
run_file "$scratch/good.toml" fresh
run_file "$scratch/sweeps.toml" sweeps
expect_refused "sweeps.toml:1:10: key 'output' = 'sweeps' is invalid: 'results/sweeps' holds no stickslip run" \
  run --results results "$scratch/good.toml" "$scratch/sweeps.toml"

# --results: a file, a path under a file, a name too long for the file system.
expect_refused "results = 'file' is invalid: it is not a directory" $cont --results file --output t
expect_refused "results = 'file/sub' is invalid: it cannot be created" run --results file/sub "$scratch/good.toml"
long=$(printf 'x%.0s' {1..300})
expect_refused "results = 'new/$long' is invalid: it cannot be created (File name too long)" \
  $cont --results "new/$long" --output t

# check reads the stored run before computing: a missing one is exit 2, not the start's exit 3.
printf 'output = "absent"\n[start]\npreset = "paper-5.1"\nguess = { d1 = 0.01, x10 = 40, phi = 5 }\n[continuation]\nparameter = "omega"\ndirection = "up"\nrange = [0.3, 0.9]\n' \
  > "$scratch/absent.toml"
expect_refused "cannot read 'results/absent/branch.csv'" check --results results "$scratch/absent.toml"

# Output files: a directory, or a path in a directory that does not exist.
sweep="sweep --preset paper-5.1 --from 0.55 --to 0.56 --steps 1 --transients 1 --periods 1"
expect_refused "output = 'results/sweeps' is invalid: it is a directory" $sweep --output results/sweeps
expect_refused "output = 'missing/x.csv' is invalid: directory 'missing' does not exist" $sweep --output missing/x.csv
expect_refused "output = '$long' is invalid: it cannot be examined (File name too long)" $sweep --output "$long"
expect_refused "csv = 'results/figures' is invalid: it is a directory" simulate --preset paper-5.1 --csv results/figures
expect_refused "csv = 'missing/x.csv' is invalid: directory 'missing' does not exist" \
  simulate --preset paper-5.1 --csv missing/x.csv
mkdir "$results/paper-5.1-omega-up/b.paper-5.1-omega-up"
before=$(snapshot)
expect_refused "b.paper-5.1-omega-up = 'results/paper-5.1-omega-up/b.paper-5.1-omega-up' is invalid: it is a directory" \
  export --auto results/paper-5.1-omega-up
rmdir "$results/paper-5.1-omega-up/b.paper-5.1-omega-up"

# A directory where no file can be created (as root, permissions do not tell: /proc).
before=$(snapshot)
if [ -d /proc/self ]; then
  expect_refused "results = '/proc' is invalid: no file can be created in it" $cont --results /proc --output t
  expect_refused "csv = '/proc/x.csv' is invalid: no file can be created in directory '/proc'" \
    simulate --preset paper-5.1 --csv /proc/x.csv
fi

# An output file that is a symbolic link: its target is written, the link stays a link. The target
# is an earlier CSV of simulate's (its header on line 1): only such a file is replaced.
printf 't,x1,x2,v1,v2,mode\nold\n' > "$scratch/target.csv"
ln -s "$scratch/target.csv" "$scratch/link.csv"
"$bin" simulate --preset paper-5.1 --periods 1 --csv "$scratch/link.csv" > /dev/null || fail "simulate into a link: exit $?"
[ -L "$scratch/link.csv" ] || fail "the link to the output file was replaced"
head -1 "$scratch/target.csv" | grep -q "^t,x1,x2,v1,v2,mode$" || fail "the link's target was not written"
grep -q "^old$" "$scratch/target.csv" && fail "the link's target was not replaced"
echo "ok   a symbolic link as output file: target written, link kept"

# Re-running a run replaces its three files and keeps every other file in its directory.
(cd "$work" && "$bin" $cont --results results --output again > "$scratch/out") || fail "first run exit $?"
grep -q "kept" "$scratch/out" && fail "a first run reports kept files: $(cat "$scratch/out")"
printf 'b file\n' > "$results/again/b.again"
mkdir "$results/again/notes"
printf 'a note\n' > "$results/again/notes/a.txt"
cp "$results/again/branch.csv" "$scratch/first.csv"
(cd "$work" && "$bin" $cont --ds 0.02 --results results --output again > "$scratch/out") || fail "re-run exit $?"
[ "$(cat "$results/again/b.again")" = "b file" ] || fail "b.again lost or changed"
[ "$(cat "$results/again/notes/a.txt")" = "a note" ] || fail "notes/a.txt lost or changed"
grep -qF "again: kept 2 other file(s) of results/again: b.again, notes" "$scratch/out" ||
  fail "kept files not reported: $(cat "$scratch/out")"
cmp -s "$scratch/first.csv" "$results/again/branch.csv" && fail "the re-run's branch.csv was not written"
[ -z "$(find "$results" -maxdepth 1 -name '.again.*')" ] || fail "temporary directories left: $(ls -a "$results")"
echo "ok   re-run kept b.again and notes/"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
