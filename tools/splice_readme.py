#!/usr/bin/python3
"""Copies a generated Markdown file into results/README.md between <!-- NAME:begin --> and
<!-- NAME:end -->, so that the results page shows results without anyone editing them by hand.
(The front page, README.md, holds no generated table: it links to results/README.md.)
Usage: tools/splice_readme.py NAME FILE"""
import os
import sys

name, source = sys.argv[1], sys.argv[2]
readme_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "results", "README.md")
readme = open(readme_path).read()
begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
if begin not in readme or end not in readme:
    sys.exit(f"splice_readme.py: {readme_path} has no {begin} ... {end} markers")
head, rest = readme.split(begin, 1)
_, tail = rest.split(end, 1)
with open(readme_path + ".tmp", "w") as out:
    out.write(head + begin + "\n" + open(source).read() + end + tail)
os.replace(readme_path + ".tmp", readme_path)
