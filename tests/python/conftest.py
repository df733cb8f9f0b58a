"""Shared by the tests of the Python module: the command line beside it (STICKSLIP), the source
tree (STICKSLIP_SOURCE), both set by ctest (tests/CMakeLists.txt)."""
import json
import os
import pathlib
import subprocess

import pytest

BINARY = os.environ.get("STICKSLIP", "stickslip")
SOURCE = pathlib.Path(os.environ.get("STICKSLIP_SOURCE", pathlib.Path(__file__).resolve().parents[2]))
RESULTS = SOURCE / "results"
PRESETS = ("paper-4.1", "paper-4.2", "paper-5.1", "paper-5.2", "paper-6")


def cli(*args, cwd=None):
    """Runs the command line; returns the completed process (text output)."""
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=600)


def cli_error(*args):
    """The one-line message of a command that must refuse its input (exit 2, "error: <message>")."""
    done = cli(*args)
    assert done.returncode == 2, (args, done.returncode, done.stderr)
    lines = done.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), done.stderr
    return lines[0][len("error: "):]


def cli_json(*args):
    done = cli(*args)
    assert done.returncode in (0, 4), (args, done.returncode, done.stderr)
    return json.loads(done.stdout)


@pytest.fixture
def results_copy(tmp_path):
    """An empty results directory of the test's own."""
    path = tmp_path / "results"
    path.mkdir()
    return path
