#!/usr/bin/python3
"""The documentation pages: README.md is a front door of at most 20 KB; the pages users read name
no test (no path under tests/, no test case); every relative link and anchor between the pages
resolves; and the tables that tools/run.sh and tools/benchmark.sh splice into results/README.md are
the generated files under results/, byte for byte (a stale page fails here).
Usage: front_door_test.py SOURCE_DIR"""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
pages = ["README.md", "tools/README.md", "lib/README.md", "lib/python/README.md",
         "continuation-scripts/README.md", "results/README.md"]
# lib/README.md is the developer's page: it says which test checks what.
user_pages = [p for p in pages if p != "lib/README.md"]
failures = []

size = os.path.getsize(os.path.join(root, "README.md"))
if size > 20 * 1024:
    failures.append(f"README.md is {size} bytes, over 20 KB: move reference material to the pages beside it")

test_name = re.compile(r"(?<![\w/])tests/(?!\*)[\w./-]+|\b[A-Z][A-Za-z0-9]+\.[A-Z][A-Za-z0-9]{15,}\b|\b\w+_test\.(?:cpp|sh|py)\b")
for page in user_pages:
    for number, line in enumerate(open(os.path.join(root, page)), 1):
        for m in test_name.finditer(line):
            failures.append(f"{page}:{number}: names a test ({m.group(0)}); say it in lib/README.md's Verification")


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

results_page = open(os.path.join(root, "results", "README.md")).read()
for name, generated in [("runs", "results/runs.md"), ("paper-table", "results/paper-table.md"),
                        ("trace-intervals", "results/trace-intervals.md"),
                        ("orbit-type-maps", "results/maps/maps.md"), ("benchmark", "results/benchmark.md")]:
    begin, end = f"<!-- {name}:begin -->\n", f"<!-- {name}:end -->"
    if begin not in results_page or end not in results_page:
        failures.append(f"results/README.md has no {name} markers")
        continue
    spliced = results_page.split(begin, 1)[1].split(end, 1)[0]
    if spliced != open(os.path.join(root, generated)).read():
        failures.append(f"results/README.md's {name} table is not {generated}: run tools/run.sh (or tools/splice_readme.py {name} {generated})")
for page in ["README.md"]:
    if "<!--" in open(os.path.join(root, page)).read():
        failures.append(f"{page} holds a generated table: splice into results/README.md instead")

print("\n".join(failures) or f"ok: README.md {size} bytes, {len(pages)} pages, links and generated tables current")
sys.exit(1 if failures else 0)
