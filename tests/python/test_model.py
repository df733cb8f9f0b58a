"""The model from Python: Parameters, the paper presets, the natural frequencies and simulate,
against the command line's output and analytic identities."""
import math
import pickle

import numpy as np
import pytest

import stickslip
from conftest import PRESETS, cli, cli_json


def test_parameters_keep_their_values_and_compare_by_value():
    p = stickslip.Parameters(chi=0.3, eta=4.0, omega=0.6, u_s=0.1, u_r=0.2996)
    assert (p.chi, p.eta, p.omega, p.u_s, p.u_r) == (0.3, 4.0, 0.6, 0.1, 0.2996)
    assert p.as_dict() == {"chi": 0.3, "eta": 4.0, "omega": 0.6, "u_s": 0.1, "u_r": 0.2996}
    assert p.replace(omega=0.58) == stickslip.Parameters(chi=0.3, eta=4.0, omega=0.58, u_s=0.1, u_r=0.2996)
    assert pickle.loads(pickle.dumps(p)) == p
    with pytest.raises(TypeError):
        stickslip.Parameters(0.3, 4.0, 0.6, 0.1, 0.2996)  # keywords only


def test_natural_frequencies_satisfy_the_characteristic_equation():
    # omega1^2 + omega2^2 = 1 + chi eta and omega1^2 omega2^2 = chi eta (1 - chi) (eq. 56).
    for name in PRESETS:
        p = stickslip.Parameters.preset(name)
        w1, w2 = stickslip.natural_frequencies(p)
        assert 0 < w1 < w2
        assert math.isclose(w1**2 + w2**2, 1 + p.chi * p.eta, rel_tol=1e-14)
        assert math.isclose(w1**2 * w2**2, p.chi * p.eta * (1 - p.chi), rel_tol=1e-14)


def test_presets_hold_the_paper_data_the_command_line_uses():
    assert sorted(stickslip.presets) == sorted(PRESETS)
    for name, preset in stickslip.presets.items():
        assert preset.name == name
        assert stickslip.Parameters.preset(name) == preset.parameters
        # The command line's simulation of the preset starts from the same data and state.
        sim = stickslip.simulate(preset=name, periods=1)
        assert sim.parameters == preset.parameters
        assert list(sim.initial_state) == list(preset.state)
        assert sim.phi == preset.phi
        assert len(preset.durations) == len(preset.signature)


@pytest.mark.parametrize("method", ["exact", "odeint"])
def test_simulate_gives_the_command_line_events_bit_for_bit(method):
    for name in PRESETS:
        sim = stickslip.simulate(preset=name, periods=2, method=method)
        expected = cli_json("simulate", "--preset", name, "--periods", 2, "--method", method, "--json")["events"]
        assert sim.completed
        assert len(sim.events["t"]) == len(expected)
        for i, e in enumerate(expected):
            assert sim.events["t"][i] == e["t"]
            assert sim.events["mode_after"][i] == e["mode_after"]
            assert list(sim.events["state"][i]) == e["state"]


def test_simulate_samples_equal_the_command_line_csv(tmp_path):
    p = stickslip.Parameters(chi=0.3, eta=4, omega=0.6, u_s=0.1, u_r=0.3)
    sim = stickslip.simulate(p, state=(1, 0, 0, 0), phi=0, periods=1.5, samples_per_period=50)
    csv = tmp_path / "series.csv"
    done = cli("simulate", "--set", "chi=0.3", "--set", "eta=4", "--set", "omega=0.6", "--set", "u_s=0.1",
               "--set", "u_r=0.3", "--set", "x10=1", "--periods", 1.5, "--samples-per-period", 50, "--csv", csv)
    assert done.returncode == 0, done.stderr
    rows = [line.split(",") for line in csv.read_text().splitlines()[1:]]
    assert len(rows) == len(sim.samples["t"])
    for i, row in enumerate(rows):
        assert float(row[0]) == sim.samples["t"][i]
        assert [float(v) for v in row[1:5]] == list(sim.samples["state"][i])
        assert row[5] == sim.samples["mode"][i]


def test_exact_and_odeint_simulations_agree():
    exact = stickslip.simulate(preset="paper-5.1", periods=3, method="exact")
    odeint = stickslip.simulate(preset="paper-5.1", periods=3, method="odeint")
    assert list(exact.events["kind"]) == list(odeint.events["kind"])
    assert np.max(np.abs(exact.events["t"] - odeint.events["t"])) < 1e-8
    assert np.max(np.abs(exact.samples["state"] - odeint.samples["state"])) < 1e-8
