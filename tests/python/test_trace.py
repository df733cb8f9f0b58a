"""Traces from Python: the files of `stickslip trace` byte for byte (save), a run file's trace equal
to the stored results of `stickslip run`, the Trace's branches, ends and special points as the files
hold them, load and save round trips, and bad input refused with the command line's message."""
import pathlib

import pytest

import stickslip
from conftest import RESULTS, SOURCE, cli, cli_error

# §4.1 downwards switches once (crossing-sliding at omega = 0.5999775071) and ends not confirmed;
# upwards it reaches the range's end.
KEYWORDS = dict(preset="paper-4.1", ds=0.005, ds_max=0.05)
OPTIONS = {"--preset": "paper-4.1", "--parameter": "omega", "--range": "0.3,0.69", "--ds": "0.005", "--ds-max": "0.05"}


def flags(*changes):
    """The trace's options, with some replaced or added: flags("--ds", "-1")."""
    options = dict(OPTIONS, **dict(zip(changes[::2], changes[1::2])))
    return [text for pair in options.items() for text in pair]


FLAGS = flags()


def tree(directory):
    """{relative path: bytes} of every file under `directory`."""
    root = pathlib.Path(directory)
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def trace41():
    return stickslip.trace("omega", (0.3, 0.69), **KEYWORDS)


def test_a_trace_saves_the_command_lines_files_byte_for_byte(trace41, tmp_path):
    done = cli("trace", *FLAGS, "--results", tmp_path / "cli", "--output", "t41")
    assert done.returncode == 0, done.stderr  # the down chain ends not confirmed: an end like any other
    trace41.save(tmp_path / "py" / "t41")
    expected = tree(tmp_path / "cli" / "t41")
    assert len(expected) == 2 + 3 * 3  # trace.csv, trace.json and three branch directories
    assert tree(tmp_path / "py" / "t41") == expected


def test_the_trace_holds_its_branches_ends_and_special_points(trace41):
    assert trace41.ends == {"down": "not-confirmed", "up": "parameter-bound"}
    # The end names the parameter and its value, rounded (not "lambda_max = 0.6899999999999999").
    assert trace41.directions["up"]["message"] == "reached omega = 0.69"
    assert trace41.directions["down"]["branches"] == [1, 2] and trace41.directions["up"]["branches"] == [3]
    first, second, third = trace41.branches
    assert first.signature == "slip- / antisymmetric" and first.link["start"] == "trace-start"
    assert first.link["end"] == "switched" and first.link["chain"] == "down"
    assert second.signature == "slip- stick / antisymmetric" and second.link["margin"] == "reversal:1"
    assert second.link["switch"]["bifurcation"] == "crossing-sliding" and second.link["switch"]["persists"]
    assert third.link["chain"] == "up" and third.link["end"] == "parameter-bound"
    # trace.csv: every branch's points, in file order, the parameter continuous across the switch.
    assert len(trace41["omega"]) == sum(len(b) for b in trace41.branches)
    assert list(trace41["branch"]).count(2) == len(second) == second.link["points"]
    assert abs(first["omega"][-1] - 0.5999775071) < 1e-10 and second["omega"][0] == first["omega"][-1]
    assert list(trace41["signature"][: len(first)]) == [first.signature] * len(first)
    # The special points of every branch, each naming its branch.
    assert len(trace41.special_points) == sum(len(b.special_points) for b in trace41.branches)
    assert {s["branch"] for s in trace41.special_points} == {"branch-1", "branch-2", "branch-3"}
    assert trace41.special_points[0] == dict(first.special_points[0], branch="branch-1")


def test_a_run_file_with_a_trace_table_gives_the_stored_results(trace41, tmp_path):
    # continuation-scripts/paper-4.1-omega-trace.toml is the same trace with max_branches = 20.
    traced = stickslip.run(SOURCE / "continuation-scripts" / "paper-4.1-omega-trace.toml", results=RESULTS)
    assert isinstance(traced, stickslip.Trace) and traced.output == "paper-4.1-omega-trace"
    traced.save(tmp_path / traced.output)
    # The stored results were written by `stickslip run` with the run file's path as given to it.
    stored = tree(RESULTS / "paper-4.1-omega-trace")
    saved = tree(tmp_path / traced.output)
    assert saved.keys() == stored.keys()
    path = str(SOURCE / "continuation-scripts" / "paper-4.1-omega-trace.toml")
    for name, content in saved.items():
        assert content.replace(path.encode(), b"continuation-scripts/paper-4.1-omega-trace.toml") == stored[name], name
    # The branches are the keyword trace's.
    assert [b.files()["branch.csv"] for b in traced] == [b.files()["branch.csv"] for b in trace41]


def test_a_loaded_trace_saves_the_same_bytes(trace41, tmp_path):
    trace41.save(tmp_path / "first")
    loaded = stickslip.Trace.load(tmp_path / "first")
    assert loaded.ends == trace41.ends and loaded.output == "first"
    loaded.save(tmp_path / "again")
    first, again = tree(tmp_path / "first"), tree(tmp_path / "again")
    assert {k: v.replace(b'"again"', b'"first"') for k, v in again.items()} == first
    # The other files of a replaced trace directory are kept.
    (tmp_path / "first" / "notes.txt").write_text("mine")
    assert trace41.save(tmp_path / "first") == ["notes.txt"]


def test_a_saved_trace_keeps_the_users_files_inside_its_branches(trace41, tmp_path):
    # Issue 22: the AUTO export's files, notes and a directory of the user's inside branch-<k>/ were
    # deleted by the next save; they are kept and listed, at every depth.
    trace41.save(tmp_path / "t")
    mine = {"branch-2/b.branch-2": "b", "branch-2/s.branch-2": "s", "branch-1/NOTES.md": "n",
            "branch-1/plots/omega.txt": "p"}
    for name, text in mine.items():
        (tmp_path / "t" / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "t" / name).write_text(text)
    assert trace41.save(tmp_path / "t") == ["branch-1/NOTES.md", "branch-1/plots", "branch-2/b.branch-2",
                                            "branch-2/s.branch-2"]
    assert {name: (tmp_path / "t" / name).read_text() for name in mine} == mine


@pytest.mark.parametrize("keywords, options", [
    (dict(max_branches=0), ["--max-branches", "0"]),
    (dict(max_branches=10001), ["--max-branches", "10001"]),
    (dict(max_branches=2.5), ["--max-branches", "2.5"]),
    (dict(max_amplitude=-1.0), ["--max-amplitude", "-1"]),
    (dict(loop_tolerance=0.1), ["--loop-tolerance", "0.1"]),
    (dict(max_points=0), ["--max-points", "0"]),
    (dict(ds=-1.0), ["--ds", "-1"]),
    (dict(preset="paper-9"), ["--preset", "paper-9"]),
])
def test_bad_input_raises_the_command_lines_message(tmp_path, keywords, options):
    message = cli_error("trace", *flags(*options), "--results", tmp_path, "--output", "t")
    with pytest.raises(ValueError) as error:
        stickslip.trace("omega", (0.3, 0.69), **dict(KEYWORDS, **keywords))
    assert str(error.value) == message
    assert not (tmp_path / "t").exists()


def test_a_trace_takes_no_direction_and_a_branch_run_no_trace_file():
    with pytest.raises(TypeError, match="direction"):
        stickslip.trace("omega", (0.3, 0.69), direction="up", **KEYWORDS)
    with pytest.raises(ValueError, match=r"^follow_past_unswitched = 1 is invalid: valid range True or False$"):
        stickslip.trace("omega", (0.3, 0.69), follow_past_unswitched=1, **KEYWORDS)
    with pytest.raises(ValueError, match=r"\[trace\] is invalid here"):
        stickslip.Continuation.from_run_file(SOURCE / "continuation-scripts" / "paper-4.1-omega-trace.toml")


def test_a_start_that_is_not_a_motion_is_refused_unless_allowed(tmp_path):
    # Section 5.2's printed data solve to an orbit whose stick ends early (G:3 < 0): solve returns it
    # (admissible False, the command line's exit 4); a trace from it raises ValueError with the
    # command line's message (exit 4 there), unless allow_inadmissible.
    keywords = dict(preset="paper-5.2", ds=0.005, ds_max=0.05, max_branches=1, max_points=30)
    assert not stickslip.solve(preset="paper-5.2").admissible
    done = cli("trace", "--preset", "paper-5.2", "--parameter", "omega", "--range", "0.3,0.68", "--ds", "0.005",
               "--ds-max", "0.05", "--max-branches", "1", "--max-points", "30", "--results", tmp_path, "--output", "t")
    assert done.returncode == 4 and not (tmp_path / "t").exists(), done.stderr
    message = "the start is not a motion of the system: margin G:3 = -0.0072388 < 0 at omega = 0.66"
    assert message in done.stderr
    with pytest.raises(ValueError, match=message):
        stickslip.trace("omega", (0.3, 0.68), **keywords)
    traced = stickslip.trace("omega", (0.3, 0.68), allow_inadmissible=True, **keywords)
    assert len(traced.branches) == 2
    with pytest.raises(ValueError, match=r"^allow_inadmissible = 1 is invalid: valid range True or False$"):
        stickslip.trace("omega", (0.3, 0.68), allow_inadmissible=1, **keywords)
