#!/usr/bin/env bash
# Every command that reads stored results (export --auto, check, a restart from a labelled point
# by run file or by --point) meets a damaged results/<run>/ with exit code 2 and one line on
# stderr naming the file, the line and the column, not a crash. A short row of branch.csv used to
# crash export --auto (SIGSEGV).
set -u
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
root=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
run=paper-5.1-omega-up

# damage <file> <python statement on `lines`, the file's lines without their newlines>:
# a fresh copy of the stored results with one file of the run edited.
damage() {
  rm -rf "$work/results" && cp -r "$root/results" "$work/results"
  /usr/bin/python3 - "$work/results/$run/$1" "$2" <<'PY'
import sys
path, statement = sys.argv[1:]
lines = open(path).read().splitlines()
exec(statement)
open(path, "w").write("\n".join(lines) + "\n")
PY
}

expect_rejected() {  # expect_rejected <expected text> <args...>
  local text=$1
  shift
  (cd "$work" && "$bin" "$@") > /dev/null 2> "$work/stderr"
  local code=$?
  if [ "$code" -eq 2 ] && [ "$(wc -l < "$work/stderr")" -eq 1 ] && grep -qF -- "$text" "$work/stderr"; then
    echo "ok   [$*]: $(cat "$work/stderr")"
  else
    echo "FAIL [$*]: exit code $code; want 2 and one stderr line with '$text'"
    sed 's/^/    stderr: /' "$work/stderr"
    failures=$((failures + 1))
  fi
}

restart_file="$work/restart.toml"
sed "s|^output = .*|output = \"restart-check\"|" "$root/continuation-scripts/paper-5.1-u_r-from-uz.toml" > "$restart_file"

# A row one field short (the last one cut off).
damage branch.csv 'lines[5] = lines[5].rsplit(",", 1)[0]'
expect_rejected "results/$run/branch.csv:6: the row has 55 fields, the header 56" export --auto "results/$run"
expect_rejected "results/$run/branch.csv:6: the row has 55 fields" check --results results "$root/continuation-scripts/$run.toml"

# A column missing from special-points.csv (from the header and every row).
damage special-points.csv 'k = lines[0].split(",").index("x10"); lines[:] = [",".join(f for i, f in enumerate(l.split(",")) if i != k) for l in lines]'
expect_rejected "results/$run/special-points.csv:1: column 'x10' is missing" simulate --point "$run:UZ5" --results results --periods 1
expect_rejected "results/$run/special-points.csv:1: column 'x10' is missing" run --results results "$restart_file"

# A field that is not a number.
damage special-points.csv 'f = lines[5].split(","); f[4] = "0.58.1"; lines[5] = ",".join(f)'
expect_rejected "results/$run/special-points.csv:6: column 'omega' = '0.58.1' is not a number" export --auto "results/$run"
expect_rejected "key 'start.restart' = '$run:UZ5' cannot be used: results/$run/special-points.csv:6: column 'omega'" run --results results "$restart_file"

# A non-finite orbit variable (an orbit is never stored with one): export and plot used to pass
# it on with exit 0 (found by the hostile-input pass); a restart refused it already.
damage branch.csv 'f = lines[2].split(","); f[4] = "nan"; lines[2] = ",".join(f)'
expect_rejected "results/$run/branch.csv:3: column 'omega' = 'nan' is not a finite number" export --auto "results/$run"
damage special-points.csv 'f = lines[1].split(","); f[8] = "inf"; lines[1] = ",".join(f)'
expect_rejected "results/$run/special-points.csv:2: column 'x10' = 'inf' is not a finite number" export --auto "results/$run"
expect_rejected "results/$run/special-points.csv:2: column 'x10' = 'inf' is not a finite number" simulate --point "$run:EP1" --results results --periods 1

# A key missing from summary.json.
damage summary.json 'lines[:] = [l for l in lines if "\"parameter\"" not in l]'
expect_rejected "results/$run/summary.json: key 'parameter' is missing" export --auto "results/$run"
expect_rejected "results/$run/summary.json: key 'parameter' is missing" simulate --point "$run:UZ5" --results results --periods 1

# summary.json that is not JSON.
damage summary.json 'lines[:] = lines[:4]'
expect_rejected "results/$run/summary.json: invalid JSON: parse error at line 5, column 1" export --auto "results/$run"
expect_rejected "results/$run/summary.json: invalid JSON" check --results results "$root/continuation-scripts/$run.toml"

# Issue 22, defect 8: columns the readers did not check. u_s = 1e308 in a branch file (plot, a
# restart), d1 = -5 in a trace's branch (plot of the trace), a nan among a map file's section
# points and a signature 'slip- bogus' there (map-sweep --merge, map --brute-force).
damage branch.csv 'k = lines[0].split(",").index("u_s"); f = lines[2].split(","); f[k] = "1e308"; lines[2] = ",".join(f)'
expect_rejected "results/$run/branch.csv:3: column 'u_s' = '1e308' is invalid: valid |u_s| <= 1000" plot "$run" --results results --output "$work/p.png"
expect_rejected "results/$run/branch.csv:3: column 'u_s' = '1e308' is invalid" simulate --point "$run:UZ5" --results results --periods 1
trace=paper-4.1-omega-trace
/usr/bin/python3 - "$work/results/$trace/branch-1/branch.csv" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
k = lines[0].split(",").index("d1"); f = lines[1].split(","); f[k] = "-5"; lines[1] = ",".join(f)
open(sys.argv[1], "w").write("\n".join(lines) + "\n")
PY
expect_rejected "results/$trace/branch-1/branch.csv:2: column 'd1' = '-5' is invalid: valid 0 <= d1 <=" plot "$trace" --results results --output "$work/p.png"
map_file="$work/map.csv"
damaged_map() {  # damaged_map <column> <value>: the committed section 6 map with one field of line 2 replaced
  /usr/bin/python3 - "$root/results/maps/paper-6-omega-u_r-brute-force.csv" "$map_file" "$1" "$2" <<'PY'
import sys
source, target, column, value = sys.argv[1:]
lines = open(source).read().splitlines()
k = lines[0].split(",").index(column); f = lines[1].split(","); f[k] = value; lines[1] = ",".join(f)
open(target, "w").write("\n".join(lines) + "\n")
PY
}
damaged_map x1 nan
expect_rejected "$map_file:2: column 'x1' = 'nan' is not a finite number" map-sweep --merge "$work/merged.csv" "$map_file"
expect_rejected "$map_file:2: column 'x1' = 'nan' is not a finite number" map --trace "results/paper-6-omega-trace" --second u_r --second-from 1.2 --second-to 1.6 --brute-force "$map_file" --output "$work/my-map"
damaged_map signature "slip- bogus"
expect_rejected "$map_file:2: column 'signature' = 'slip- bogus' is invalid" map-sweep --merge "$work/merged.csv" "$map_file"
[ ! -e "$work/merged.csv" ] || { echo "FAIL: a merge of a damaged map was written"; failures=$((failures + 1)); }

# A field a megabyte long: the one line shows its start and its length, not the megabyte (the
# whole field was printed before).
damage branch.csv 'f = lines[3].split(","); f[9] = "1" * 1000000; lines[3] = ",".join(f)'
expect_rejected "results/$run/branch.csv:4: column 'x20' = '1111111111" export --auto "results/$run"
grep -qF "...' (1000000 characters) is not a" "$work/stderr" && [ "$(wc -c < "$work/stderr")" -lt 400 ] ||
  { echo "FAIL: the message of a megabyte field is $(wc -c < "$work/stderr") bytes"; failures=$((failures + 1)); }

# Nothing was written beside the damaged run, and no restart run was created.
[ ! -e "$work/results/$run/b.$run" ] || { echo "FAIL: export wrote b.$run from a damaged run"; failures=$((failures + 1)); }
[ ! -e "$work/results/restart-check" ] || { echo "FAIL: a restart from a damaged run was written"; failures=$((failures + 1)); }

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "every reader of stored results rejects damaged files with one line naming where"
