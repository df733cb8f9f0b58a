"""Branch switching from Python: the branch that leaves a period doubling, from a stored label
(continue_orbit(point=..., switch_branch=True)) equal byte for byte to the command line's run of
continuation-scripts/paper-5.2-period-2.toml, and from a branch in memory (Branch.switch, with the
engine's own tangent) ending where that run ends; bad input raises ValueError."""
import json

import pytest

import stickslip
from conftest import RESULTS, SOURCE

# The start of continuation-scripts/paper-5.2-omega-to-pd.toml, downwards through its PD2 (point 9).
TO_PD = dict(preset="paper-5.2", set={"omega": 0.737},
             guess={"x10": 0.8358908442122435, "x20": 1.5258036723705244, "v10": -1.0897400526017202,
                    "phi": 3.5580641421981336, "d1": 2.8655384579659624, "d2": 3.1896629391933726,
                    "d3": 2.470432677030011},
             direction="down", ds=0.005, ds_max=0.1)
# The continuation keys of continuation-scripts/paper-5.2-period-2.toml.
PERIOD_2 = dict(range=(0.6, 0.8), ds=0.005, ds_max=0.02, max_points=500)


def test_a_switch_at_a_stored_label_gives_the_run_files_branch_byte_for_byte():
    branch = stickslip.continue_orbit("omega", results=RESULTS, point="paper-5.2-omega-to-pd:PD2", switch_branch=True,
                                      direction="up", output="paper-5.2-period-2", **PERIOD_2)
    stored = RESULTS / "paper-5.2-period-2"
    files = branch.files()
    assert files["branch.csv"] == (stored / "branch.csv").read_text()
    assert files["special-points.csv"] == (stored / "special-points.csv").read_text()
    summary, expected = json.loads(files["summary.json"]), json.loads((stored / "summary.json").read_text())
    assert summary.pop("run_file") == "(command line)"
    expected.pop("run_file")
    assert summary == expected


def test_a_switch_from_a_branch_in_memory_follows_the_period_2_orbits_to_the_run_files_end():
    to_pd = stickslip.continue_orbit("omega", (0.6, 0.739), max_points=12, **TO_PD)
    assert to_pd.special_point("PD2")["pt"] == 9
    period_2 = to_pd.switch("PD2", side=1, **PERIOD_2)
    assert period_2.signature == "slip- slip+ stick slip- slip+ stick / period 2"
    # The engine's tangent at the located PD and the one recomputed at the stored label differ by
    # rounding: the branch ends at the same change of type.
    stored = stickslip.Branch.load(RESULTS / "paper-5.2-period-2")
    assert period_2.termination == stored.termination == "terminal-event"
    assert abs(period_2.special_point("SK2")["omega"] - stored.special_point("SK2")["omega"]) < 1e-9
    # Its first point lies one step along the new branch from the PD, as the run file's does.
    assert abs(period_2["omega"][0] - stored["omega"][0]) < 1e-8
    assert 0 < period_2["omega"][0] - to_pd.special_point("PD2")["omega"] < 0.005
    # The other side: the same orbits shifted by one period (the durations of the two periods
    # swapped: d1 - d4 changes sign), on the same side of the PD in omega (a pitchfork).
    other = to_pd.switch("PD2", side=-1, **dict(PERIOD_2, max_points=6))
    pd = to_pd.special_point("PD2")["omega"]
    for one, two in ((period_2, other), (other, period_2)):
        assert all(one["omega"][:6] > pd)
        assert all((one["d1"][:6] - one["d4"][:6]) * (two["d1"][:6] - two["d4"][:6]) < 0)


def test_a_continuation_stepped_by_hand_switches_too():
    cont = stickslip.Continuation("omega", (0.6, 0.739), max_points=12, **TO_PD)
    branch = cont.run()
    assert branch.switch("PD2", max_points=3).signature == "slip- slip+ stick slip- slip+ stick / period 2"


def test_bad_switches_raise_value_error(tmp_path):
    to_pd = stickslip.continue_orbit("omega", (0.6, 0.739), max_points=12, **TO_PD)
    with pytest.raises(ValueError, match=r"^special point = EP is invalid: valid range a branch point \(BP\), a period "
                                         r"doubling \(PD\) or a symmetry breaking \(SB\)$"):
        to_pd.switch("EP1")
    with pytest.raises(ValueError, match=r"^side = 0 is invalid: valid range \+1 or -1$"):
        to_pd.switch("PD2", side=0)
    with pytest.raises(ValueError, match=r"^label = 'LP7' is invalid: valid range a label of the branch: EP1, PD2, "):
        to_pd.switch("LP7")
    with pytest.raises(ValueError, match=r"^max-points = 0 is invalid"):
        to_pd.switch("PD2", max_points=0)
    to_pd.save(tmp_path / "to-pd")
    with pytest.raises(ValueError, match=r"^switch = 'PD2' is invalid: valid on a branch computed in this process"):
        stickslip.Branch.load(tmp_path / "to-pd").switch("PD2")
    with pytest.raises(ValueError, match=r"^switch_branch = True is invalid: valid range True with point='RUN:LABEL'"):
        stickslip.continue_orbit("omega", (0.6, 0.739), switch_branch=True, **TO_PD)
    with pytest.raises(ValueError, match=r"^switch_branch = 1 is invalid: valid range True or False$"):
        stickslip.continue_orbit("omega", (0.6, 0.8), results=tmp_path, point="to-pd:PD2", switch_branch=1)
    # At a label that is no PD or SB, named as the command line's option (as max-points is).
    with pytest.raises(ValueError, match=r"^switch-branch = true is invalid at 'EP1' \(type EP\): valid at a period "
                                         r"doubling \(PD\) or a symmetry breaking \(SB\)"):
        stickslip.continue_orbit("omega", (0.6, 0.8), results=tmp_path, point="to-pd:EP1", switch_branch=True)


def test_a_switch_at_a_symmetry_breaking_leaves_on_mirror_image_orbits_without_the_symmetry():
    # The §6 type continued down in omega past its type changes (no motion there: a test of the
    # algebra) meets a multiplier -1 of its half-period map at omega = 0.55014
    # (tests/branches/bifurcation_branches_test.cpp).
    antisymmetric = stickslip.continue_orbit(
        "omega", (0.54, 0.56), preset="paper-6", set={"omega": 0.5501955483169749},
        guess={"x10": 9.936832707872899, "x20": 11.737822390429132, "v10": -6.552116682904398,
               "phi": 3.586861573229454, "d1": 3.129379765497387, "d2": 1.8950732856966541,
               "d3": 0.6855034600859811},
        direction="down", ds=0.01, ds_max=0.02, max_points=30, continue_past_type_changes=True)
    sb = [s for s in antisymmetric.special_points if s["type"] == "SB" and s["located"]]
    assert len(sb) == 1 and abs(sb[0]["omega"] - 0.55014) < 1e-5
    sides = [antisymmetric.switch(sb[0]["label"], side=side, max_points=12) for side in (1, -1)]
    for branch in sides:
        assert branch.signature == "slip- stick slip- slip+ stick slip+" and len(branch) == 12
    # Without the symmetry the two halves' durations differ, more so away from the point; the two
    # sides are mirror images, whose halves are swapped: d1 - d4 of opposite signs.
    asymmetry = [branch["d1"] - branch["d4"] for branch in sides]
    assert all(abs(asymmetry[0][1:]) > abs(asymmetry[0][:-1]))
    assert all(asymmetry[0] * asymmetry[1] < 0)


def test_a_type_boundary_from_a_stored_label_gives_the_run_files_curve_byte_for_byte():
    # continuation-scripts/paper-4.1-sk-boundary.toml: the §4.1 crossing-sliding boundary in (omega, u_r).
    branch = stickslip.two_parameter("omega", "u_r", (0.3, 0.69), point="paper-4.1-omega-down:SK2", results=RESULTS,
                                     direction="down", ds=0.01, ds_max=0.05, max_points=400,
                                     output="paper-4.1-sk-boundary")
    stored = RESULTS / "paper-4.1-sk-boundary"
    files = branch.files()
    assert files["branch.csv"] == (stored / "branch.csv").read_text()
    assert files["special-points.csv"] == (stored / "special-points.csv").read_text()
    assert branch.signature == "slip- / antisymmetric"
    assert all(abs(branch["margin:reversal:1"]) < 1e-10)  # the force at the stop held at the static level
    assert branch["u_r"][-1] < branch["u_r"][0]  # the curve moves in both parameters


@pytest.mark.parametrize("keywords, message", [
    (dict(point=None), "boundary = 'u_r' is invalid: valid range a second parameter with point='RUN:LABEL'"),
    (dict(point="paper-4.1-omega-down:EP1"), "boundary = 'u_r' is invalid at 'EP1'"),
])
def test_a_type_boundary_needs_a_stored_change_of_type(keywords, message):
    with pytest.raises(ValueError) as error:
        stickslip.continue_orbit("omega", (0.3, 0.69), boundary="u_r", results=RESULTS, **keywords)
    assert message in str(error.value)


def test_a_switch_whose_first_point_leaves_the_range_raises_naming_the_range_and_the_side():
    # The period-2 branch leaves PD2 upwards in omega: a range that ends on the PD holds the label
    # but not the new branch's first point. Nothing is continued from outside the range.
    to_pd = stickslip.continue_orbit("omega", (0.6, 0.739), max_points=12, **TO_PD)
    pd = to_pd.special_point("PD2")["omega"]
    with pytest.raises(ValueError, match=r"^range = '0.6,.*' excludes the first point of the branch that leaves "
                                         r"'PD2' \(direction = \"up\"\), omega = 0\.73"):
        to_pd.switch("PD2", side=1, range=(0.6, pd), ds=0.005, ds_max=0.02)
    # The same from the stored label, stepped by hand: the first step raises.
    stored_pd = stickslip.Branch.load(RESULTS / "paper-5.2-omega-to-pd").special_point("PD2")["omega"]
    stepped = stickslip.Continuation("omega", (0.6, stored_pd), results=RESULTS, point="paper-5.2-omega-to-pd:PD2",
                                     switch_branch=True, direction="up", ds=0.005, ds_max=0.02)
    with pytest.raises(ValueError, match=r"excludes the first point of the branch that leaves 'PD2'"):
        stepped.step()


def test_a_type_boundary_does_not_continue_past_the_changes_of_type():
    # Checked once every keyword is read: the rule joins two of them (boundary was once taken
    # with continue_past_type_changes=True, which the command line and a run file refuse).
    with pytest.raises(ValueError) as error:
        stickslip.continue_orbit("omega", (0.3, 0.69), point="paper-4.1-omega-down:SK2", boundary="u_r",
                                 continue_past_type_changes=True, results=RESULTS, output="never")
    assert str(error.value).startswith("continue-past-type-changes = true is invalid with boundary: valid false")


def test_an_empty_boundary_is_refused_not_taken_as_none():
    with pytest.raises(ValueError, match=r"^boundary = '' is invalid: valid the name of a second parameter"):
        stickslip.continue_orbit("omega", (0.3, 0.69), point="paper-4.1-omega-down:SK2", boundary="",
                                 results=RESULTS, output="never")
