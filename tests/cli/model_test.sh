#!/usr/bin/env bash
# A user's own oscillator on the command line: describe and find --model read every example of
# continuation-scripts/models/ (exit 0); find --model's orbit of the mass on a belt is the closed-form
# stick-slip cycle (../shared/FRICTION-LITERATURE.md) and its JSON the text's; a steady slide exits 5;
# map-sweep --model's amplitudes are Den Hartog's; and a table of bad input: exit 2, one line naming
# the key or option, nothing written.
source "$(dirname "$0")/expect.sh"
models="$root/continuation-scripts/models"

for f in "$models"/*.toml; do
  "$bin" describe "$f" > "$work/describe.txt" 2>&1 && grep -q "^parameters" "$work/describe.txt" && pass ||
    fail "describe $(basename "$f"): $(cat "$work/describe.txt")"
  "$bin" find --model "$f" > "$work/find.txt" 2>&1 && grep -q "^verification passed" "$work/find.txt" && pass ||
    fail "find --model $(basename "$f"): $(cat "$work/find.txt")"
done

# The belt's cycle at v_b = 0.2 m/s and, by --set, 0.9 m/s against T_stick = 2 (F_s - F_k)/(k v_b),
# T_slip = (pi + 2 atan(v_b/(omega_n d)))/omega_n, the re-stick at x = (2 F_k - F_s)/k.
for v in 0.2 0.9; do
  "$bin" find --model "$models/belt.toml" --set v_b=$v --json > "$work/belt.json" 2> "$work/belt.err" ||
    fail "find --model belt.toml --set v_b=$v exits $?: $(cat "$work/belt.err")"
  /usr/bin/python3 - "$work/belt.json" $v <<'PY' && pass || fail "belt at v_b = $v is not the closed-form cycle"
import json, math, sys
o = json.load(open(sys.argv[1]))["orbit"]
v, k, m, fs, fk = float(sys.argv[2]), 1.0, 1.0, 1.5, 1.0
d, w = (fs - fk) / k, math.sqrt(k / m)
expected = {"stick": 2 * d / v, "slip": (math.pi + 2 * math.atan(v / (w * d))) / w}
assert o["signature"] == "stick slip-", o["signature"]
assert abs(o["durations"][0] - expected["stick"]) <= 1e-10 * expected["stick"], o["durations"]
assert abs(o["durations"][1] - expected["slip"]) <= 1e-10 * expected["slip"], o["durations"]
assert abs(o["start"]["m1_0"] - (2 * fk - fs) / k) <= 1e-10, o["start"]
assert list(o["start"]) == ["m1_0", "v_m1_0"], o["start"]
assert o["verification"]["passed"] and o["admissible"]
PY
done
# The JSON's orbit is the text's.
"$bin" find --model "$models/five-mass-chain.toml" > "$work/five.txt"
"$bin" find --model "$models/five-mass-chain.toml" --json > "$work/five.json"
/usr/bin/python3 - "$work/five.txt" "$work/five.json" <<'PY' && pass || fail "find --model: the JSON is not the text's orbit"
import json, sys
text, o = open(sys.argv[1]).read(), json.load(open(sys.argv[2]))["orbit"]
assert f"signature  {o['signature']}\n" in text
for name, value in o["start"].items():
    assert f"{name}={value:.10g}" in text, name
PY

# The damped belt traced in v_b (the default without forcing) from its cycle at 0.4: up, the slip arc
# grazes the belt's speed and the family folds with its stick finite (near v_b = 0.549, stick 0.91:
# the general-oscillator issue's numbers); down, it reaches the range's end. Printed, and as JSON.
"$bin" find --model "$models/belt-damped.toml" --trace 0.1,1.0 > "$work/trace.txt" 2> "$work/trace.err" ||
  fail "find --model belt-damped.toml --trace exits $?: $(cat "$work/trace.err")"
grep -q "^  up: no-adjacent-type: stop-slope:2" "$work/trace.txt" && pass || fail "the damped belt's trace: $(cat "$work/trace.txt")"
"$bin" find --model "$models/belt-damped.toml" --trace 0.1,1.0 --json > "$work/trace.json" 2>&1 || fail "find --trace --json exits $?"
/usr/bin/python3 - "$work/trace.json" <<'PY' && pass || fail "the damped belt's fold is not near v_b = 0.549 with a stick of 0.91"
import json, sys
t = json.load(open(sys.argv[1]))
assert t["parameter"] == "v_b" and t["start"]["status"] == "found"
up, down = t["up"]["branches"][-1], t["down"]["branches"][-1]
fold = up["points"][-1]
assert up["end"] == "no-adjacent-type" and abs(fold["v_b"] - 0.549) < 5e-4, fold["v_b"]
assert abs(fold["durations"][0] - 0.91) < 5e-3, fold["durations"]
assert t["down"]["end"] == "parameter-bound" and down["points"][-1]["v_b"] == 0.1
assert all(p["stable"] == 1 for p in up["points"]), "the attracting cycle is stable along the branch"
PY

# The five-mass chain's antisymmetric orbit at v_b = 0 traced in the belt's speed: written over its
# whole period (the mirror of a stick on a moving belt moves the other way), both ways to the bounds.
"$bin" find --model "$models/five-mass-chain.toml" --trace -0.3,0.3 --trace-parameter v_b > "$work/vb.txt" 2>&1 ||
  fail "find --model five-mass-chain.toml --trace in v_b exits $?: $(tail -3 "$work/vb.txt")"
[ "$(grep -c "^  'stick slip+ stick slip-' .* parameter-bound$" "$work/vb.txt")" -eq 2 ] && pass ||
  fail "the five-mass chain in v_b is not traced over its whole period: $(grep "^  '" "$work/vb.txt")"
# ... and in its kinetic level, F_s = 0.4 held: upwards the trace stops where F_k meets F_s, short of
# the range asked for, and its end says why.
"$bin" find --model "$models/five-mass-chain.toml" --trace 0.1,0.5 --trace-parameter F_k > "$work/fk.txt" 2>&1 &&
  grep -qx "  up: parameter-bound: reached F_k = 0.4 (F_k <= F_s = 0.4)" "$work/fk.txt" &&
  grep -qx "  down: parameter-bound: reached F_k = 0.1" "$work/fk.txt" && pass ||
  fail "the trace in F_k does not say that F_s ended it: $(grep "^  [a-z]*:" "$work/fk.txt")"

# A damped mass on a belt with equal levels slides steadily: no orbit type (exit 5), nothing printed on stdout.
cat > "$work/slide.toml" <<'TOML'
[model]
kind = "chain"
masses = [1.0]
springs = [{ between = ["m1", "ground"], k = 1.0 }]
dampers = [{ between = ["m1", "ground"], c = 0.5 }]
contact = "m1"
parameters = { F_k = 1.0, F_s = 1.0, v_b = 0.5 }
TOML
expect 5 "steady slip" "$bin" find --model "$work/slide.toml"

# sweep --model: Den Hartog's mass swept in omega from rest, one pass; the amplitude column is the
# closed form X = sqrt(V^2 - beta^2 U^2) at every point, the columns the model's; the same file on
# one thread as on two; a file the sweep did not write is not replaced.
"$bin" sweep --model "$models/den-hartog.toml" --from 1.5 --to 2.5 --steps 4 --transients 400 --periods 8 \
  --start fixed --chains 1 --threads 2 --output "$work/dh.csv" > "$work/dh.txt" 2>&1 || fail "sweep --model exits $?: $(cat "$work/dh.txt")"
/usr/bin/python3 - "$work/dh.csv" <<'PY' && pass || fail "sweep --model: not Den Hartog's amplitude"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert list(rows[0])[3:8] == ["omega", "section_phase", "k", "m1", "v_m1"], list(rows[0])
assert len({r["step"] for r in rows}) == 5
for r in rows:
    w, beta = float(r["omega"]), 0.25
    v, u = 1 / (1 - w * w), math.tan(math.pi / (2 * w)) / w
    assert abs(float(r["amplitude:m1"]) - math.sqrt(v * v - beta * beta * u * u)) < 1e-8, r
    assert r["period"] == "1" and r["stops_per_period"] == "2" and r["sticks_per_period"] == "0", r
PY
"$bin" sweep --model "$models/den-hartog.toml" --from 1.5 --to 2.5 --steps 4 --transients 400 --periods 8 \
  --start fixed --chains 1 --threads 1 --output "$work/dh1.csv" > /dev/null 2>&1 && cmp -s "$work/dh.csv" "$work/dh1.csv" &&
  pass || fail "sweep --model: the file depends on --threads"
# The same oscillator in other units (force, hence lengths and speeds, times 1e-7 and 1e7): the same
# periods on the section, settled (300 transient periods) or not (none), and amplitudes scaled.
for s in 1 1e-7 1e7; do
  sed "s|forcing = { m1 = 1.0 }|forcing = { m1 = $s }|; s|F_k = 0.25, F_s = 0.25|F_k = $(python3 -c "print(0.25*$s)"), F_s = $(python3 -c "print(0.25*$s)")|" \
    "$models/den-hartog.toml" > "$work/dh-$s.toml"
  for n in 0 300; do
    "$bin" sweep --model "$work/dh-$s.toml" --from 1.5 --to 2.5 --steps 4 --transients $n --periods 8 --start fixed \
      --chains 1 --output "$work/dh-$s-$n.csv" > /dev/null 2>&1 || fail "sweep --model dh-$s.toml exits $?"
  done
done
/usr/bin/python3 - "$work" <<'PY' && pass || fail "sweep --model: the periods depend on the model's units"
import csv, sys
def rows(s, n):
    return list(csv.DictReader(open(f"{sys.argv[1]}/dh-{s}-{n}.csv")))
for n in (0, 300):
    one = rows("1", n)
    assert any(r["period"] == "0" for r in rows("1", 0)), "the unsettled start should read no period"
    for s in ("1e-7", "1e7"):
        for a, b in zip(one, rows(s, n)):
            assert a["period"] == b["period"], (s, n, a["omega"], a["period"], b["period"])
            assert abs(float(b["amplitude:m1"]) / float(s) - float(a["amplitude:m1"])) <= 1e-9 * float(a["amplitude:m1"])
PY
# find --model in those units: a linear oscillator with Coulomb friction is homogeneous (forces and
# the state times s give a motion), so the five-mass chain's orbit with forces times 1e-7 and 1e7 is
# the same type with the same durations, its start state s times, solved and verified (the
# tolerances relative to the orbit's size: absolute ones failed Odeint's check at 1e-7 and Newton at 1e7).
for s in 1 1e-7 1e7; do
  sed "s|forcing = { m1 = 1.0 }|forcing = { m1 = $s }|; s|F_k = 0.3, F_s = 0.4|F_k = $(python3 -c "print(0.3*$s)"), F_s = $(python3 -c "print(0.4*$s)")|" \
    "$models/five-mass-chain.toml" > "$work/chain-$s.toml"
  "$bin" find --model "$work/chain-$s.toml" --json > "$work/chain-$s.json" 2> "$work/chain-$s.err" ||
    fail "find --model chain-$s.toml exits $?: $(cat "$work/chain-$s.err")"
done
/usr/bin/python3 - "$work" <<'PY' && pass || fail "find --model: the orbit depends on the model's units"
import json, sys
def orbit(s):
    return json.load(open(f"{sys.argv[1]}/chain-{s}.json"))["orbit"]
one = orbit("1")
for s in ("1e-7", "1e7"):
    o = orbit(s)
    assert o["signature"] == one["signature"] and o["verification"]["passed"], (s, o["signature"], o["verification"])
    assert all(abs(a - b) <= 1e-9 * (1 + abs(a)) for a, b in zip(one["durations"], o["durations"])), (s, o["durations"])
    scale = max(abs(v) for v in one["start"].values())
    assert all(abs(o["start"][k] / float(s) - v) <= 1e-8 * scale for k, v in one["start"].items()), (s, o["start"])
PY
# Declared units label every output, the numbers unchanged: describe's parameters and free
# oscillations, find's measures, and a trace's summaries (which figures read); the same orbit as SI.
{ cat "$models/five-mass-chain.toml"; echo 'units = { length = "mm", time = "ms", force = "kN" }'; } > "$work/mm.toml"
"$bin" describe "$work/mm.toml" > "$work/mm.txt" 2>&1 && grep -q "omega .* rad/ms .*forcing frequency" "$work/mm.txt" &&
  grep -q "^  v_b .* mm/ms " "$work/mm.txt" && grep -q "^free oscillations (rad/ms, damping ratio)" "$work/mm.txt" &&
  grep -q "^forcing    m1 1 kN" "$work/mm.txt" && pass || fail "describe: the declared units: $(cat "$work/mm.txt")"
"$bin" describe "$work/mm.toml" --json | /usr/bin/python3 -c '
import json, sys
d = json.load(sys.stdin)
assert d["units"] == {"length": "mm", "time": "ms", "force": "kN"}, d["units"]
assert [p["unit"] for p in d["parameters"]] == ["rad/ms", "kN", "kN", "mm/ms"], d["parameters"]' && pass ||
  fail "describe --json: the declared units"
same='^(signature.*|start.*|  m[0-9] +amplitude [^ ]+  peak-to-peak [^ ]+|  d[0-9]+ = [^ ]+ )'
"$bin" find --model "$work/mm.toml" > "$work/mm-find.txt" 2>&1 && grep -q "J per period" "$work/five.txt" &&
  grep -q "kN mm per period, equivalent viscous damping .* kN ms/mm" "$work/mm-find.txt" &&
  grep -q "^period .* ms  phi" "$work/mm-find.txt" && grep -q "^measures over one period (lengths in mm)" "$work/mm-find.txt" &&
  [ "$(grep -oE "$same" "$work/mm-find.txt")" = "$(grep -oE "$same" "$work/five.txt")" ] && pass ||
  fail "find --model: the declared units: $(diff "$work/five.txt" "$work/mm-find.txt")"
"$bin" find --model "$work/mm.toml" --trace 0.55,0.65 --output mm-trace --results "$work" > /dev/null 2>&1
/usr/bin/python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))
assert s["units"] == {"length": "mm", "time": "ms", "force": "kN"}, s' "$work/mm-trace/branch-1/summary.json" && pass ||
  fail "find --model --trace: the summary lacks the declared units"
"$bin" find --model "$work/mm.toml" --json | /usr/bin/python3 -c '
import json, sys
assert json.load(sys.stdin)["orbit"]["units"] == {"length": "mm", "time": "ms", "force": "kN"}' && pass ||
  fail "find --model --json: the orbit lacks the declared units"
# The run file's units changed since the run: a restart would relabel every number; refused.
sed -i 's|length = "mm"|length = "cm"|' "$work/mm.toml"
expect 2 "the run's numbers are in mm, ms, kN (length, time, force) but" \
  "$bin" solve --point branch-1:EP1 --results "$work/mm-trace"
expect 2 "the run's numbers are in mm, ms, kN (length, time, force) but" \
  "$bin" continue --point branch-1:EP1 --results "$work/mm-trace" --parameter F_s --range 0.3,0.8 --output x
# The AUTO export writes the numbers without units: not refused.
"$bin" export --auto "$work/mm-trace/branch-1" > /dev/null 2>&1 && pass || fail "export --auto refused a run whose units changed"
sed 's|m1|b|g; s|contact = "b"|contact = "b"\nnames = ["b"]|' "$models/den-hartog.toml" > "$work/b.toml"
expect 2 "parameter = 'v_b' is invalid" "$bin" sweep --model "$work/b.toml" --parameter v_b --from 0.1 --to 0.3 --output "$work/x.csv"
sed 's|m1|k|g; s|contact = "k"|contact = "k"\nnames = ["k"]|' "$models/belt.toml" > "$work/k.toml"
expect 2 "gives the state a column 'k'" "$bin" describe "$work/k.toml"
echo "mine" > "$work/mine.csv"
expect 2 "output" "$bin" sweep --model "$models/den-hartog.toml" --from 1.5 --to 2.5 --output "$work/mine.csv"
grep -qx mine "$work/mine.csv" && pass || fail "sweep --model replaced a file it did not write"
# The belt (no forcing) swept in its speed, read on its stick entries: the closed-form cycle's
# max |x| = F_k/k + hypot(d, v_b/omega_n) and re-stick x = (2 F_k - F_s)/k at every speed.
"$bin" sweep --model "$models/belt.toml" --parameter v_b --from 0.2 --to 0.9 --steps 7 --transients 5 --periods 6 \
  --start fixed --chains 1 --output "$work/belt.csv" > /dev/null 2>&1 || fail "sweep --model belt.toml exits $?"
/usr/bin/python3 - "$work/belt.csv" <<'PY' && pass || fail "sweep --model belt.toml: not the closed-form cycle"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len({r["step"] for r in rows}) == 8
for r in rows:
    v = float(r["v_b"])
    assert r["period"] == "1" and r["sticks_per_period"] == "1" and r["stops_per_period"] == "1", r
    assert abs(float(r["amplitude:m1"]) - (1.0 + math.hypot(0.5, v))) < 1e-9, r
    assert abs(float(r["m1"]) - 0.5) < 1e-9 and abs(float(r["v_m1"]) - v) < 1e-9, r
PY
expect 2 "parameter = 'omega' is invalid" "$bin" sweep --model "$models/belt.toml" --from 0.2 --to 0.3 --output "$work/belt2.csv"
expect 2 "parameter = 'chi' is invalid: valid range omega, F_k, F_s, v_b" "$bin" sweep --model "$models/den-hartog.toml" --parameter chi --from 0.2 --to 0.3 --output "$work/x.csv"
expect 2 "to: " "$bin" sweep --model "$models/den-hartog.toml" --parameter F_s --from 0.25 --to 0.1 --output "$work/x.csv"
expect 2 "preset is not taken with --model" "$bin" sweep --model "$models/den-hartog.toml" --preset paper-4.1 --from 1 --to 2 --output "$work/x.csv"
expect 2 "omega2 = 1 is invalid: omega2 is no parameter of the model" "$bin" sweep --model "$models/den-hartog.toml" --set omega2=1 --from 1.5 --to 2 --output "$work/x.csv"
[ ! -e "$work/belt2.csv" ] && [ ! -e "$work/x.csv" ] && pass || fail "a refused sweep --model wrote its file"

# The paper's oscillator (section 4.1's data) written as a chain in physical units (eq. 3 with m1 = 1,
# k1 + k2 = 1: m2 = 1/eta, k1 = 1 - chi, k2 = chi, forcing 1/eta on m2, F_k = u_s, F_s = u_r; time and
# lengths then equal the paper's scaled ones), started where the paper's preset starts (--set its state
# and phase): find --model reads the same subharmonics as the paper's own finder, period 3 antisymmetric
# at omega = 0.37 and period 2 at 0.40: the same period, the same segments up to where the period is
# read from, the same measures to 1e-8 (the paper's friction work and equivalent damping are per unit
# m2, eq. 2's force eta u_s: eta = 4 times the chain's joules and N s/m), the same stability. Two
# independent closed forms (the paper's eqs. 5-20 against the general model's modes).
cat > "$work/pascal.toml" <<'TOML'
[model]
kind = "chain"
masses = [1.0, 0.25]
names = ["x1", "x2"]
springs = [{ between = ["x1", "ground"], k = 0.7 }, { between = ["x1", "x2"], k = 0.3 }]
forcing = { x2 = 0.25 }
contact = "x2"
parameters = { omega = 0.6, F_k = 0.1, F_s = 0.2996 }
TOML
for w in 0.37 0.40; do
  "$bin" find --preset paper-4.1 --set omega=$w --json > "$work/paper.json" 2>&1 || fail "find --preset paper-4.1 at $w exits $?"
  "$bin" find --model "$work/pascal.toml" --set omega=$w --set x1_0=1.5608 --set x2_0=3.3295 --set v1_0=0.1523 \
    --set phi=0.3925 --json > "$work/model.json" 2> "$work/model.err" || fail "find --model (the paper's chain) at $w exits $?: $(cat "$work/model.err")"
  /usr/bin/python3 - "$work/paper.json" "$work/model.json" <<'PY' && pass || fail "find --model: not the paper's orbit at omega = $w"
import json, math, sys
paper, model = json.load(open(sys.argv[1]))["orbit"], json.load(open(sys.argv[2]))["orbit"]
def whole(signature, durations):  # the modes and durations over the whole period
    modes = signature.split(" / ")[0].split()
    if "antisymmetric" in signature:
        mirror = {"slip+": "slip-", "slip-": "slip+", "stick": "stick"}
        modes, durations = modes + [mirror[m] for m in modes], durations + durations
    return modes, durations
p_modes, p_d = whole(paper["signature"], [s["duration"] for s in paper["segments"]])
m_modes, m_d = whole(model["signature"], model["durations"])
# The same cycle of segments, whichever stop each finder took as the origin.
shifts = [k for k in range(len(m_modes)) if m_modes[k:] + m_modes[:k] == p_modes and
          max(abs(a - b) for a, b in zip(m_d[k:] + m_d[:k], p_d)) < 1e-8]
assert len(p_modes) == len(m_modes) and shifts, (paper["signature"], p_d, model["signature"], m_d)
assert abs(model["period"] - sum(p_d) / (2 if "antisymmetric" in paper["signature"] else 1) *
           (2 if "antisymmetric" in paper["signature"] else 1)) < 1e-8
eta = 4.0
for key, value in paper["measures"].items():
    expected = value / eta if key in ("friction-work", "equivalent-damping") else value
    assert abs(model["measures"][key] - expected) <= 1e-8 * max(1, abs(expected)), (key, value, model["measures"][key])
assert model["stable"] == paper["stable"] and model["verification"]["passed"]
PY
done
# Section 5.1's data at omega = 0.57: after 1000 periods the motion still contracts onto its period-1
# orbit with a multiplier near a cube root of unity, so it repeats to 1e-6 after 3 periods first; the
# orbit read over 3 periods is the period-1 one written three times, and is reduced to it (the
# paper's finder, which lengthens its transient, reads period 1 with the same durations).
sed 's|masses = \[1.0, 0.25\]|masses = [1.0, 0.238095238095238]|; s|k = 0.7 }|k = 0.78 }|; s|k = 0.3 }|k = 0.22 }|;
     s|x2 = 0.25|x2 = 0.238095238095238|; s|omega = 0.6, F_k = 0.1, F_s = 0.2996|omega = 0.57, F_k = 0.0138, F_s = 0.4962|' \
  "$work/pascal.toml" > "$work/p51.toml"
"$bin" find --model "$work/p51.toml" --set x1_0=-0.3643 --set x2_0=4.1887 --set v1_0=-0.2578 --set phi=0.3177 \
  --json > "$work/p51.json" 2>&1 || fail "find --model p51.toml exits $?: $(cat "$work/p51.json")"
"$bin" find --preset paper-5.1 --set omega=0.57 --json > "$work/paper51.json" 2>&1 || fail "find --preset paper-5.1 exits $?"
/usr/bin/python3 - "$work/p51.json" "$work/paper51.json" <<'PY' && pass || fail "find --model: a period-1 orbit read as three copies"
import json, sys
model, paper = json.load(open(sys.argv[1]))["orbit"], json.load(open(sys.argv[2]))["orbit"]
assert model["signature"] == "slip- stick slip+" == paper["signature"], (model["signature"], paper["signature"])
pairs = zip(sorted(model["durations"]), sorted(s["duration"] for s in paper["segments"]))
assert len(model["durations"]) == 3 and all(abs(a - b) < 1e-8 for a, b in pairs), model["durations"]
PY
expect 2 "x9_0 = 1 is invalid: x9_0 is no parameter of the model: valid omega, F_k, F_s, v_b, or the start's x1_0, x2_0, v1_0, v2_0 and phi" \
  "$bin" find --model "$work/pascal.toml" --set x9_0=1
expect 2 "x2_0 = 1e+300 is invalid" "$bin" find --model "$work/pascal.toml" --set x2_0=1e300
expect 2 "max-multiple" "$bin" find --model "$work/pascal.toml" --max-multiple 21
printf 'start = { x9_0 = 1.0 }\n' | cat "$work/pascal.toml" - > "$work/start.toml"
expect 2 "start.toml:9:9: model.start.x9_0 = 1 is invalid: x9_0 is not the start's: valid x1_0, x2_0, v1_0, v2_0 and phi" \
  "$bin" find --model "$work/start.toml"
printf 'start = { phi = 1e10 }\n' | cat "$work/pascal.toml" - > "$work/start.toml"
expect 2 "model.start.phi" "$bin" find --model "$work/start.toml"

# Bad input: the key or option named, exit 2.
bad() {  # bad <name> <the line of belt.toml to replace> <its replacement>
  sed "s|$2|$3|" "$models/belt.toml" > "$work/$1.toml"
}
bad contact 'contact = "m1"' 'contact = "m2"'
expect 2 "key 'model.contact' = 'm2' is invalid" "$bin" find --model "$work/contact.toml"
expect 2 "key 'model.contact' = 'm2' is invalid" "$bin" describe "$work/contact.toml"
bad levels 'F_s = 1.5' 'F_s = 0.5'
expect 2 "model.parameters.F_s = 0.5 is invalid" "$bin" find --model "$work/levels.toml"
bad spring 'k = 1.0' 'k = -1.0'
expect 2 "key 'model.springs[0].k' = -1 is invalid: valid >= 0" "$bin" describe "$work/spring.toml"
bad unknown 'contact = "m1"' 'contact = "m1"\nmass = 2'
expect 2 "key 'model.mass' is unknown: did you mean 'model.masses'?" "$bin" describe "$work/unknown.toml"
{ printf '[model]\nkind = "chain"\nmasses = ['; for k in $(seq 50); do printf '1.0, '; done
  printf '1.0]\ncontact = "m1"\n'; } > "$work/51.toml"
expect 2 "key 'model.masses' holds 51 masses: valid 1 to 50" "$bin" describe "$work/51.toml"
bad ground 'contact = "m1"' 'contact = "m1"\nnames = ["ground"]'
expect 2 "key 'model.names' holds 'ground'" "$bin" describe "$work/ground.toml"
bad loose 'between = \["m1", "ground"\], k = 1.0' 'between = ["m1", "ground"], k = 0.0'
expect 2 "model.springs" "$bin" describe "$work/loose.toml"
expect 2 "Omega = 1 is invalid: Omega is no parameter of the model" "$bin" find --model "$models/belt.toml" --set Omega=1
expect 2 "v_b = 1e+300 is invalid" "$bin" find --model "$models/belt.toml" --set v_b=1e300
expect 2 "transients" "$bin" find --model "$models/belt.toml" --transients 1
expect 2 "transients" "$bin" find --model "$models/belt.toml" --transients 1e9
expect 2 "preset is not taken with --model" "$bin" find --model "$models/belt.toml" --preset paper-5.1
expect 2 "output = 't' is invalid: valid range with --trace" "$bin" find --model "$models/belt.toml" --output t --results "$work/out"
expect 2 "output = 'a/b' is invalid" "$bin" find --model "$models/belt.toml" --trace 0.1,0.3 --output a/b --results "$work/out"
mkdir -p "$work/out/mine" && echo notes > "$work/out/mine/NOTES.md"
expect 2 "output = 'mine' is invalid" "$bin" find --model "$models/belt.toml" --trace 0.1,0.3 --output mine --results "$work/out"
rm -r "$work/out/mine"
expect 2 "trace-parameter = 'F_k' is invalid: valid range with --model" "$bin" find --preset paper-4.1 --trace-parameter F_k
expect 2 "trace-parameter = 'v_b' is invalid: valid range with --trace" "$bin" find --model "$models/belt.toml" --trace-parameter v_b
expect 2 "trace-parameter = 'omega' is invalid" "$bin" find --model "$models/belt.toml" --trace 0.1,1 --trace-parameter omega
expect 2 "trace = '0.3,1' is invalid: valid range finite LO < HI with LO <= v_b = 0.2 <= HI" "$bin" find --model "$models/belt.toml" --trace 0.3,1
# A [model]'s trace written as stickslip trace writes one: the forced chain's trace.csv holds each
# orbit's period (k 2 pi/omega, k from its signature), its start state by the model's names, and
# the points --json prints; a second run replaces its own files and keeps the user's.
"$bin" find --model "$models/five-mass-chain.toml" --trace 0.55,0.7 --output chain --results "$work/traces" \
  > "$work/chain.txt" 2> "$work/chain.err" && grep -q "^chain: 3 branches in" "$work/chain.txt" && pass ||
  fail "find --model --trace --output: $(cat "$work/chain.err" "$work/chain.txt")"
"$bin" find --model "$models/five-mass-chain.toml" --trace 0.55,0.7 --json > "$work/chain.json"
/usr/bin/python3 - "$work/traces/chain" "$work/chain.json" <<'PY' && pass || fail "the written model trace is not the printed one"
import csv, json, math, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/trace.csv")))
printed = json.load(open(sys.argv[2]))
points = [p for d in ("down", "up") for b in printed[d]["branches"] for p in b["points"]]
assert len(rows) == len(points) > 50, (len(rows), len(points))
assert list(rows[0])[7:17] == ["m1_0", "m2_0", "m3_0", "m4_0", "m5_0", "v_m1_0", "v_m2_0", "v_m3_0", "v_m4_0", "stable"], list(rows[0])
for row, p in zip(rows, points):
    k = 3 if "period 3" in row["signature"] else 2 if "period 2" in row["signature"] else 1
    assert abs(float(row["period"]) - k * 2 * math.pi / float(row["omega"])) <= 1e-12 * float(row["period"]), row
    assert float(row["omega"]) == p["omega"] and float(row["period"]) == p["period"], (row, p)
    assert int(row["stable"]) == p["stable"] and int(row["admissible"]) == p["admissible"], (row, p)
# The slip's natural frequencies, which a figure over omega marks: five equal masses and springs, fixed
# at one end and free at the other (the contact's mass sliding): 2 sin((2k - 1) pi / 22) rad/s.
natural = json.load(open(sys.argv[1] + "/trace.json"))["natural_frequencies"]
assert len(natural) == 5 and all(abs(f - 2 * math.sin((2 * k - 1) * math.pi / 22)) <= 1e-12
                                 for k, f in enumerate(natural, 1)), natural
summary = json.load(open(sys.argv[1] + "/branch-1/summary.json"))
assert summary["model"] == "linear-oscillator" and json.load(open(sys.argv[1] + "/trace.json"))["model"] == "linear-oscillator"
PY
# The steps of its branches, as trace takes them: --max-points caps every branch's points (the chain's
# first branch ends there), and a smaller --ds-max takes more points over the same branch.
"$bin" find --model "$models/five-mass-chain.toml" --trace 0.55,0.7 --max-points 5 --json > "$work/steps.json" 2>&1 ||
  fail "find --model --trace --max-points 5 exits $?: $(tail -2 "$work/steps.json")"
"$bin" find --model "$models/five-mass-chain.toml" --trace 0.55,0.7 --ds-max 0.01 --json > "$work/fine.json" 2>&1 ||
  fail "find --model --trace --ds-max 0.01 exits $?: $(tail -2 "$work/fine.json")"
/usr/bin/python3 - "$work/steps.json" "$work/fine.json" "$work/chain.json" <<'PY' && pass || fail "find --model --trace ignores its steps"
import json, sys
capped, fine, default = (json.load(open(path)) for path in sys.argv[1:4])
branches = [b for d in ("down", "up") for b in capped[d]["branches"]]
assert all(len(b["points"]) <= 5 for b in branches), [len(b["points"]) for b in branches]
assert any(b["end"] == "max-points" for b in branches), [b["end"] for b in branches]
first = lambda t: t["up"]["branches"][0]["points"]
assert len(first(fine)) > len(first(default)), (len(first(fine)), len(first(default)))
PY
expect 2 "max-points = 5 is invalid: valid range with --trace or --write-run" "$bin" find --model "$models/belt.toml" --max-points 5

# A [model]'s label restarts on the branch that leaves it (switch_branch = true): the five-mass
# chain's antisymmetric period-3 orbit breaks its symmetry at SB2 (omega = 0.37506); the branch from
# there has lost the symmetry (the contact's peak-to-peak, twice its amplitude on the antisymmetric
# branch, is 10 % less at its end), and its orbits are motions both simulators verify (solve at its
# TR2). At a label that is no crossing, and with multiple shooting, it is refused naming the key.
sed 's/omega = 0.6,/omega = 0.38,/' "$models/five-mass-chain.toml" > "$work/chain38.toml"
"$bin" find --model "$work/chain38.toml" --trace 0.374,0.38 --output sb --results "$work/switch" > /dev/null 2>&1 &&
  grep -q "^[0-9]*,SB2,0.37505" "$work/switch/sb/branch-1/special-points.csv" && pass ||
  fail "the chain's trace from omega = 0.38 has no SB2: $(cut -d, -f1-3 "$work/switch/sb/branch-1/special-points.csv")"
printf '%s\n' 'output = "sb-switched"' '[start]' 'restart = { run = "branch-1", label = "SB2", switch_branch = true }' \
  '[continuation]' 'parameter = "omega"' 'direction = "down"' 'range = [0.37, 0.38]' > "$work/switch.toml"
"$bin" run --results "$work/switch/sb" "$work/switch.toml" > "$work/switch.txt" 2>&1 &&
  grep -qF '"signature": "stick slip+ stick slip+ stick slip- stick slip- / period 3"' "$work/switch/sb/sb-switched/summary.json" &&
  grep -q "^[0-9]*,TR2," "$work/switch/sb/sb-switched/special-points.csv" && /usr/bin/python3 -c '
import csv, sys
def asymmetry(path):  # |2 amplitude - peak-to-peak| / amplitude of the contact, at each point
    return [abs(2 * float(r["amplitude:m5"]) - float(r["peak-to-peak:m5"])) / float(r["amplitude:m5"])
            for r in csv.DictReader(open(path))]
assert max(asymmetry(sys.argv[1])) <= 1e-12 and asymmetry(sys.argv[2])[-1] > 0.05, asymmetry(sys.argv[2])' \
  "$work/switch/sb/branch-1/branch.csv" "$work/switch/sb/sb-switched/branch.csv" && pass ||
  fail "no branch without the symmetry leaves SB2: $(cat "$work/switch.txt")"
"$bin" solve --results "$work/switch/sb" --point sb-switched:TR2 --json > "$work/tr2.json" 2>&1 &&
  /usr/bin/python3 -c '
import json, sys
o = json.load(open(sys.argv[1]))["orbit"]
assert o["signature"] == "stick slip+ stick slip+ stick slip- stick slip- / period 3", o["signature"]
assert o["verification"]["passed"] and o["admissible"], o["verification"]' "$work/tr2.json" && pass ||
  fail "the switched branch's TR2 is no verified motion: $(tail -3 "$work/tr2.json")"
# The other side (direction = "up") is the other half of the pitchfork, the mirror images, whose
# halves are swapped: d1 - d5 of the opposite sign at every point (both directions gave one half).
sed 's/"sb-switched"/"sb-other"/; s/"down"/"up"/' "$work/switch.toml" > "$work/switch-other.toml"
"$bin" run --results "$work/switch/sb" "$work/switch-other.toml" > /dev/null 2>&1 && /usr/bin/python3 -c '
import csv, sys
one, other = ([float(r["d1"]) - float(r["d5"]) for r in csv.DictReader(open(p))] for p in sys.argv[1:3])
assert min(len(one), len(other)) > 5 and all(a * b < 0 for a, b in zip(one, other)), (one[:3], other[:3])' \
  "$work/switch/sb/sb-switched/branch.csv" "$work/switch/sb/sb-other/branch.csv" && pass ||
  fail "switch_branch's two directions are not the two mirror halves at SB2"
sed 's/label = "SB2"/label = "EP1"/' "$work/switch.toml" > "$work/switch-ep.toml"
expect 2 "key 'start.restart.switch_branch' = true is invalid at 'EP1' (type EP): valid at a period doubling (PD) or a symmetry breaking (SB)" \
  "$bin" run --results "$work/switch/sb" "$work/switch-ep.toml"
sed 's/parameter = "omega"/parameter = "v_b"/; s/range = \[0.37, 0.38\]/range = [0.0, 0.1]/' "$work/switch.toml" > "$work/switch-vb.toml"
expect 2 "so no other branch crosses there in v_b: valid omega, F_k, F_s" \
  "$bin" run --results "$work/switch/sb" "$work/switch-vb.toml"
# SB2 lies on F_k = 0.3: both halves of the branch leaving it start below, outside a range [0.3, 0.4]
# that holds the label. Refused, naming the side, and nothing written (a one-point run was).
for side in down up; do
  sed "s/\"sb-switched\"/\"sb-fk\"/; s/parameter = \"omega\"/parameter = \"F_k\"/; s/range = \[0.37, 0.38\]/range = [0.3, 0.4]/; s/\"down\"/\"$side\"/" \
    "$work/switch.toml" > "$work/switch-fk.toml"
  expect 2 "key 'continuation.range' = [0.3, 0.4] excludes the first point of the branch that leaves 'SB2' (direction = \"$side\"), F_k = 0.29999" \
    "$bin" run --results "$work/switch/sb" "$work/switch-fk.toml"
  [ ! -e "$work/switch/sb/sb-fk" ] && pass || fail "the refused switch in F_k going $side wrote its run"
done
printf 'shooting = "multiple"\n' >> "$work/switch.toml"
expect 2 "key 'continuation.shooting' = \"multiple\" is invalid with start.restart.switch_branch" \
  "$bin" run --results "$work/switch/sb" "$work/switch.toml"
expect 2 "ds = 0.1 is invalid: valid range 0 < ds-min (1e-08) <= ds <= ds-max (0.05)" "$bin" find --model "$models/belt.toml" --trace 0.1,0.3 --ds 0.1

echo mine > "$work/traces/chain/NOTES.md"
"$bin" find --model "$models/five-mass-chain.toml" --trace 0.55,0.7 --output chain --results "$work/traces" > "$work/chain.txt" &&
  grep -q "kept 1 other file(s) of .*: NOTES.md" "$work/chain.txt" && [ "$(cat "$work/traces/chain/NOTES.md")" = mine ] && pass ||
  fail "a second find --model --trace --output did not keep the user's file: $(cat "$work/chain.txt")"
"$bin" plot "$work/traces/chain" --output "$work/chain.png" > /dev/null && [ -s "$work/chain.png" ] && pass ||
  fail "stickslip plot of a [model]'s trace"
# A [model]'s label restarts continue and trace (issue 22: every label restarts), from the command line
# and from a run file's [start.restart], and check re-runs such a run file. The branch in F_s from EP1
# (omega = 0.6) passes F_s = 0.5 (a user value) at the orbit the motion from rest settles on there
# (find --model --set F_s=0.5: a simulation and its own Newton solve, not the continuation).
"$bin" continue --results "$work/traces/chain" --point branch-1:EP1 --parameter F_s --range 0.3,0.8 \
  --direction both --user-value F_s=0.5 --output fs > "$work/fs.txt" 2>&1 &&
  grep -q "^fs-up: .* UZ(F_s=0.5)" "$work/fs.txt" && grep -q "^fs-down: .*reached F_s = 0.3" "$work/fs.txt" && pass ||
  fail "continue from a [model]'s label: $(cat "$work/fs.txt")"
"$bin" find --model "$models/five-mass-chain.toml" --set F_s=0.5 --json > "$work/fs.json"
/usr/bin/python3 - "$work/traces/chain/fs-up" "$work/fs.json" <<'PY' && pass || fail "the branch from a [model]'s label is not the found orbit"
import csv, json, sys
uz = [r for r in csv.DictReader(open(sys.argv[1] + "/special-points.csv")) if r["label"].startswith("UZ")]
orbit = json.load(open(sys.argv[2]))["orbit"]
assert len(uz) == 1 and orbit["signature"] == json.load(open(sys.argv[1] + "/summary.json"))["signature"], (uz, orbit)
found = dict(orbit["start"], phi=orbit["phi"], d1=orbit["durations"][0], d2=orbit["durations"][1])
for name, value in found.items():
    if name in uz[0]:
        assert abs(float(uz[0][name]) - value) <= 1e-9 * (1 + abs(value)), (name, uz[0][name], value)
assert json.load(open(sys.argv[1] + "/summary.json"))["run_file"].endswith("five-mass-chain.toml")
PY
# A user value of any unknown: the phase phi, reached on the branch in F_s.
"$bin" continue --results "$work/traces/chain" --point branch-1:EP1 --parameter F_s --range 0.3,0.8 \
  --user-value phi=-0.43 --output uv > /dev/null &&
  awk -F, 'NR > 1 && $2 ~ /^UZ/ { found = ($7 + 0.43 < 1e-12 && $7 + 0.43 > -1e-12) } END { exit !found }' \
    "$work/traces/chain/uv/special-points.csv" && pass || fail "a user value of phi at a [model]'s label"
"$bin" trace --results "$work/traces/chain" --point fs-up:UZ2 --parameter omega --range 0.5,0.7 --output fs-omega \
  > "$work/fs-omega.txt" 2>&1 && grep -q "^fs-omega: [0-9]* branches in" "$work/fs-omega.txt" &&
  grep -q '"model": "linear-oscillator"' "$work/traces/chain/fs-omega/trace.json" && pass ||
  fail "trace from a [model]'s label: $(cat "$work/fs-omega.txt")"
printf 'output = "fs-file"\n[start.restart]\nrun = "branch-1"\nlabel = "EP1"\n[continuation]\nparameter = "F_s"\nrange = [0.3, 0.8]\n[trace]\n' \
  > "$work/restart.toml"
"$bin" run --results "$work/traces/chain" "$work/restart.toml" > /dev/null && \
  "$bin" check --results "$work/traces/chain" "$work/restart.toml" > "$work/check.txt" && grep -q "fs-file/trace.json: ok" "$work/check.txt" &&
  pass || fail "run and check of a run file restarting from a [model]'s label: $(cat "$work/check.txt")"
restart=(continue --results "$work/traces/chain" --output z)
for bad in "--set omega=0.5:set is invalid with a [model]'s label ('branch-1:EP1')" "--free phi:free is invalid with a [model]'s label" \
  "--preset paper-4.1:preset is invalid with a [model]'s label" \
  "--user-value omega=0.6:user-value names 'omega', which is not an unknown of the run" \
  "--fix phi=0.3:fix is invalid with a [model]'s label"; do
  expect 2 "${bad#*:}" "$bin" "${restart[@]}" --point branch-1:EP1 --parameter F_s --range 0.3,0.8 ${bad%%:*}
done
expect 2 "parameter = 'chi' is invalid: valid range omega, F_k, F_s, v_b" "$bin" "${restart[@]}" --point branch-1:EP1 \
  --parameter chi --range 0.3,0.8
expect 2 "range = '0.45,0.6' excludes the start, F_s = 0.4" "$bin" "${restart[@]}" --point branch-1:EP1 --parameter F_s \
  --range 0.45,0.6
expect 2 "label 'XX1' is not in" "$bin" "${restart[@]}" --point branch-1:XX1 --parameter F_s --range 0.3,0.8
[ ! -e "$work/traces/chain/z" ] && pass || fail "a refused restart wrote its output"
# solve at a [model]'s label: its orbit solved again (no Newton step needed) and checked as find
# --model checks the orbit it finds; its JSON is find --model's, its orbit the stored one.
"$bin" solve --results "$work/traces/chain" --point fs-up:UZ2 > "$work/solve.txt" 2>&1 &&
  grep -q "^verification passed" "$work/solve.txt" && grep -q "^newton     converged after 0 iteration" "$work/solve.txt" &&
  pass || fail "solve at a [model]'s label: $(cat "$work/solve.txt")"
"$bin" solve --results "$work/traces/chain" --point fs-up:UZ2 --json > "$work/solve.json" &&
  /usr/bin/python3 - "$work/traces/chain/fs-up" "$work/solve.json" <<'PY' && pass || fail "solve --json at a [model]'s label is not the stored orbit"
import csv, json, sys
uz = [r for r in csv.DictReader(open(sys.argv[1] + "/special-points.csv")) if r["label"] == "UZ2"][0]
orbit = json.load(open(sys.argv[2]))["orbit"]  # as find --model --json prints it
assert orbit["admissible"] and orbit["verification"]["passed"], orbit
stored = dict(orbit["start"], phi=orbit["phi"], d1=orbit["durations"][0], d2=orbit["durations"][1])
assert len([n for n in stored if n in uz]) == len(stored) - 1, (list(uz), list(stored))  # the contact's velocity: none
for name, value in stored.items():
    assert name not in uz or abs(float(uz[name]) - value) <= 1e-12 * (1 + abs(value)), (name, uz[name], value)
PY
# A trace from a label where the type changes (GR4, with T0 and SK at the same point) switches there
# on its up chain, as the trace that stored the label did, instead of taking its own start for a loop.
"$bin" trace --results "$work/traces/chain" --point branch-2:GR4 --parameter omega --range 0.55,0.7 --output from-gr \
  > "$work/gr.txt" 2>&1 && grep -q "^  up: parameter-bound: reached omega = 0.7" "$work/gr.txt" &&
  grep -q "'slip+ / antisymmetric' up from switch at" "$work/gr.txt" && pass ||
  fail "a trace from a [model]'s change of type: $(cat "$work/gr.txt")"
expect 2 "--set is not taken at a [model]'s label ('branch-1:EP1')" "$bin" solve --results "$work/traces/chain" \
  --point branch-1:EP1 --set omega=0.5
expect 2 "holds a run of a linear-oscillator (a run file's [model]): valid here a run of the paper's oscillator" \
  "$bin" simulate --results "$work/traces/chain" --point branch-1:EP1
expect 2 "phi = 0.3 is invalid: the model has no forcing" "$bin" find --model "$models/belt.toml" --set phi=0.3
expect 5 "the motion has not settled (nor is any k <= 8 forcing periods a period of it) (--transients 2 periods now: more simulates longer)" \
  "$bin" find --model "$models/five-mass-chain.toml" --transients 2
expect 2 "results = '$work/out' is invalid: valid range with --output" "$bin" find --model "$models/belt.toml" --results "$work/out"
# A run file changed since the run no longer describes its model: export refuses the s. file.
sed 's|masses = \[1.0|masses = [1.5|' "$models/five-mass-chain.toml" > "$work/changed.toml"
"$bin" find --model "$work/changed.toml" --trace 0.55,0.6 --output changed --results "$work/traces" > /dev/null &&
  sed -i 's|masses = \[1.5|masses = [1.0|' "$work/changed.toml" && pass || fail "find --model changed.toml --trace"
expect 2 "is no periodic orbit of the model" "$bin" export --auto "$work/traces/changed/branch-1"
expect 2 "is no periodic orbit of the model" "$bin" continue --results "$work/traces/changed" --point branch-1:EP1 \
  --parameter omega --range 0.5,0.7 --output z
# A stored run's relative run file is found from any working directory: above the results, where the
# run was made (as tools/run.sh makes results/ at the repository's root).
mkdir -p "$work/project/continuation-scripts" "$work/project/results" &&
  cp -r "$models" "$work/project/continuation-scripts/" &&
  cp -r "$root/results/models/five-mass-chain-omega-trace" "$work/project/results/" &&
  (cd / && "$bin" continue --results "$work/project/results/five-mass-chain-omega-trace" --point branch-1:EP1 \
    --parameter F_k --range 0.2,0.4 --output from-elsewhere > /dev/null) &&
  [ -s "$work/project/results/five-mass-chain-omega-trace/from-elsewhere/branch.csv" ] && pass ||
  fail "a restart from a [model]'s label outside the directory it was made in"
expect 2 "output = '' is invalid" "$bin" find --model "$models/belt.toml" --trace 0.1,0.3 --output "" --results "$work/out"
# With --set the file is not the run's input: the command line is (as the paper's find writes it).
"$bin" find --model "$models/belt.toml" --set F_s=2 --trace 0.1,0.3 --output belt --results "$work/traces" > /dev/null &&
  grep -q '"run_file": "(command line)"' "$work/traces/belt/trace.json" &&
  grep -q '"run_file": "(command line)"' "$work/traces/belt/branch-1/summary.json" && pass ||
  fail "find --model --set --trace --output: the run file is not the command line"
"$bin" export --auto "$work/traces/chain/branch-1" > /dev/null && [ -s "$work/traces/chain/branch-1/s.branch-1" ] && pass ||
  fail "export --auto of a [model]'s run"
expect 2 "was computed from the command line (--set): its model is in no run file" \
  "$bin" export --auto "$work/traces/belt/branch-1"
expect 2 "cannot read the run file" "$bin" describe "$work/none.toml"
expect 2 "key 'model' is missing" "$bin" describe "$root/continuation-scripts/paper-5.1-omega-up.toml"
sed 's/^\[model\]/[modle]/' "$models/belt.toml" > "$work/modle.toml"
expect 2 "key 'model' is missing: give a [model] table (kind = \"chain\" or \"matrices\") ('modle' at " \
  "$bin" describe "$work/modle.toml"
expect 2 "\`stickslip describe\` and \`stickslip find --model\` take a [model]" \
  "$bin" run --results "$work/out" "$models/belt.toml"
# A [model]'s atlas: M. Pascal's two masses written as a chain reproduce the paper's own atlas's
# bifurcations (its committed intervals: PD at omega = 0.3499031780, SB at 0.3497430893, the fold at
# 0.6011956426); its files are an atlas's (each trace-<t> a trace's, atlas.json "model"); the same
# bytes on one thread and two; a re-run keeps the user's files; bad input writes nothing.
for t in 1 2; do
  "$bin" atlas --model "$models/paper-4.1-as-a-chain.toml" --range 0.3,0.65 --steps 14 --threads $t --output chain41 \
    --results "$work/atlas$t" > "$work/atlas$t.txt" 2> "$work/atlas$t.err" || fail "atlas --model (threads $t): $(cat "$work/atlas$t.err")"
done
diff -r "$work/atlas1/chain41" "$work/atlas2/chain41" > /dev/null && pass || fail "atlas --model: files differ for 1 and 2 threads"
# Its brute force is a one-row map file (omega along i, F_k held along j), which --merge reads back.
"$bin" map-sweep --merge "$work/atlas-map.csv" "$work/atlas1/chain41/brute-force.csv" > /dev/null &&
  cmp -s "$work/atlas-map.csv" "$work/atlas1/chain41/brute-force.csv" &&
  head -1 "$work/atlas-map.csv" | grep -q "^i,j,ni,nj,omega,F_k," && pass || fail "atlas --model: brute-force.csv is no map file"
/usr/bin/python3 - "$work/atlas1/chain41" <<'PY' && pass || fail "atlas --model of the paper's masses as a chain"
import csv, json, sys
atlas = json.load(open(sys.argv[1] + "/atlas.json"))
assert atlas["model"] == "linear-oscillator" and atlas["parameter"] == "omega", atlas["parameter"]
counts = atlas["counts"]
assert counts["on_branches"] == counts["periodic_within_limit"] > 10, counts
rows = list(csv.DictReader(open(sys.argv[1] + "/atlas-intervals.csv")))
def located(label, value):
    return any(r[end].startswith(label) and abs(float(r[side]) - value) <= 1e-8
               for r in rows for end, side in (("first_label", "from"), ("last_label", "to")))
for label, value in (("PD", 0.34990317802386234), ("SB", 0.3497430892795275), ("LP", 0.60119564258631)):
    assert located(label, value), (label, value)
for grid in atlas["grid"]:
    for a in grid["attractors"]:
        assert a["fate"] != "on-branch" or a["amplitude:x2"] > 0, a
trace = json.load(open(sys.argv[1] + "/trace-1/trace.json"))
assert trace["model"] == "linear-oscillator" and len(trace["natural_frequencies"]) == 2, trace.keys()
PY
echo mine > "$work/atlas1/chain41/trace-1/NOTES.md"
"$bin" atlas --model "$models/paper-4.1-as-a-chain.toml" --range 0.3,0.65 --steps 14 --output chain41 \
  --results "$work/atlas1" > "$work/atlas1.txt" && grep -q "kept 1 other file(s) of .*: trace-1/NOTES.md" "$work/atlas1.txt" &&
  [ "$(cat "$work/atlas1/chain41/trace-1/NOTES.md")" = mine ] && pass ||
  fail "a second atlas --model did not keep the user's file: $(cat "$work/atlas1.txt")"
"$bin" plot "$work/atlas1/chain41" --output "$work/chain41.png" > /dev/null && [ -s "$work/chain41.png" ] && pass ||
  fail "stickslip plot of a [model]'s atlas"
"$bin" atlas --model "$models/belt-damped.toml" --parameter v_b --range 0.1,0.7 --steps 6 --transients 100 --output belt \
  --results "$work/atlas1" > "$work/belt.txt" && grep -q "^belt: .* 1 trace(s)" "$work/belt.txt" && pass ||
  fail "atlas --model of a belt: $(cat "$work/belt.txt")"
# Friction falling with the slip speed turns propulsive past about 3.3 m/s: the motion from rest grows
# without bound at v_b = 3, an attractor listed "incomplete" with the reason, not the end of the atlas.
"$bin" atlas --model "$models/belt-falling-friction.toml" --parameter v_b --range 0.1,3 --steps 3 --output falling \
  --results "$work/atlas1" > "$work/falling.txt" 2>&1 && grep -q "v_b = 3, attractor 2: incomplete: 1 run(s) stopped early" "$work/falling.txt" &&
  pass || fail "atlas --model with a motion growing without bound: $(cat "$work/falling.txt")"
expect 2 "parameter = 'omega' is invalid" "$bin" atlas --model "$models/belt.toml" --range 0.2,0.3 --output b --results "$work/out"
expect 2 "range = '0.5,1' is invalid: grid value omega = 1" \
  "$bin" atlas --model "$models/den-hartog.toml" --range 0.5,1 --steps 5 --output d --results "$work/out"
expect 2 "steps" "$bin" atlas --model "$models/den-hartog.toml" --range 1.5,2 --steps 100000000 --output d --results "$work/out"
expect 2 "max-multiple" "$bin" atlas --model "$models/den-hartog.toml" --range 1.5,2 --max-multiple 0 --output d --results "$work/out"
expect 2 "preset is not taken with --model" \
  "$bin" atlas --model "$models/den-hartog.toml" --preset paper-4.1 --range 1.5,2 --output d --results "$work/out"
expect 2 "output = '' is invalid" "$bin" atlas --model "$models/den-hartog.toml" --range 1.5,2 --output "" --results "$work/out"
mkdir -p "$work/out/mine"
expect 2 "holds no stickslip atlas" "$bin" atlas --model "$models/den-hartog.toml" --range 1.5,2 --output mine --results "$work/out"
# simulate --model: Den Hartog's mass after 100 forcing periods stops at +-X(r, beta), his closed form
# (V = 1/(1 - r^2), U = tan(pi/(2r))/r, X = sqrt(V^2 - beta^2 U^2)); the exact and the Odeint
# simulators agree on the belt's events; the CSV names the model's state columns.
"$bin" simulate --model "$models/den-hartog.toml" --transients 100 --periods 1 --json > "$work/dh-sim.json" &&
  "$bin" simulate --model "$models/belt.toml" --periods 3 --json > "$work/belt-exact.json" &&
  "$bin" simulate --model "$models/belt.toml" --periods 3 --json --method odeint > "$work/belt-odeint.json" &&
  "$bin" simulate --model "$models/belt.toml" --periods 1 --csv "$work/belt-sim.csv" > /dev/null && pass ||
  fail "simulate --model"
/usr/bin/python3 - "$work" <<'PY' && pass || fail "simulate --model against Den Hartog's closed form and Odeint"
import json, math, sys
work = sys.argv[1]
r, beta = 1.5, 0.25
V, U = 1 / (1 - r * r), math.tan(math.pi / (2 * r)) / r
X = math.sqrt(V * V - beta * beta * U * U)
events = json.load(open(work + "/dh-sim.json"))["events"]
assert len(events) == 2 and all(abs(abs(e["state"][0]) - X) <= 1e-9 for e in events), (events, X)
assert all(e["t"] >= 100 * 2 * math.pi / r for e in events), events
exact = json.load(open(work + "/belt-exact.json"))["events"]
odeint = json.load(open(work + "/belt-odeint.json"))["events"]
assert len(exact) == len(odeint) >= 4, (len(exact), len(odeint))
assert all(a["kind"] == b["kind"] and abs(a["t"] - b["t"]) <= 1e-6 for a, b in zip(exact, odeint)), (exact, odeint)
assert open(work + "/belt-sim.csv").readline() == "t,m1,v_m1,mode\n"
PY
expect 2 "phi = 1 is invalid: the model has no forcing" "$bin" simulate --model "$models/belt.toml" --set phi=1
expect 2 "preset is not taken with --model" "$bin" simulate --model "$models/belt.toml" --preset paper-4.1
echo mine > "$work/out/notes.csv"
expect 2 "it exists and was not written by stickslip simulate" \
  "$bin" simulate --model "$models/belt.toml" --csv "$work/out/notes.csv"
expect 2 "periods" "$bin" simulate --model "$models/den-hartog.toml" --periods 0
expect 2 "set gives 'F_k' twice (0.1 and 0.2): give it once" \
  "$bin" simulate --model "$models/belt.toml" --set F_k=0.1 --set F_k=0.2
expect 2 "omega = 1000000000000 is invalid: the model has no forcing" "$bin" simulate --model "$models/belt.toml" --set omega=1e12
expect 2 "model = '' is invalid" "$bin" simulate --model ""
expect 2 "model = '' is invalid" "$bin" atlas --model "" --range 1,2 --output x --results "$work/out"
# A motion growing without bound: the exact simulator ends where it overflows, and nothing printed
# or written holds an infinity (--json stays JSON).
"$bin" simulate --model "$models/belt-falling-friction.toml" --set v_b=1e6 --periods 1000 --json > "$work/falling.json" \
  2> /dev/null; [ $? -eq 1 ] && /usr/bin/python3 -c "import json, sys; json.load(open(sys.argv[1]))" "$work/falling.json" &&
  pass || fail "simulate --model of a diverging motion: not valid JSON or not exit 1"
# map-sweep --model: Den Hartog's mass over (omega, F_k), his amplitude in every cell; two shards
# merged are the whole file (two MPI ranks': map_sweep_test.sh); plot draws it.
grid=(--first-from 1.2 --first-to 2 --first-steps 4 --second F_k --second-from 0.15 --second-to 0.25 --second-steps 2
      --set F_s=0.3 --starts 2)
"$bin" map-sweep --model "$models/den-hartog.toml" "${grid[@]}" --output "$work/dh-map.csv" > /dev/null &&
  "$bin" map-sweep --model "$models/den-hartog.toml" "${grid[@]}" --shard 2/2 --output "$work/dh-2.csv" > /dev/null &&
  "$bin" map-sweep --model "$models/den-hartog.toml" "${grid[@]}" --shard 1/2 --threads 1 --output "$work/dh-1.csv" \
    > /dev/null && "$bin" map-sweep --merge "$work/dh-merged.csv" "$work/dh-2.csv" "$work/dh-1.csv" > /dev/null &&
  cmp -s "$work/dh-map.csv" "$work/dh-merged.csv" && pass || fail "map-sweep --model: shards merged differ from the whole"
/usr/bin/python3 - "$work/dh-map.csv" <<'PY' && pass || fail "map-sweep --model against Den Hartog's closed form"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 15 and rows[0]["amplitude:m1"] and list(rows[0])[-3:] == ["k", "m1", "v_m1"], list(rows[0])
for r in rows:
    w, beta = float(r["omega"]), float(r["F_k"])
    V, U = 1 / (1 - w * w), math.tan(math.pi / (2 * w)) / w
    X = math.sqrt(V * V - beta * beta * U * U)
    assert r["status"] == "periodic" and r["period"] == "1" and r["sticks_per_period"] == "0", r
    assert abs(float(r["amplitude:m1"]) - X) <= 1e-6 * X, (r, X)
PY
"$bin" plot "$work/dh-map.csv" --output "$work/dh-map.png" > /dev/null && [ -s "$work/dh-map.png" ] && pass ||
  fail "plot of a model's map-sweep"
"$bin" map-sweep --preset paper-6 --first-from 0.55 --first-to 0.56 --first-steps 1 --second-from 1.3 --second-to 1.3 \
  --second-steps 0 --transients 10 --periods 4 --starts 0 --output "$work/paper-map.csv" > /dev/null
cp "$work/dh-map.csv" "$work/out/dh-map.csv"
expect 2 "paper-map.csv:1: the header is invalid" "$bin" map-sweep --merge "$work/out/merged.csv" "$work/dh-1.csv" \
  "$work/paper-map.csv"
expect 2 "preset is not taken with --model" "$bin" map-sweep --model "$models/den-hartog.toml" --preset paper-6 \
  "${grid[@]}" --output "$work/out/x.csv"
expect 2 "first = 'chi' is invalid: valid range omega, F_k, F_s, v_b" "$bin" map-sweep --model "$models/den-hartog.toml" \
  --first chi --first-from 1 --first-to 2 --second-from 0.1 --second-to 0.2 --output "$work/out/x.csv"
expect 2 "second = 'omega' is invalid" "$bin" map-sweep --model "$models/belt.toml" --first-from 0.2 --first-to 0.4 \
  --second omega --second-from 1 --second-to 2 --output "$work/out/x.csv"
expect 2 "grid cell (i, j) = (0, 2)" "$bin" map-sweep --model "$models/den-hartog.toml" --first-from 1.2 --first-to 2 \
  --second F_k --second-from 0.1 --second-to 0.3 --second-steps 2 --output "$work/out/x.csv"
expect 2 "first-steps" "$bin" map-sweep --model "$models/den-hartog.toml" "${grid[@]}" --first-steps 0 --output "$work/out/x.csv"
expect 2 "model = '' is invalid" "$bin" map-sweep --model "" "${grid[@]}" --output "$work/out/x.csv"
expect 2 "set F_k=0.2 is invalid: the map's second axis varies F_k" "$bin" map-sweep --model "$models/den-hartog.toml" \
  "${grid[@]}" --set F_k=0.2 --output "$work/out/x.csv"
expect 2 "--transients is not taken with --merge" "$bin" map-sweep --merge "$work/out/m.csv" "$work/dh-1.csv" \
  "$work/dh-2.csv" --transients 7
cp "$models/den-hartog.toml" "$work/out/dh.toml"
expect 2 "it is the run file --model reads" "$bin" map-sweep --model "$work/out/dh.toml" "${grid[@]}" \
  --output "$work/out/./dh.toml" --force
expect 2 "it is the run file --model reads" "$bin" sweep --model "$work/out/dh.toml" --from 1.5 --to 2 \
  --output "$work/out/dh.toml" --force
echo mine > "$work/out/notes.csv"
expect 2 "it exists and was not written by stickslip map-sweep" "$bin" map-sweep --model "$models/den-hartog.toml" \
  "${grid[@]}" --output "$work/out/notes.csv"
sed 's/,periodic,/,cyclic,/' "$work/dh-map.csv" > "$work/out/damaged.csv"
expect 2 "damaged.csv:2: column 'status' = 'cyclic' is invalid" "$bin" plot "$work/out/damaged.csv" --output "$work/x.png"
finish
