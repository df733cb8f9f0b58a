"""One set of defaults per option: every keyword of the Python functions that has an option of the
same command takes the default that option shows in the command's --help (both fetched from the
library), so a script and a command line left at their defaults compute the same thing."""
import inspect
import re

import pytest

import stickslip
from conftest import cli

# (function, command, the keywords whose options are spelt with '-' for '_')
CASES = [
    (stickslip.simulate, "simulate", ["periods", "method", "samples_per_period"]),
    (stickslip.find, "find", ["transients", "max_multiple", "tolerance", "confirmations"]),
    (stickslip.sweep, "sweep", ["parameter", "steps", "transients", "periods", "start", "chains", "scatter", "seed",
                                "threads"]),
    (stickslip.map_sweep, "map-sweep", ["first_steps", "second_steps", "transients", "periods", "starts", "scatter",
                                        "seed", "tolerance", "threads"]),
]


def help_defaults(command):
    """The defaults --help shows: "--steps INT=40" gives {"steps": "40"}."""
    text = cli(command, "--help").stdout
    return {m.group(1): m.group(2) for m in re.finditer(r"^\s+--([a-z0-9-]+) [A-Z_]+(?::\{[^}]*\})?=(\S+)", text, re.M)}


@pytest.mark.parametrize("function,command,keywords", CASES, ids=[c[1] for c in CASES])
def test_a_keyword_defaults_to_its_options_default(function, command, keywords):
    shown = help_defaults(command)
    parameters = inspect.signature(function).parameters
    for keyword in keywords:
        option = keyword.replace("_", "-")
        assert option in shown, (command, option, sorted(shown))
        default = parameters[keyword].default
        if isinstance(default, str):
            assert default == shown[option], (command, keyword)
        else:
            assert float(default) == float(shown[option]), (command, keyword, default, shown[option])
