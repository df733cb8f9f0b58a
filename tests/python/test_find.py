"""stickslip.find: from a simulated motion to its exact orbit, as `stickslip find` — the same
orbit as solve from the paper's data, a period-4 motion found with its k, the command line's
messages for bad input; and trace and continue_orbit from a found or solved Orbit (start=)."""
import pathlib

import numpy as np
import pytest

import stickslip
from conftest import cli, cli_error


def test_finds_the_paper_orbit_of_section_4_1_equal_to_solve():
    exact = stickslip.solve(preset="paper-4.1")
    start = exact.sample(2)[1][0] + 1e-5  # next to the orbit's origin
    found = stickslip.find(preset="paper-4.1", state=start)
    assert found.found, found.message
    assert found.period_multiple == 1 and found.antisymmetric
    assert str(found.orbit.signature) == str(exact.signature)
    for name in ("x10", "x20", "v10", "phi"):
        assert abs(getattr(found.orbit, name) - getattr(exact, name)) < 1e-9, name
    assert np.allclose(found.orbit.durations, exact.durations, rtol=0, atol=1e-9)
    assert found.orbit.verification["passed"]


def test_finds_the_period_four_motion_and_reports_a_smaller_multiple_as_not_periodic():
    data = dict(chi=0.5, eta=2.0, u_s=0.1, u_r=0.3, omega=0.27, x10=1.0)
    found = stickslip.find(set=data)
    assert found.found, found.message
    assert found.period_multiple == 4
    assert str(found.orbit.signature).startswith("slip- stick slip+ stick " * 3 + "slip- stick slip+ stick")
    assert stickslip.find(set=data, max_multiple=2).status == "not-periodic"


@pytest.mark.parametrize("keywords, flags", [
    (dict(transients=2.5), ["--transients", "2.5"]),
    (dict(transients=-1), ["--transients", "-1"]),
    (dict(max_multiple=1000), ["--max-multiple", "1000"]),
    (dict(tolerance=1.0), ["--tolerance", "1"]),
    (dict(confirmations=0), ["--confirmations", "0"]),
])
def test_bad_options_raise_value_error_with_the_command_line_message(keywords, flags):
    with pytest.raises(ValueError) as error:
        stickslip.find(preset="paper-4.1", **keywords)
    assert str(error.value) == cli_error("find", "--preset", "paper-4.1", *flags)


def tree(directory):
    """{relative path: bytes} of every file under `directory`."""
    root = pathlib.Path(directory)
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_trace_from_a_found_orbit_writes_the_files_of_find_trace(tmp_path):
    # guess=found.orbit.variables failed ("guess gives 'chi' twice"): start= takes the Orbit itself.
    found = stickslip.find(preset="paper-4.1")
    assert found.found, found.message
    omega = found.orbit.parameters.omega
    trace = stickslip.trace("omega", (omega - 0.02, omega + 0.02), start=found.orbit)
    trace.save(tmp_path / "py" / "t")
    done = cli("find", "--preset", "paper-4.1", "--trace", f"{omega - 0.02!r},{omega + 0.02!r}",
               "--results", tmp_path / "cli", "--output", "t")
    assert done.returncode == 0, done.stderr
    written = tree(tmp_path / "cli" / "t")
    assert len(written) >= 2 + 3 and tree(tmp_path / "py" / "t") == written  # trace.csv, trace.json, a branch


def test_continue_orbit_from_an_orbit_keeps_its_unknowns():
    # Section 5.2 with phi held at pi/2 and u_r released: the branch from the Orbit is the branch
    # from the same keywords, u_r varying along it.
    keywords = dict(preset="paper-5.2", fix={"phi": np.pi / 2}, free="u_r")
    orbit = stickslip.solve(**keywords)
    from_orbit = stickslip.continue_orbit("omega", (0.5, 1.0), start=orbit, max_points=6)
    from_keywords = stickslip.continue_orbit("omega", (0.5, 1.0), max_points=6, **keywords)
    for column in ("omega", "u_r", "phi", "x10", "d1"):
        assert np.allclose(from_orbit[column], from_keywords[column], rtol=1e-9, atol=1e-12), column
    assert np.ptp(from_orbit["u_r"]) > 0 and np.all(from_orbit["phi"] == np.pi / 2)


def test_start_is_an_orbit_and_the_whole_start():
    orbit = stickslip.solve(preset="paper-4.1")
    with pytest.raises(TypeError, match="start = .* is invalid: valid range a stickslip.Orbit"):
        stickslip.continue_orbit("omega", (0.5, 0.7), start=stickslip.find(preset="paper-4.1"))
    with pytest.raises(TypeError, match="preset= cannot be given with it"):
        stickslip.trace("omega", (0.5, 0.7), start=orbit, preset="paper-4.1")
