#!/usr/bin/python3
"""The quick start of README.md runs as written: each ```toml block whose first line is `# NAME`
is written to NAME (and must be the [model] of continuation-scripts/models/NAME, whose figure the
text shows), and each ```sh block of its "Quick start" section is
run (line continuations joined, `stickslip` replaced by the program under test) in a fresh
directory, and every line of the output block that follows it in the text must be in what the
commands printed (a line ending in "..." as a prefix; a line "..." stands for lines left out;
wall times "0.024 s" match any time). The figure the text names must be written. With PYTHONPATH
holding the built module, the Python block of its "Workflows" section runs too, and each
`expression  # value...` line in it must give that value.
Usage: readme_examples_test.py STICKSLIP SOURCE_DIR"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

program, root = sys.argv[1], sys.argv[2]
text = open(os.path.join(root, "README.md")).read()


def section(title):
    start = text.index(title)
    following = text.find("\n## ", start + 1)
    return text[start:following if following >= 0 else len(text)]


def blocks(part):
    """(language, body, the plain block right after it or None)"""
    found = [(m.group(1), m.group(2), m.start(), m.end())
             for m in re.finditer(r"```(\w*)\n(.*?)```", part, re.S)]
    out = []
    for k, (lang, body, _, end) in enumerate(found):
        nxt = found[k + 1] if k + 1 < len(found) else None
        out.append((lang, body, nxt[1] if nxt and nxt[0] == "" and not part[end:nxt[2]].strip() else None))
    return out


def normal(line):
    return re.sub(r"\b\d+(\.\d+)? s\b", "T s", line.rstrip())


failures = []
quick = section("## Quick start")
ran = 0
with tempfile.TemporaryDirectory() as work:
    for lang, body, expected in blocks(quick):
        if lang == "toml" and body.startswith("# "):
            name, model = body.split("\n", 1)[0][2:].strip(), body.split("\n", 1)[1]
            with open(os.path.join(work, name), "w") as f:
                f.write(model)
            shipped_path = os.path.join(root, "continuation-scripts", "models", name)
            shipped = open(shipped_path).read() if os.path.isfile(shipped_path) else ""
            if "[model]" not in shipped or shipped[shipped.index("[model]"):] != model:
                failures.append(f"the quick start's {name} is not continuation-scripts/models/{name}'s [model]")
        if lang != "sh":
            continue
        printed = []
        for command in body.replace("\\\n", " ").splitlines():
            words = shlex.split(command, comments=True)
            if not words:
                continue
            assert words[0] == "stickslip", command
            run = subprocess.run([program] + words[1:], cwd=work, capture_output=True, text=True)
            ran += 1
            if run.returncode != 0:
                failures.append(f"exit {run.returncode}: {command}\n{run.stderr}")
            printed += [normal(line) for line in run.stdout.splitlines()]
        for line in (expected or "").splitlines():
            want = normal(line)
            if want.strip() == "...":
                continue
            if want.endswith("..."):
                prefix = want[:-3].rstrip()
                ok = any(p.startswith(prefix) for p in printed)
            else:
                ok = want in printed
            if not ok:
                failures.append(f"the README says\n  {line}\nbut the commands printed\n  " + "\n  ".join(printed))
    for figure in re.findall(r"writes (\S+\.png)", quick):
        if not os.path.isfile(os.path.join(work, figure)):
            failures.append(f"the quick start says it writes {figure}; it did not")

    if os.environ.get("PYTHONPATH"):
        code = [body for lang, body, _ in blocks(section("## Workflows")) if lang == "python"]
        old = os.getcwd()
        os.chdir(work)
        try:
            for body in code:
                scope = {}
                lines = body.splitlines()
                for k, line in enumerate(lines):
                    m = re.match(r"^(\S.*?)\s+#\s*([-+0-9.]+)\.\.\.$", line)
                    if m:  # an expression and the value the text gives for it, rounded to its digits
                        exec("\n".join(lines[:k]), scope)
                        value, said = eval(m.group(1), scope), m.group(2)
                        digits = len(said.split(".")[1]) if "." in said else 0
                        if abs(value - float(said)) > 0.5 * 10.0 ** -digits:
                            failures.append(f"{m.group(1)} gives {value!r}, the README says {said}...")
                exec(body, {})
                ran += 1
        finally:
            os.chdir(old)

print("\n".join(failures) or f"ok: {ran} README command(s) ran as the text says")
sys.exit(1 if failures else 0)
