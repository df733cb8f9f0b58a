#!/usr/bin/env bash
# stickslip sweep: the file's shape (a row per chain, direction, step and recorded period), and
# byte-identical output whatever the number of threads.
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sweep=(sweep --preset paper-6 --from 0.55 --to 0.57 --steps 4 --transients 20 --periods 3 --chains 3)

"$bin" "${sweep[@]}" --threads 1 --output "$work/one.csv" > /dev/null
"$bin" "${sweep[@]}" --threads 2 --output "$work/two.csv" > /dev/null
cmp "$work/one.csv" "$work/two.csv"
head -1 "$work/one.csv" | grep -qx "chain,direction,step,omega,section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period,amplitude:x2"
# 3 chains x (up + down) x 5 values x 3 periods, and a header.
[ "$(wc -l < "$work/one.csv")" -eq $((3 * 2 * 5 * 3 + 1)) ]
[ "$(cut -d, -f1 "$work/one.csv" | sort -u | tr '\n' ' ')" = "0 1 2 chain " ]
[ "$(cut -d, -f2 "$work/one.csv" | sed 1d | sort -u | tr '\n' ' ')" = "down up " ]

# A file an older sweep wrote (its second column "pass", renamed "direction") is the sweep's own: replaced.
printf 'chain,pass,step,omega,section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period,amplitude:x2\n' > "$work/old.csv"
"$bin" "${sweep[@]}" --output "$work/old.csv" > /dev/null
cmp "$work/one.csv" "$work/old.csv"

"$bin" "${sweep[@]}" --start fixed --output "$work/fixed.csv" > /dev/null
[ "$(wc -l < "$work/fixed.csv")" -eq $((3 * 5 * 3 + 1)) ]
[ "$(cut -d, -f2 "$work/fixed.csv" | sed 1d | sort -u)" = "fixed" ]
# A different seed scatters the other chains elsewhere; chain 0 starts from the preset's state.
"$bin" "${sweep[@]}" --seed 2 --output "$work/seed2.csv" > /dev/null
! cmp -s "$work/one.csv" "$work/seed2.csv"
cmp <(grep '^0,' "$work/one.csv") <(grep '^0,' "$work/seed2.csv")
# The last step lands on the range's end exactly: u_r down to u_s (valid) is not refused as an ulp
# below it (to - (to - from) != from).
"$bin" sweep --preset paper-4.1 --parameter u_r --from 0.1 --to 0.99 --steps 2 --chains 1 --periods 5 \
  --transients 2 --output "$work/ends.csv" > /dev/null
grep -q '^0,down,2,0.1,' "$work/ends.csv"
echo "sweep output ok"
