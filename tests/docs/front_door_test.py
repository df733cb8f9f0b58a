#!/usr/bin/python3
"""The documentation pages: README.md is a front door of at most 20 KB; no page but the developers'
tests/README.md names a test (no path under tests/, no test case), the template of results/README.md
included; every relative link and anchor between the pages resolves; and results/README.md is what
tools/splice_readme.py writes from its template tools/results_readme.md and the tables that
tools/run.sh and tools/benchmark.sh generate under results/, byte for byte (a page edited by hand, or
stale, fails here).
Usage: front_door_test.py SOURCE_DIR"""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
pages = ["README.md", "tools/README.md", "tools/COMMANDS.md", "lib/README.md", "lib/python/README.md",
         "continuation-scripts/README.md", "results/README.md", "tests/README.md"]
# tests/README.md is the developers' page: it says which test backs which claim. Every other page,
# and the template results/README.md is written from, says what is checked in words.
user_pages = [p for p in pages if p != "tests/README.md"] + ["tools/results_readme.md"]
failures = []

size = os.path.getsize(os.path.join(root, "README.md"))
if size > 20 * 1024:
    failures.append(f"README.md is {size} bytes, over 20 KB: move reference material to the pages beside it")

# (tests/README.md, the developers' page, is a page, not a test: the user's pages may link to it.)
test_name = re.compile(r"(?<![\w/])tests/(?!\*|README\.md\b)[\w./-]+|\b[A-Z][A-Za-z0-9]+\.[A-Z][A-Za-z0-9]{15,}\b|\b\w+_test\.(?:cpp|sh|py)\b")
for page in user_pages:
    for number, line in enumerate(open(os.path.join(root, page)), 1):
        for m in test_name.finditer(line):
            failures.append(f"{page}:{number}: names a test ({m.group(0)}); say it in words, the test in tests/README.md")


def anchors(path):
    found, fence = set(), False
    for line in open(path):
        if line.startswith("```"):
            fence = not fence
        m = re.match(r"^#+ (.*)", line)
        if m and not fence:
            found.add(re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-"))
    return found


for page in pages:
    text = open(os.path.join(root, page)).read()
    for m in re.finditer(r"\]\(([^)\s]+)\)", text):
        target = m.group(1)
        if re.match(r"[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        full = os.path.normpath(os.path.join(root, os.path.dirname(page), path)) if path else os.path.join(root, page)
        if not os.path.exists(full):
            failures.append(f"{page}: link to a missing file: {target}")
        elif anchor and anchor not in anchors(full):
            failures.append(f"{page}: link to a missing section: {target}")

sys.path.insert(0, os.path.join(root, "tools"))
import splice_readme  # noqa: E402

results_page = open(os.path.join(root, "results", "README.md")).read()
template = open(os.path.join(root, "tools", "results_readme.md")).read()
if re.search(r"<!-- [\w-]+:begin -->\n(?!<!-- [\w-]+:end -->)", template):
    failures.append("tools/results_readme.md holds a table between its markers: the tables come from results/")
try:
    expected = splice_readme.generate(os.path.join(root, "results"))
except SystemExit as e:
    failures.append(str(e))
else:
    if results_page != expected:
        failures.append("results/README.md is not tools/results_readme.md with the tables under results/ spliced in: "
                        "edit the template, not the page, then run tools/splice_readme.py (tools/run.sh does)")
for page in ["README.md"]:
    if "<!--" in open(os.path.join(root, page)).read():
        failures.append(f"{page} holds a generated table: splice into results/README.md instead")

print("\n".join(failures) or f"ok: README.md {size} bytes, {len(pages)} pages, links current, results/README.md generated")
sys.exit(1 if failures else 0)
