#!/usr/bin/python3
"""The command reference cannot go stale: tools/COMMANDS.md regenerated from the built program's
--help (tools/command_reference.py: the top-level help and every command it lists, in its order)
equals the committed page, byte for byte; and the page lists every command the program has.
Usage: command_reference_test.py STICKSLIP SOURCE_DIR"""
import difflib
import os
import sys

program, root = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(root, "tools"))
import command_reference  # noqa: E402

page_path = os.path.join(root, "tools", "COMMANDS.md")
committed = open(page_path).read()
generated = command_reference.generate(program)
failures = []
for name in command_reference.commands(command_reference.help_text(program)):
    if f"\n## `stickslip {name}`\n" not in committed:
        failures.append(f"tools/COMMANDS.md has no section for `stickslip {name}`")
if generated != committed:
    diff = difflib.unified_diff(committed.splitlines(True), generated.splitlines(True),
                                "tools/COMMANDS.md (committed)", "tools/COMMANDS.md (from --help)", n=1)
    failures.append("tools/COMMANDS.md is stale: run tools/command_reference.py " + program + "\n" +
                    "".join(list(diff)[:60]))
print("\n".join(failures) or f"ok: tools/COMMANDS.md is the program's --help ({len(committed)} bytes)")
sys.exit(1 if failures else 0)
