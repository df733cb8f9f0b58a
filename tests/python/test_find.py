"""stickslip.find: from a simulated motion to its exact orbit, as `stickslip find` — the same
orbit as solve from the paper's data, a period-4 motion found with its k, and the command line's
messages for bad input."""
import numpy as np
import pytest

import stickslip
from conftest import cli_error


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
