"""Branches from Python: continue_orbit, run, the Continuation stepped by hand, and the result
files, against the command line's files byte for byte."""
import numpy as np
import pytest

import stickslip
from conftest import RESULTS, SOURCE, cli

# The run of continuation-scripts/paper-5.1-omega-up.toml as keywords, and as `stickslip continue`.
KEYWORDS = dict(preset="paper-5.1", ds=0.005, ds_max=0.05, max_points=3000, user_values=[0.58])
FLAGS = ["--preset", "paper-5.1", "--parameter", "omega", "--range", "0.3,0.9", "--ds", "0.005", "--ds-max", "0.05",
         "--max-points", "3000"]
FILES = ("branch.csv", "special-points.csv", "summary.json")


def read_files(directory):
    return {name: (directory / name).read_bytes() for name in FILES}


def test_continue_orbit_saves_the_files_of_stickslip_continue(tmp_path):
    # `continue` has no user values: the run without them.
    keywords = {k: v for k, v in KEYWORDS.items() if k != "user_values"}
    branch = stickslip.continue_orbit("omega", (0.3, 0.9), output="run", **keywords)
    done = cli("continue", *FLAGS, "--output", "run", "--results", tmp_path / "cli")
    assert done.returncode == 0, done.stderr
    assert branch.save(tmp_path / "python" / "run") == []
    assert read_files(tmp_path / "python" / "run") == read_files(tmp_path / "cli" / "run")
    assert {k: v.encode() for k, v in branch.files().items()} == read_files(tmp_path / "cli" / "run")


@pytest.mark.parametrize("run", ["paper-5.1-omega-up", "paper-6-omega-up", "paper-4.2-omega-up"])
def test_a_run_file_gives_the_stored_results_byte_for_byte(run, tmp_path, monkeypatch):
    # The stored results were written by `stickslip run continuation-scripts/<run>.toml` from the
    # source tree, which records that path.
    monkeypatch.chdir(SOURCE)
    branch = stickslip.run(f"continuation-scripts/{run}.toml")
    branch.save(tmp_path / run)
    assert read_files(tmp_path / run) == read_files(RESULTS / run)


def test_columns_are_the_files_numbers_and_special_points_are_labelled():
    branch = stickslip.continue_orbit("omega", (0.3, 0.9), **KEYWORDS)
    assert len(branch) == 106 and len(branch["omega"]) == 106
    assert branch.columns[:3] == ["pt", "label", "chi"]
    assert branch["pt"][0] == 1 and branch["label"][0] == "EP1"
    # lib/python/README.md's special points, then the end, at the last located point, with a label of its own.
    labels = [s["label"] for s in branch.special_points]
    assert labels == ["EP1", "TR2", "UZ3", "LP4", "UZ5", "GR6", "EP7"]
    assert [s["type"] for s in branch.special_points] == ["EP", "TR", "UZ", "LP", "UZ", "GR", "EP"]
    lp = branch.special_point("LP4")
    assert lp["type"] == "LP" and lp["located"] == 1
    assert abs(lp["omega"] - 0.5868188661) < 1e-9  # the value lib/python/README.md and README.md give
    assert branch.termination == "terminal-event"
    # The file's labels mark the same rows (the end shares GR6's row).
    for s in branch.special_points[1:-1]:
        assert branch["label"][s["pt"] - 1] == s["label"]
    t, x = branch.sample(-1, 50)
    assert x.shape == (50, 4) and t[-1] > 0
    assert abs(branch["x10"][-1] - x[0, 0]) < 1e-14
    # The orbit's measures, after `admissible`: the counts as integers, the amplitudes bounding the
    # sampled orbit of each row.
    measures = ["amplitude:x1", "amplitude:x2", "peak-to-peak:x2", "stick-fraction", "stops", "sticks",
                "friction-work", "equivalent-damping"]
    at = branch.columns.index("admissible")
    assert branch.columns[at + 1:at + 9] == measures
    assert branch["stops"].dtype.kind == "i" and set(branch["stops"]) == {3} and set(branch["sticks"]) == {1}
    for i in (0, len(branch) // 2, len(branch) - 1):
        _, x = branch.sample(i, 2000)
        assert np.max(np.abs(x[:, 0])) <= branch["amplitude:x1"][i] + 1e-12
        assert np.max(np.abs(x[:, 0])) >= branch["amplitude:x1"][i] - 1e-4
        assert np.ptp(x[:, 1]) <= branch["peak-to-peak:x2"][i] + 1e-12


def test_save_and_load_round_trip_byte_for_byte(tmp_path):
    branch = stickslip.continue_orbit("omega", (0.5, 0.6), preset="paper-6", max_points=20)
    branch.save(tmp_path / "paper-6-short")
    loaded = stickslip.Branch.load(tmp_path / "paper-6-short")
    assert loaded.output == "paper-6-short"
    assert loaded.files()["branch.csv"] == branch.files()["branch.csv"]
    assert loaded.files()["special-points.csv"] == branch.files()["special-points.csv"]
    assert (loaded["omega"] == branch["omega"]).all()


def test_a_stepped_continuation_gives_the_branch_of_one_run():
    whole = stickslip.continue_orbit("omega", (0.3, 0.9), **KEYWORDS)
    cont = stickslip.Continuation("omega", (0.3, 0.9), **KEYWORDS)
    points = []
    for point in cont:
        points.append(point)
        if point["omega"] > 0.58:
            break  # stop, inspect, go on
    assert not cont.ended and cont.end == "running"
    assert len(cont) >= len(points)
    middle = cont.branch()
    assert middle.files()["branch.csv"].splitlines() == whole.files()["branch.csv"].splitlines()[: len(middle) + 1]
    points += list(cont)
    assert cont.ended and cont.end == whole.termination
    assert len(points) == len(whole)
    assert [p["omega"] for p in points] == list(whole["omega"])
    assert [p["label"] for p in points] == list(whole["label"])
    assert cont.branch().files() == whole.files()
    # The stepping ends where one call ends.
    assert not cont.step()


def test_a_resonance_ends_the_branch_called_whole_or_stepped_as_the_command_line(tmp_path):
    # The §4.1 orbit continued up towards omega1 = 0.7012302: it ends at its first point whose
    # amplitude passes max_amplitude, in one call, stepped by hand, and as `stickslip continue`.
    keywords = dict(preset="paper-4.1", ds=0.01, ds_max=1.0, max_amplitude=20.0, output="res")
    whole = stickslip.continue_orbit("omega", (0.3, 0.8), **keywords)
    assert whole.termination == "stopped" and whole.summary["message"].startswith("resonance: the amplitude")
    amplitude = np.maximum(whole["amplitude:x1"], whole["amplitude:x2"])
    assert amplitude[-1] > 20.0 and amplitude[:-1].max() <= 20.0
    # Without the bound, it ends within 1 % of omega1, which it approaches never sticking.
    near = stickslip.continue_orbit("omega", (0.3, 0.8), preset="paper-4.1", ds=0.01, ds_max=1.0)
    assert near.summary["message"].startswith("resonance: at omega_1 = 0.7012301669")
    assert 0.99 * 0.7012302 <= near["omega"][-1] < 0.7012302
    # resonance_approach=0 turns that off: the amplitude's bound ends it.
    far = stickslip.continue_orbit("omega", (0.3, 0.8), preset="paper-4.1", ds=0.01, ds_max=1.0,
                                   resonance_approach=0.0, max_amplitude=200.0)
    assert far.summary["message"].startswith("resonance: the amplitude") and far["omega"][-1] > 0.6942
    with pytest.raises(ValueError, match="resonance-approach"):
        stickslip.continue_orbit("omega", (0.3, 0.8), preset="paper-4.1", resonance_approach=1.0)
    cont = stickslip.Continuation("omega", (0.3, 0.8), **keywords)
    assert len(list(cont)) == len(whole) and cont.end == "stopped"
    assert cont.branch().files() == whole.files()
    done = cli("continue", "--preset", "paper-4.1", "--parameter", "omega", "--range", "0.3,0.8", "--ds", "0.01",
               "--ds-max", "1", "--max-amplitude", "20", "--output", "res", "--results", tmp_path)
    assert done.returncode == 0, done.stderr
    assert {k: v.encode() for k, v in whole.files().items()} == read_files(tmp_path / "res")
    for bad in (0.0, -1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="max-amplitude"):
            stickslip.continue_orbit("omega", (0.3, 0.8), preset="paper-4.1", max_amplitude=bad)


def test_a_continuation_restarts_from_a_labelled_point_as_the_command_line(tmp_path):
    results = tmp_path / "results"
    stored = results / "paper-5.1-omega-up"
    stored.mkdir(parents=True)
    for name in FILES:
        (stored / name).write_bytes((RESULTS / "paper-5.1-omega-up" / name).read_bytes())
    branch = stickslip.continue_orbit("omega", (0.3, 0.9), point="paper-5.1-omega-up:TR2", results=results,
                                      direction="down", output="from-tr")
    done = cli("continue", "--point", "paper-5.1-omega-up:TR2", "--results", results, "--parameter", "omega",
               "--direction", "down", "--range", "0.3,0.9", "--output", "from-tr")
    assert done.returncode == 0, done.stderr
    assert {k: v.encode() for k, v in branch.files().items()} == read_files(results / "from-tr")


def test_a_start_that_does_not_converge_raises_convergence_error(tmp_path):
    guess = {"d1": 0.05, "d2": 0.5, "d3": 0.05, "d4": 0.05}
    with pytest.raises(stickslip.ConvergenceError) as error:
        stickslip.continue_orbit("omega", (0.3, 0.9), preset="paper-5.1", guess=guess, output="t")
    assert error.value.summary["termination"] == "start-failed"
    with pytest.raises(stickslip.ConvergenceError):
        stickslip.Continuation("omega", (0.3, 0.9), preset="paper-5.1", guess=guess).step()
    done = cli("continue", "--preset", "paper-5.1", "--parameter", "omega", "--range", "0.3,0.9", "--output", "t",
               "--results", tmp_path, *sum((["--guess", f"{k}={v}"] for k, v in guess.items()), []))
    assert done.returncode == 3
    assert done.stderr.strip() == f"error: {error.value}"


def test_to_pandas_gives_the_columns():
    pandas = pytest.importorskip("pandas")
    branch = stickslip.continue_orbit("omega", (0.5, 0.6), preset="paper-5.1", max_points=5)
    frame = branch.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == branch.columns and (frame["omega"].to_numpy() == branch["omega"]).all()


def test_a_run_file_stepped_gives_the_branch_of_one_run(monkeypatch):
    monkeypatch.chdir(SOURCE)
    cont = stickslip.Continuation.from_run_file("continuation-scripts/paper-6-omega-down.toml")
    assert cont.step() and len(cont) == 1 and cont.point(0)["label"] == "EP1"
    assert cont.run().files() == stickslip.run("continuation-scripts/paper-6-omega-down.toml").files()


def test_to_pandas_without_pandas_says_what_is_missing():
    try:
        import pandas  # noqa: F401
        pytest.skip("pandas is installed")
    except ImportError:
        pass
    branch = stickslip.continue_orbit("omega", (0.5, 0.6), preset="paper-5.1", max_points=3)
    with pytest.raises(ImportError, match="python3-pandas"):
        branch.to_pandas()


def test_misuse_raises_python_errors_and_never_crashes():
    cont = stickslip.Continuation("omega", (0.5, 0.6), preset="paper-5.1", max_points=3)
    with pytest.raises(IndexError):
        cont.point(0)  # nothing computed yet
    branch = cont.run()
    with pytest.raises(IndexError):
        cont.point(99)
    with pytest.raises(IndexError):
        branch.sample(99)
    with pytest.raises(ValueError, match="n = 1 is invalid"):
        branch.sample(0, 1)
    with pytest.raises(KeyError, match="valid columns"):
        branch["omgea"]
    with pytest.raises(TypeError):
        stickslip.simulate(stickslip.presets["paper-5.1"].parameters, state=(1, 2, 3))
    with pytest.raises(TypeError):
        stickslip.solve(preset="paper-5.1", guess=[("d1", 3.0)])
    with pytest.raises(TypeError):
        stickslip.continue_orbit("omega", (0.5,), preset="paper-5.1")
    with pytest.raises(TypeError):
        stickslip.Continuation("omega", (0.5, 0.6), preset="paper-5.1", bogus=1)
    assert not cont.step() and cont.ended


def test_ctrl_c_ends_a_long_continuation_between_steps():
    import _thread
    import threading
    import time

    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    started = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        # About 1e5 points of 1e-6 in arclength: minutes, unless interrupted.
        stickslip.continue_orbit("omega", (0.3, 0.9), preset="paper-5.1", ds=1e-6, ds_min=1e-8, ds_max=1e-6,
                                 max_points=1000000)
    timer.join()
    assert time.perf_counter() - started < 30


def test_the_end_names_the_parameter_and_its_rounded_value():
    # Not "reached lambda_min = 0.19999999999999993": the parameter's name and the bound as given.
    for parameter, bounds, direction, message in (("omega", (0.6, 0.62), "up", "reached omega = 0.62"),
                                                  ("u_r", (0.2, 0.3), "down", "reached u_r = 0.2")):
        branch = stickslip.continue_orbit(parameter, bounds, preset="paper-4.1", direction=direction)
        assert branch.termination == "parameter-bound" and branch.message == message, branch.message


def test_an_end_short_of_the_range_says_which_physical_bound_ended_it():
    # Section 4.1's data have u_s = 0.1: the static level u_r, continued downwards with u_s held,
    # stops where it meets it (eq. 4), short of the range's 0.01, and the message says why.
    branch = stickslip.continue_orbit("u_r", (0.01, 0.3), preset="paper-4.1", direction="down")
    assert branch.termination == "parameter-bound"
    assert branch.message == "reached u_r = 0.1 (u_r >= u_s = 0.1)", branch.message
