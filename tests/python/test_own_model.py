"""An oscillator of your own from Python, as from the command line: stickslip.describe is `stickslip
describe --json`, stickslip.find(model=...) is `stickslip find --model --json`; the mass on a belt
settles on the closed-form stick-slip cycle (../shared/FRICTION-LITERATURE.md); bad input raises
ValueError with the command line's message."""
import math

import pytest

import stickslip
from conftest import RESULTS, SOURCE, cli, cli_error, cli_json

MODELS = SOURCE / "continuation-scripts" / "models"


def test_describe_is_the_command_lines_json():
    described = stickslip.describe(MODELS / "five-mass-chain.toml")
    assert described == cli_json("describe", MODELS / "five-mass-chain.toml", "--json")
    assert described["coordinates"] == ["m1", "m2", "m3", "m4", "m5"] and described["contact"] == "m5"
    units = {p["name"]: p["unit"] for p in described["parameters"]}
    assert units == {"omega": "rad/s", "F_k": "N", "F_s": "N", "v_b": "m/s"}
    assert described["units"] == {"length": "m", "time": "s", "force": "N"}


@pytest.mark.parametrize("v_b", [0.2, 0.9])
def test_finds_the_belts_closed_form_stick_slip_cycle(v_b):
    found = stickslip.find(model=MODELS / "belt.toml", set={"v_b": v_b})
    assert found.found, found.message
    o = found.orbit
    d, w = (1.5 - 1.0) / 1.0, 1.0
    stick, slip = 2 * d / v_b, (math.pi + 2 * math.atan(v_b / (w * d))) / w
    assert o["signature"] == "stick slip-"
    assert o["durations"][0] == pytest.approx(stick, rel=1e-10)
    assert o["durations"][1] == pytest.approx(slip, rel=1e-10)
    assert o["measures"]["amplitude:m1"] == pytest.approx(1.0 + math.hypot(d, v_b / w), abs=1e-10)


def test_find_is_the_command_lines_json():
    found = stickslip.find(model=MODELS / "three-mass-matrices.toml", transients=300)
    done = cli("find", "--model", MODELS / "three-mass-matrices.toml", "--transients", 300, "--json")
    assert done.returncode == 0, done.stderr
    import json
    assert found == stickslip.ModelFound(**json.loads(done.stdout))


def test_bad_input_raises_the_command_lines_message():
    with pytest.raises(ValueError) as python:
        stickslip.find(model=MODELS / "belt.toml", set={"Omega": 1.0})
    assert str(python.value) == cli_error("find", "--model", MODELS / "belt.toml", "--set", "Omega=1")
    with pytest.raises(ValueError, match="cannot read the run file"):
        stickslip.describe(MODELS / "none.toml")
    with pytest.raises(ValueError, match="transients"):
        stickslip.find(model=MODELS / "belt.toml", transients=0)
    with pytest.raises(ValueError, match="preset is invalid with model="):
        stickslip.find(model=MODELS / "belt.toml", preset="paper-5.1")
    with pytest.raises(ValueError, match="set"):
        stickslip.find(model=MODELS / "belt.toml", set=[("v_b", 1.0)])
    with pytest.raises(ValueError, match="v_b"):
        stickslip.find(model=MODELS / "belt.toml", set={"v_b": True})


def test_trace_is_the_command_lines_json_and_saves_its_files(tmp_path):
    traced = stickslip.trace("v_b", (0.1, 1.0), model=MODELS / "belt-damped.toml", max_branches=4)
    done = cli("find", "--model", MODELS / "belt-damped.toml", "--trace", "0.1,1.0", "--trace-parameter", "v_b",
               "--json", "--output", "belt", "--results", tmp_path / "cli")
    assert done.returncode == 0, done.stderr
    import json
    assert traced == json.loads(done.stdout)
    assert traced["up"]["end"] == "no-adjacent-type"
    assert traced.save(tmp_path / "python" / "belt") == []
    written = sorted(p.relative_to(tmp_path / "cli") for p in (tmp_path / "cli").rglob("*") if p.is_file())
    assert len(written) >= 5, written
    for name in written:
        assert (tmp_path / "python" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    import copy, pickle
    assert pickle.loads(pickle.dumps(traced)) == traced and copy.deepcopy(traced) == traced
    loaded = stickslip.Trace.load(tmp_path / "python" / "belt")
    assert len(loaded.files()["trace.csv"].splitlines()) == 1 + sum(
        len(b["points"]) for d in ("down", "up") for b in traced[d]["branches"])
    # .trace is the same trace as a Trace (named "trace" until saved), which plot() draws.
    assert traced.trace.files()["trace.csv"] == loaded.files()["trace.csv"]
    assert traced.plot().axes
    with pytest.raises(TypeError, match="shooting"):
        stickslip.trace("v_b", (0.1, 1.0), model=MODELS / "belt-damped.toml", shooting="single")


def test_a_models_label_switches_branch_as_a_run_file_does(tmp_path):
    # The five-mass chain's antisymmetric period-3 orbit breaks its symmetry at SB2 (omega = 0.37506):
    # continue_orbit(switch_branch=True) from the saved label is the run file's restart with
    # switch_branch = true, byte for byte, on the whole period's type.
    chain = tmp_path / "chain38.toml"
    chain.write_text((MODELS / "five-mass-chain.toml").read_text().replace("omega = 0.6,", "omega = 0.38,"))
    stickslip.trace("omega", (0.374, 0.38), model=chain).save(tmp_path / "sb")
    branch = stickslip.continue_orbit(point="branch-1:SB2", results=tmp_path / "sb", switch_branch=True,
                                      parameter="omega", range=(0.37, 0.38), direction="down", output="switched")
    assert branch.signature == "stick slip+ stick slip+ stick slip- stick slip- / period 3"
    # Off the antisymmetric family: the contact's peak-to-peak is no longer twice its amplitude.
    assert abs(2 * branch["amplitude:m5"][-1] - branch["peak-to-peak:m5"][-1]) > 0.05 * branch["amplitude:m5"][-1]
    branch.save(tmp_path / "sb" / "python")
    (tmp_path / "switch.toml").write_text('output = "switched"\n[start]\nrestart = { run = "branch-1", label = "SB2", '
                                          'switch_branch = true }\n[continuation]\nparameter = "omega"\n'
                                          'direction = "down"\nrange = [0.37, 0.38]\n')
    done = cli("run", "--results", tmp_path / "sb", tmp_path / "switch.toml")
    assert done.returncode == 0, done.stderr
    for name in ("branch.csv", "special-points.csv"):
        assert (tmp_path / "sb" / "python" / name).read_bytes() == (tmp_path / "sb" / "switched" / name).read_bytes()


def test_trace_takes_the_steps_of_its_branches_as_the_command_line():
    # max_points and ds_max as find --model --trace's --max-points and --ds-max: the same JSON, and
    # every branch within its points; bad steps raise the command line's message.
    traced = stickslip.trace("v_b", (0.1, 1.0), model=MODELS / "belt-damped.toml", max_points=4, ds_max=0.02)
    import json
    assert traced == json.loads(cli("find", "--model", MODELS / "belt-damped.toml", "--trace", "0.1,1.0", "--max-points",
                                    4, "--ds-max", 0.02, "--json").stdout)
    branches = [b for d in ("down", "up") for b in traced[d]["branches"]]
    assert all(len(b["points"]) <= 4 for b in branches) and any(b["end"] == "max-points" for b in branches)
    with pytest.raises(ValueError) as python:
        stickslip.trace("v_b", (0.1, 1.0), model=MODELS / "belt-damped.toml", ds=0.1)
    assert str(python.value) == cli_error("find", "--model", MODELS / "belt-damped.toml", "--trace", "0.1,1.0", "--ds", 0.1)
    with pytest.raises(ValueError, match="max-points"):
        stickslip.trace("v_b", (0.1, 1.0), model=MODELS / "belt-damped.toml", max_points=0)


def test_trace_from_a_models_label_is_the_command_lines_and_passes_the_found_orbit(tmp_path):
    # The five-mass chain's trace in omega, saved; from its EP1 (omega = 0.6) a trace in F_s through
    # F_s = 0.5 (a user value), whose orbit there the motion from rest settles on (find: a simulation
    # and its own solve), and which `stickslip trace --point` writes byte for byte.
    chain = stickslip.trace("omega", (0.55, 0.7), model=MODELS / "five-mass-chain.toml")
    chain.save(tmp_path / "chain")
    traced = stickslip.trace("F_s", (0.3, 0.8), point="branch-1:EP1", results=tmp_path / "chain", user_values=[0.5])
    traced.save(tmp_path / "chain" / "python")
    done = cli("trace", "--results", tmp_path / "chain", "--point", "branch-1:EP1", "--parameter", "F_s", "--range",
               "0.3,0.8", "--user-value", "F_s=0.5", "--output", "cli")
    assert done.returncode == 0, done.stderr
    for name in ("trace.csv", "trace.json", "branch-2/branch.csv", "branch-2/special-points.csv"):
        python, written = (tmp_path / "chain" / "python" / name).read_text(), (tmp_path / "chain" / "cli" / name).read_text()
        assert python.replace('"python"', '"cli"') == written, name
    found = stickslip.find(model=MODELS / "five-mass-chain.toml", set={"F_s": 0.5}).orbit
    up = traced.branches[-1]
    at = [i for i, label in enumerate(up["label"]) if label.startswith("UZ")]
    assert len(at) == 1 and up.signature == found["signature"]
    for name, value in found["start"].items():
        if name != "v_m5_0":  # the contact's velocity, no variable
            assert up[name][at[0]] == pytest.approx(value, abs=1e-9)
    assert up["phi"][at[0]] == pytest.approx(found["phi"], abs=1e-9)
    with pytest.raises(ValueError) as python:
        stickslip.trace("F_s", (0.3, 0.8), point="branch-1:EP1", results=tmp_path / "chain", set={"omega": 0.5})
    assert str(python.value) == cli_error("trace", "--results", tmp_path / "chain", "--point", "branch-1:EP1",
                                          "--parameter", "F_s", "--range", "0.3,0.8", "--set", "omega=0.5", "--output", "x")
    # continue_orbit from the label: the branch `stickslip continue --point` writes, byte for byte.
    branch = stickslip.continue_orbit(point="branch-1:EP1", results=tmp_path / "chain", parameter="F_s",
                                      range=(0.3, 0.8), output="up")
    assert branch.save(tmp_path / "chain" / "up") == []
    done = cli("continue", "--results", tmp_path / "chain", "--point", "branch-1:EP1", "--parameter", "F_s",
               "--range", "0.3,0.8", "--output", "cli-up")
    assert done.returncode == 0, done.stderr
    for name in ("branch.csv", "special-points.csv"):
        assert (tmp_path / "chain" / "up" / name).read_bytes() == (tmp_path / "chain" / "cli-up" / name).read_bytes()
    with pytest.raises(ValueError, match="valid range a label of a saved branch for a \\[model\\]'s"):
        branch.switch("EP1")
    # solve at the UZ label (F_s = 0.5): the orbit the motion from rest settles on (find's), and what
    # `stickslip solve --point --json` prints; a start keyword beside it is refused.
    uz = (tmp_path / "chain" / "python", f"branch-{len(traced.branches)}:{up['label'][at[0]]}")
    solved = stickslip.solve(point=uz[1], results=uz[0])
    assert solved.found and solved.signature == found["signature"]
    for name, value in found["start"].items():
        assert solved.orbit["start"][name] == pytest.approx(value, abs=1e-9), name
    assert solved.orbit == cli_json("solve", "--results", uz[0], "--point", uz[1], "--json")["orbit"]
    with pytest.raises(ValueError, match="free is invalid with a \\[model\\]'s point"):
        stickslip.solve(point=uz[1], results=uz[0], free="F_s")


def test_a_models_type_boundary_is_the_run_files_curve_byte_for_byte():
    # continuation-scripts/curves/two-masses-sk-boundary.toml from SK2 of the two masses' trace.
    branch = stickslip.two_parameter("omega", "F_s", (30.0, 60.1), point="branch-1:SK2",
                                     results=RESULTS / "models" / "two-masses-omega-trace", direction="down", ds=0.2,
                                     ds_max=0.5, max_points=400, output="two-masses-sk-boundary")
    stored = RESULTS / "models" / "two-masses-omega-trace" / "two-masses-sk-boundary"
    files = branch.files()
    assert files["branch.csv"] == (stored / "branch.csv").read_text()
    assert files["special-points.csv"] == (stored / "special-points.csv").read_text()
    assert all(abs(branch["margin:reversal:1"]) < 1e-9)  # the force at the stops held at the static level
    assert branch["F_s"][-1] < branch["F_s"][0]
    with pytest.raises(ValueError) as error:
        stickslip.two_parameter("omega", "chi", (30.0, 60.1), point="branch-1:SK2",
                                results=RESULTS / "models" / "two-masses-omega-trace")
    assert str(error.value).startswith("boundary = 'chi' is invalid: valid range F_k, F_s, v_b")
    for second in ("", None):
        with pytest.raises(ValueError) as error:
            stickslip.two_parameter("omega", second, (30.0, 60.1), point="branch-1:SK2",
                                    results=RESULTS / "models" / "two-masses-omega-trace")
        assert "second = " in str(error.value) and "is invalid" in str(error.value)
    with pytest.raises(ValueError) as error:  # as the command line's --range
        stickslip.two_parameter("omega", "F_s", (30.0, float("inf")), point="branch-1:SK2",
                                results=RESULTS / "models" / "two-masses-omega-trace")
    assert "MIN < MAX, both finite" in str(error.value)


def test_sweep_is_the_command_lines_file(tmp_path):
    swept = stickslip.sweep(range=(1.5, 2.5), model=MODELS / "den-hartog.toml", steps=2, transients=400, periods=8,
                            start="fixed", chains=1)
    out = tmp_path / "dh.csv"
    done = cli("sweep", "--model", MODELS / "den-hartog.toml", "--from", 1.5, "--to", 2.5, "--steps", 2,
               "--transients", 400, "--periods", 8, "--start", "fixed", "--chains", 1, "--output", out)
    assert done.returncode == 0, done.stderr
    assert swept.csv() == out.read_text()
    assert swept.parameter == "omega" and swept.section.shape == (3, 8, 2)
    # Den Hartog's amplitude X = sqrt(V^2 - beta^2 U^2) at omega = 2: V = -1/3, U = 1/2, beta = 1/4.
    assert max(abs(swept.section[1, :, 0])) <= math.sqrt(1 / 9 - 1 / 64) + 1e-8
    with pytest.raises(ValueError) as python:
        stickslip.sweep(range=(0.2, 0.3), parameter="omega", model=MODELS / "belt.toml")
    assert str(python.value) == cli_error("sweep", "--model", MODELS / "belt.toml", "--parameter", "omega", "--from",
                                          0.2, "--to", 0.3, "--output", tmp_path / "belt.csv")
    with pytest.raises(ValueError, match="preset is invalid with model="):
        stickslip.sweep(range=(1.5, 2.5), model=MODELS / "den-hartog.toml", preset="paper-4.1")


def test_map_sweep_is_the_command_lines_file(tmp_path):
    mapped = stickslip.map_sweep(model=MODELS / "den-hartog.toml", first_range=(1.2, 2.0), first_steps=2,
                                 second="F_k", second_range=(0.15, 0.25), second_steps=1, starts=1,
                                 set={"F_s": 0.3})
    out = tmp_path / "dh-map.csv"
    done = cli("map-sweep", "--model", MODELS / "den-hartog.toml", "--first-from", 1.2, "--first-to", 2.0,
               "--first-steps", 2, "--second", "F_k", "--second-from", 0.15, "--second-to", 0.25, "--second-steps", 1,
               "--starts", 1, "--set", "F_s=0.3", "--output", out)
    assert done.returncode == 0, done.stderr
    assert mapped.csv() == out.read_text()
    assert stickslip.ModelMapSweepResult.load(out).csv() == mapped.csv()
    assert (mapped.first, mapped.second, mapped.shape) == ("omega", "F_k", (3, 2))
    a = mapped.attractors
    assert list(a["period"]) == [1] * 6 and a["section"][0].shape == (1, 2)
    # Den Hartog's amplitude in every cell, to the simulation's settling.
    for cell, amplitude in zip(a["cell"], a["amplitude:m1"]):
        r, beta = mapped.cells["omega"][cell], mapped.cells["F_k"][cell]
        V, U = 1 / (1 - r * r), math.tan(math.pi / (2 * r)) / r
        assert abs(amplitude - math.sqrt(V * V - beta * beta * U * U)) <= 1e-6 * amplitude
    with pytest.raises(ValueError) as python:
        stickslip.map_sweep(model=MODELS / "belt.toml", first_range=(0.2, 0.4), second="omega", second_range=(1, 2))
    assert str(python.value) == cli_error("map-sweep", "--model", MODELS / "belt.toml", "--first-from", 0.2,
                                          "--first-to", 0.4, "--second", "omega", "--second-from", 1, "--second-to", 2,
                                          "--output", tmp_path / "belt.csv")
    with pytest.raises(ValueError, match="point is invalid with model="):
        stickslip.map_sweep(model=MODELS / "den-hartog.toml", first_range=(1.2, 2), second_range=(0.3, 0.4),
                            point="x:EP1")


def test_find_reads_a_subharmonic_from_a_given_start(tmp_path):
    # Section 4.1's oscillator as a chain in physical units (m1 = 1, m2 = 1/eta, k1 = 1 - chi, k2 = chi,
    # forcing 1/eta on m2, F_k = u_s, F_s = u_r), started at the paper's preset state and phase: at
    # omega = 0.40 the motion settles on a period-2 orbit, as the paper's own finder reads it.
    model = tmp_path / "pascal.toml"
    model.write_text('[model]\nkind = "chain"\nmasses = [1.0, 0.25]\nnames = ["x1", "x2"]\n'
                     'springs = [{ between = ["x1", "ground"], k = 0.7 }, { between = ["x1", "x2"], k = 0.3 }]\n'
                     'forcing = { x2 = 0.25 }\ncontact = "x2"\nparameters = { omega = 0.4, F_k = 0.1, F_s = 0.2996 }\n')
    start = {"x1_0": 1.5608, "x2_0": 3.3295, "v1_0": 0.1523, "phi": 0.3925}
    found = stickslip.find(model=model, set=start)
    assert found.found, found.message
    assert found.orbit["signature"].endswith("/ period 2")
    paper = stickslip.find(preset="paper-4.1", set={"omega": 0.4})
    assert found.orbit["period"] == pytest.approx(paper.orbit.period, rel=1e-12)
    assert found.orbit["measures"]["amplitude:x2"] == pytest.approx(paper.orbit.measures["amplitude:x2"], rel=1e-9)
    assert not stickslip.find(model=model, set=start, max_multiple=1).found


def test_atlas_is_the_command_lines_files(tmp_path):
    """stickslip.atlas(model=...) writes the bytes `stickslip atlas --model` writes (but the run file,
    which records the Python call's output name as the command line's), and every attractor of the
    damped belt it solves lies on the one stick-slip branch up to the fold."""
    mapped = stickslip.atlas("v_b", (0.1, 0.7), model=MODELS / "belt-damped.toml", steps=6, transients=100,
                             output="belt")
    done = cli("atlas", "--model", MODELS / "belt-damped.toml", "--parameter", "v_b", "--range", "0.1,0.7",
               "--steps", 6, "--transients", 100, "--output", "belt", "--results", tmp_path / "cli")
    assert done.returncode == 0, done.stderr
    assert mapped.save(tmp_path / "python" / "belt") == []
    written = sorted(p.relative_to(tmp_path / "cli") for p in (tmp_path / "cli").rglob("*") if p.is_file())
    assert len(written) >= 8, written
    for name in written:
        assert (tmp_path / "python" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    assert mapped.json["model"] == "linear-oscillator"
    assert mapped.counts["on_branches"] == mapped.counts["periodic_within_limit"] > 0
    assert {a["exact_signature"] for a in mapped.attractors if a["fate"] == "on-branch"} == {"stick slip-"}
    with pytest.raises(ValueError, match="preset is invalid with model="):
        stickslip.atlas("v_b", (0.1, 0.7), model=MODELS / "belt-damped.toml", preset="paper-4.1")
    with pytest.raises(ValueError) as python:
        stickslip.atlas("omega", (0.2, 0.3), model=MODELS / "belt.toml")
    assert str(python.value) == cli_error("atlas", "--model", MODELS / "belt.toml", "--range", "0.2,0.3",
                                          "--output", "x", "--results", tmp_path / "none")


def test_simulate_is_the_command_lines_events():
    """stickslip.simulate(model=...) gives the events `stickslip simulate --model --json` prints, its
    states of the model's size, and Den Hartog's stops at +-X(r, beta) after the transient."""
    simulated = stickslip.simulate(model=MODELS / "belt.toml", periods=3, set={"v_b": 0.3})
    done = cli_json("simulate", "--model", MODELS / "belt.toml", "--periods", 3, "--set", "v_b=0.3", "--json")
    assert len(done["events"]) == len(simulated.events["t"]) >= 4
    for k, e in enumerate(done["events"]):
        assert e["t"] == simulated.events["t"][k] and e["kind"] == simulated.events["kind"][k]
        assert list(simulated.events["state"][k]) == e["state"]
    assert simulated.state_names == ["m1", "m1'"] and simulated.samples["state"].shape[1] == 2
    assert simulated.parameters == {"omega": 1.0, "F_k": 1.0, "F_s": 1.5, "v_b": 0.3}
    r, beta = 1.5, 0.25
    V, U = 1 / (1 - r * r), math.tan(math.pi / (2 * r)) / r
    dh = stickslip.simulate(model=MODELS / "den-hartog.toml", periods=200)
    last = dh.events["state"][-2:, 0]
    assert max(abs(abs(last) - math.sqrt(V * V - beta * beta * U * U))) <= 1e-9, last
    with pytest.raises(ValueError, match="preset is invalid with model="):
        stickslip.simulate(model=MODELS / "belt.toml", preset="paper-4.1")
