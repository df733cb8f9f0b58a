#!/usr/bin/env bash
# A run name that --point RUN:LABEL could never reach (one with ':') or that is not valid UTF-8
# (summary.json, JSON text, would store it otherwise than the disk has it) is refused wherever a run
# is named: exit 2, one line naming the option and the rule, nothing written (issue 22).
source "$(dirname "$0")/expect.sh"
o="$work/out"
c=(--preset paper-4.1 --parameter omega --range 0.5,0.6 --max-points 3 --results "$o")
rule="a run name: 1 to 200 bytes of UTF-8, not '.', without '/', '..', ':'"
for name in a:b ':' 'b:EP1' $'\xff' $'caf\xc3' $'\xed\xa0\x80' $'\xc0\xaf'; do
  expect 2 "$rule" "$bin" continue "${c[@]}" --output "$name"
  expect 2 "$rule" "$bin" trace "${c[@]}" --output "$name"
done
for name in a:b ':' 'b:EP1'; do
  printf 'output = "%s"\n[start]\npreset = "paper-4.1"\n[continuation]\nparameter = "omega"\ndirection = "up"\nrange = [0.5, 0.6]\n' "$name" \
    > "$work/bad.toml"
  expect 2 "key 'output' = '$name' is invalid: valid $rule" "$bin" run --results "$o" "$work/bad.toml"
done
cd "$root" || exit 1
expect 2 "output = '$o/m:1' is invalid" "$bin" map --trace results/paper-5.1-omega-trace --second u_r --second-from 0.4 \
  --second-to 0.6 --first-from 0.53 --first-to 0.6 --raster 64 --output "$o/m:1"
# A UTF-8 name beyond ASCII is a name like any other.
"$bin" continue "${c[@]}" --output "café-ω" > /dev/null && [ -s "$o/café-ω/summary.json" ] && pass || fail "a UTF-8 name"
finish
