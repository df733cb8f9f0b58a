"""stickslip.atlas: the same atlas as `stickslip atlas` (the same files, byte for byte, from the
two front ends), saved and loaded back unchanged, drawn as a figure; bad input refused in the
command line's words."""
import filecmp
import os

import pytest

import stickslip
from conftest import cli, cli_error

SMALL = dict(preset="paper-4.1", steps=2, starts=2, transients=300)
FLAGS = ["--preset", "paper-4.1", "--range", "0.58,0.62", "--steps", "2", "--starts", "2", "--transients", "300"]


def same_tree(a, b):
    compared = filecmp.dircmp(a, b)
    assert not compared.left_only and not compared.right_only and not compared.diff_files, compared.report()
    for sub in compared.common_dirs:
        same_tree(os.path.join(a, sub), os.path.join(b, sub))


def test_the_same_files_as_the_command_line(tmp_path):
    atlas = stickslip.atlas("omega", (0.58, 0.62), output="a", **SMALL)
    atlas.save(tmp_path / "python" / "a")
    done = cli("atlas", *FLAGS, "--results", tmp_path / "cli", "--output", "a")
    assert done.returncode == 0, done.stderr
    # The run file each records differs by design: "(command line)" and "(python)".
    for text in (tmp_path / "python" / "a").rglob("*.json"):
        text.write_text(text.read_text().replace('"(python)"', '"(command line)"'))
    same_tree(tmp_path / "python" / "a", tmp_path / "cli" / "a")
    assert atlas.counts["on_branches"] == atlas.counts["periodic_within_limit"] > 0
    assert all(a["fate"] == "on-branch" for a in atlas.attractors if a["find"] == "found")


def test_saved_and_loaded_back_unchanged_and_drawn(tmp_path):
    atlas = stickslip.atlas("omega", (0.58, 0.62), **SMALL)
    atlas.save(tmp_path / "a")
    loaded = stickslip.Atlas.load(tmp_path / "a")
    assert loaded.files() == atlas.files()
    assert [t.files() for t in loaded.traces] == [t.files() for t in atlas.traces]
    figure = loaded.plot(yscale="log")
    assert len(figure.axes) == 2  # the response and the coexistence strip


@pytest.mark.parametrize("keywords, flags", [
    (dict(range=(0.62, 0.58)), ["--range", "0.62,0.58"]),
    (dict(max_multiple=0), ["--max-multiple", "0"]),
    (dict(max_amplitude=-1.0), ["--max-amplitude", "-1"]),
])
def test_bad_input_in_the_command_lines_words(keywords, flags):
    arguments = dict(SMALL, range=(0.58, 0.62))
    arguments.update(keywords)
    parameter_range = arguments.pop("range")
    with pytest.raises(ValueError) as error:
        stickslip.atlas("omega", parameter_range, **arguments)
    flag_arguments = [f for f in FLAGS if f not in ("--range", "0.58,0.62")]
    message = cli_error("atlas", *flag_arguments, *(flags if "--range" in flags else ["--range", "0.58,0.62", *flags]),
                        "--output", "b")
    assert str(error.value).split(" is invalid")[0] == message.split(" is invalid")[0]
