"""Single orbits from Python: Signature, solve and the Orbit, against `stickslip solve --json` bit for
bit, and the orbit's own closed form."""
import math

import numpy as np
import pytest

import stickslip
from conftest import PRESETS, cli, cli_json


def test_signature_parses_and_prints_the_text_form():
    s = stickslip.Signature("slip- stick slip- / antisymmetric")
    assert str(s) == "slip- stick slip- / antisymmetric"
    assert s.segments == ["slip-", "stick", "slip-"]
    assert s.antisymmetric and s.period_multiple == 1 and len(s) == 3
    assert s.full_period == ["slip-", "stick", "slip-", "slip+", "stick", "slip+"]
    # A slip into a stick, the stick out into slip-, and slip- into the mirrored first segment, slip+.
    assert s.end_kinds == ["stick-entry", "exit-to-slip-", "reversal"]
    assert stickslip.Signature("slip- slip+ / period 2").period_multiple == 2
    assert stickslip.Signature("slip- slip+ stick slip+") == stickslip.Signature("slip-  slip+ stick slip+")


@pytest.mark.parametrize("name", PRESETS)
def test_paper_orbits_equal_the_command_line_bit_for_bit(name):
    orbit = stickslip.solve(preset=name)
    expected = cli_json("solve", "--preset", name, "--json")
    assert str(orbit.signature) == expected["signature"]
    assert orbit.parameters.as_dict() == expected["parameters"]
    for key in ("phi", "x10", "x20", "v10"):
        assert getattr(orbit, key) == expected[key], key
    assert list(orbit.durations) == [s["duration"] for s in expected["segments"]]
    assert orbit.newton["iterations"] == expected["iterations"]
    assert orbit.newton["termination"] == expected["termination"]
    assert orbit.newton["residual_norms"][-1] == expected["residual_norm"]
    assert orbit.shooting == expected["shooting"]
    assert orbit.family_dimension == expected["family_dimension"] == 0
    assert list(orbit.margins) == list(expected["margins"])
    for key, value in expected["margins"].items():
        assert orbit.margins[key] == value or (value is None and not math.isfinite(orbit.margins[key])), key
    assert [[mu.real, mu.imag] for mu in orbit.multipliers] == expected["multipliers"]
    assert orbit.stable == expected["stable"]
    assert orbit.multipliers_one_sided == expected["multipliers_one_sided"]
    assert orbit.measures == expected["measures"]
    assert isinstance(orbit.measures["stops"], int) and isinstance(orbit.measures["sticks"], int)
    v = orbit.verification
    assert v["passed"] == expected["verification"]["passed"]
    for simulator in ("exact", "odeint"):
        assert v[simulator]["events"] == expected["verification"][simulator]["events"]
        assert v[simulator]["max_mismatch"] == expected["verification"][simulator]["max_mismatch"]
    # The unknowns are those the command line lists.
    text = cli("solve", "--preset", name).stdout
    line = next(line for line in text.splitlines() if line.startswith("unknowns"))
    assert list(orbit.unknowns) == line.split()[1:len(orbit.unknowns) + 1]
    assert orbit.unknowns["x10"] == orbit.x10
    assert orbit.unknowns == expected["unknowns"] and orbit.tie_u_r == expected["tie_u_r"]
    assert orbit.admissible == expected["admissible"]


def test_section_5_2_at_the_printed_data_is_not_a_motion():
    orbit = stickslip.solve(preset="paper-5.2")
    name, value = orbit.smallest_margin
    assert name == "G:3" and value < 0 and not orbit.admissible
    assert cli("solve", "--preset", "paper-5.2").returncode == 4


def test_paper_choice_releases_u_r_for_section_5_2():
    orbit = stickslip.solve(preset="paper-5.2", fix={"phi": math.pi / 2}, free="u_r")
    expected = cli_json("solve", "--preset", "paper-5.2", "--fix", f"phi={math.pi / 2!r}", "--free", "u_r", "--json")
    assert "u_r" in orbit.unknowns and orbit.phi == math.pi / 2
    assert orbit.parameters.u_r == expected["parameters"]["u_r"]


def test_orbit_samples_close_over_one_period():
    orbit = stickslip.solve(preset="paper-5.1")
    t, x = orbit.sample(101)
    assert t.shape == (101,) and x.shape == (101, 4)
    assert t[0] == 0 and t[-1] == orbit.period
    # The flow over zero time: the start to rounding.
    assert np.allclose(x[0], (orbit.x10, orbit.x20, orbit.v10, 0.0), rtol=1e-14, atol=1e-15)
    assert np.max(np.abs(x[-1] - x[0])) < 1e-9  # periodic: the periodicity equations hold
    # An antisymmetric orbit comes back mirrored after half a period.
    half = stickslip.solve(preset="paper-6")
    t, x = half.sample(201)
    assert np.max(np.abs(x[100] + x[0])) < 1e-9


def test_solve_from_parameters_and_a_signature_equals_the_preset():
    preset = stickslip.presets["paper-5.1"]
    guess = {"x10": preset.state[0], "x20": preset.state[1], "v10": preset.state[2], "phi": preset.phi}
    guess.update({f"d{i + 1}": d for i, d in enumerate(preset.durations)})
    orbit = stickslip.solve(preset.parameters, preset.signature, guess=guess)
    reference = stickslip.solve(preset="paper-5.1")
    assert orbit.variables == reference.variables


def test_unknowns_one_equation_short_stay_a_newton_failure_not_a_family():
    # d1 = pi/omega fixed and u_s released: u_s could take any value (a "family" through the
    # parameters), so Newton's singular Jacobian stands, as on the command line (exit 3).
    with pytest.raises(stickslip.ConvergenceError) as error:
        stickslip.solve(preset="paper-4.1", free=["u_s"], fix=["d1"])
    assert error.value.summary["termination"] == "singular-jacobian"
    assert cli("solve", "--preset", "paper-4.1", "--free", "u_s", "--fix", "d1").returncode == 3


def test_no_convergence_raises_convergence_error_with_the_newton_summary():
    with pytest.raises(stickslip.ConvergenceError) as error:
        stickslip.solve(preset="paper-5.1", guess={"d1": 0.05, "d2": 0.5, "d3": 0.05, "d4": 0.05})
    summary = error.value.summary
    assert not summary["converged"]
    assert summary["termination"] != "converged"
    assert len(summary["residual_norms"]) >= 1
    assert str(error.value).startswith("Newton did not converge: ")
    done = cli("solve", "--preset", "paper-5.1", "--guess", "d1=0.05", "--guess", "d2=0.5", "--guess", "d3=0.05",
               "--guess", "d4=0.05")
    assert done.returncode == 3
    assert done.stderr.strip() == f"error: {error.value}"
