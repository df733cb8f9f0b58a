#!/usr/bin/env bash
# A [model]'s curve in two parameters from a run file ([start.restart] with boundary, as the
# paper's): continuation-scripts/curves/two-masses-sk-boundary.toml from SK2 of the README's two
# masses (section 4.1's data in SI units) ends where the paper's curve paper-4.1-sk-boundary, stored
# in results/ by the paper's own closed forms, ends: at its NS, omega = 100 times the paper's,
# F_s = 40 N times its u_r. Then the refusals: exit 2, one line naming the key, nothing written.
source "$(dirname "$0")/expect.sh"
models="$root/continuation-scripts/models"
curve="$root/continuation-scripts/curves/two-masses-sk-boundary.toml"

"$bin" find --model "$models/two-masses.toml" --trace 59,66 --results "$work" --output tm > /dev/null 2>&1 &&
  grep -q "^[0-9]*,SK2,60.01" "$work/tm/branch-1/special-points.csv" && pass ||
  fail "the two masses' trace from omega = 65 has no SK2 near 60.01"
"$bin" run --results "$work/tm" "$curve" > "$work/curve.txt" 2>&1 && pass || fail "run of the curve: $(cat "$work/curve.txt")"
/usr/bin/python3 - "$work/tm/two-masses-sk-boundary" "$root/results/paper-4.1-sk-boundary" <<'PY' && pass ||
import csv, sys
def special(run, label):
    return next(r for r in csv.DictReader(open(run + "/special-points.csv")) if r["label"].startswith(label))
model, paper = special(sys.argv[1], "NS"), special(sys.argv[2], "NS")
assert abs(float(model["omega"]) / 100 - float(paper["omega"])) <= 1e-10, (model["omega"], paper["omega"])
assert abs(float(model["F_s"]) / 40 - float(paper["u_r"])) <= 1e-10, (model["F_s"], paper["u_r"])
assert float(model["F_k"]) == 4.0
PY
  fail "the [model]'s curve does not end where the paper's does"

# Refused: nothing written, the curve's files as they were.
tm="$work/tm"
sums=$(md5sum "$tm"/two-masses-sk-boundary/*) entries=$(ls -A "$tm")
# refused TEXT EDIT: the curve's run file edited by the sed expression EDIT is refused with TEXT.
refused() { expect 2 "$1" "$bin" run --results "$tm" <(sed "$2" "$curve"); }
refused "key 'start.restart.boundary' = 'omega' is invalid at 'SK2' (margin:reversal:1): valid a parameter the model varies, not the continued omega nor one released already: F_k, F_s, v_b" \
  's/boundary = "F_s"/boundary = "omega"/'
refused "key 'start.restart.boundary' = 'chi' is invalid: valid range F_k, F_s, v_b" 's/boundary = "F_s"/boundary = "chi"/'
refused "key 'start.restart.boundary' = 'F_s' is invalid at 'EP3' (EP): valid LP, SB or TR for an antisymmetric orbit" 's/label = "SK2"/label = "EP3"/'
refused "key 'start.restart.boundary' = '' is invalid" 's/boundary = "F_s"/boundary = ""/'
refused "key 'continuation.continue_past_type_changes' = true is invalid with start.restart.boundary" \
  's/^max_points = 400$/max_points = 400\ncontinue_past_type_changes = true/'
refused "key 'start.restart.boundary' cannot go with start.restart.switch_branch" 's/boundary = "F_s"/boundary = "F_s", switch_branch = true/'
[ "$(md5sum "$tm"/two-masses-sk-boundary/*)" = "$sums" ] && [ "$(ls -A "$tm")" = "$entries" ] && pass ||
  fail "a refused curve changed the results: $(ls "$tm")"
finish
