"""Brute-force maps from Python: the command line's CSV byte for byte, the arrays the file's
numbers, the same map on any number of threads, the threads used, and bad input refused with the
command line's one-line message."""
import numpy as np
import pytest

import stickslip
from conftest import cli, cli_error
from test_sweep import most_threads_during

MAP = dict(preset="paper-6", first="omega", first_range=(0.55, 0.6), first_steps=3, second="u_r",
           second_range=(1.2, 1.5), second_steps=2, transients=30, periods=6, starts=2)
OPTIONS = {"--preset": "paper-6", "--first": "omega", "--first-from": "0.55", "--first-to": "0.6", "--first-steps": "3",
           "--second": "u_r", "--second-from": "1.2", "--second-to": "1.5", "--second-steps": "2",
           "--transients": "30", "--periods": "6", "--starts": "2"}


def flags(**changes):
    """The map's options, with some replaced or added (--first-steps as first_steps=)."""
    options = dict(OPTIONS, **{"--" + key.replace("_", "-"): value for key, value in changes.items()})
    return [text for pair in options.items() for text in pair]


FLAGS = flags()


def test_a_map_gives_the_command_line_csv_byte_for_byte(tmp_path):
    result = stickslip.map_sweep(**MAP)
    done = cli("map-sweep", *FLAGS, "--output", tmp_path / "map.csv")
    assert done.returncode == 0, done.stderr
    expected = (tmp_path / "map.csv").read_text()
    assert result.csv() == expected
    result.save(tmp_path / "saved.csv")
    assert (tmp_path / "saved.csv").read_text() == expected
    assert stickslip.MapSweepResult.load(tmp_path / "map.csv").csv() == expected


def test_the_arrays_hold_the_files_cells_and_attractors(tmp_path):
    result = stickslip.map_sweep(**MAP)
    assert result.first == "omega" and result.second == "u_r" and result.shape == (4, 3) and len(result) == 12
    cells, attractors = result.cells, result.attractors
    # By j then i; the axes' values from the range, the last one exactly `to`.
    assert list(cells["i"]) == [0, 1, 2, 3] * 3 and list(cells["j"]) == [0] * 4 + [1] * 4 + [2] * 4
    assert cells["omega"][0] == 0.55 and cells["omega"][3] == 0.6 and cells["u_r"][11] == 1.5
    assert cells["attractors"].sum() == len(attractors["cell"])
    # The file's rows: one per section point of each attractor (one for a motion that did not settle).
    rows = result.csv().splitlines()[1:]
    points = sum(max(1, s.shape[0]) for s in attractors["section"])
    assert len(rows) == points
    first = dict(zip(result.csv().splitlines()[0].split(","), rows[0].split(",")))
    assert int(first["attractors"]) == cells["attractors"][0] and first["status"] == attractors["status"][0]
    assert int(first["period"]) == attractors["period"][0] and int(first["starts"]) == attractors["starts"][0]
    assert float(first["x1"]) == attractors["section"][0][0, 0]
    for status, period, section in zip(attractors["status"], attractors["period"], attractors["section"]):
        assert section.shape == ((period, 4) if status == "periodic" else (1, 4))


def test_the_map_does_not_depend_on_the_threads():
    assert stickslip.map_sweep(**MAP, threads=1).csv() == stickslip.map_sweep(**MAP, threads=2).csv()


def test_a_map_from_python_runs_on_several_threads_with_the_gil_released():
    work = dict(MAP, transients=500)  # long enough (0.2 s) for the sampling thread to see the workers
    one = most_threads_during(lambda: stickslip.map_sweep(**work, threads=1))
    two = most_threads_during(lambda: stickslip.map_sweep(**work, threads=2))
    # The caller is one worker: threads=2 adds one thread. (The sampling thread runs only because
    # the map releases the GIL.)
    assert two == one + 1


@pytest.mark.parametrize("change, options", [
    (dict(first_steps=2.5), dict(first_steps="2.5")),
    (dict(first_steps=10001), dict(first_steps="10001")),
    (dict(second="omega"), dict(second="omega")),
    (dict(first="mu"), dict(first="mu")),
    (dict(periods=1), dict(periods="1")),
    (dict(starts=1001), dict(starts="1001")),
    (dict(seed=-1), dict(seed="-1")),
    (dict(tolerance=0.0), dict(tolerance="0")),
    (dict(scatter=-1.0), dict(scatter="-1")),
    (dict(threads=1025), dict(threads="1025")),
    (dict(second_range=(0.01, 1.5)), dict(second_from="0.01")),
    (dict(first_steps=1000, second_steps=1000, starts=10), dict(first_steps="1000", second_steps="1000", starts="10")),
])
def test_bad_input_raises_the_command_lines_message(tmp_path, change, options):
    message = cli_error("map-sweep", *flags(**options), "--output", tmp_path / "m.csv")
    with pytest.raises(ValueError) as error:
        stickslip.map_sweep(**dict(MAP, **change))
    assert str(error.value) == message
    assert not (tmp_path / "m.csv").exists()
