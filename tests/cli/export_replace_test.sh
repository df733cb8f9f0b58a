#!/usr/bin/env bash
# export --auto replaces an existing b., s. or d. file only with --force (AUTO's formats have no
# room for a mark of who wrote them: it may be the user's), and never writes through a link at
# those names, whose target lies outside the run (before: a user's d.<run> was replaced, and a
# link's target outside the run was written). An empty directory is bad input (before: exit 1
# with a filesystem message), and so is a directory that holds no run: the message says what export
# reads (before: "cannot read '<dir>/branch.csv'", not what a valid input is).
source "$(dirname "$0")/expect.sh"
run=out
cp "$root/results/paper-5.1-omega-up/"* "$work/out/"
echo mine > "$work/out/d.$run"
expect 2 "'$work/out/d.$run' exists: an export replaces it only with --force" "$bin" export --auto "$work/out"
rm "$work/out/d.$run"
echo precious > "$work/precious"
ln -s ../precious "$work/out/s.$run"
expect 2 "'$work/out/s.$run' is a link: the export writes only into the run's directory" \
  "$bin" export --auto "$work/out" --force
[ "$(cat "$work/precious")" = precious ] && pass || fail "the link's target was written"
rm "$work/out/s.$run"
"$bin" export --auto "$work/out" > /dev/null && pass || fail "export into a run without an export"
expect 2 "exists: an export replaces it only with --force" "$bin" export --auto "$work/out"
cp "$work/out/b.$run" "$work/b.first"
"$bin" export --auto "$work/out" --force > /dev/null && cmp -s "$work/out/b.$run" "$work/b.first" && pass ||
  fail "export --force over its own earlier export"
expect 2 "directory = '' is invalid: it is empty" "$bin" export --auto ""
mkdir "$work/not-a-run" "$work/trace"
echo '{}' > "$work/trace/trace.json"
valid="valid a run's directory (results/<run>/, holding branch.csv, special-points.csv and summary.json), or one branch-<k>/"
expect 2 "directory = '$work/not-a-run' is invalid: it holds no branch.csv: $valid" "$bin" export --auto "$work/not-a-run"
expect 2 "directory = '$work/trace' is invalid: it is a trace's directory (its runs are its branch-<k>/): $valid" \
  "$bin" export --auto "$work/trace"
expect 2 "directory = '$work/absent' is invalid: it does not exist: $valid" "$bin" export --auto "$work/absent"
[ -z "$(ls "$work/not-a-run")" ] && pass || fail "export wrote into a directory that holds no run"
finish
