#!/usr/bin/python3
"""Compares two result trees (copies of results/: a commit's, e.g. from `git worktree` or `git archive`,
and the working tree's) number by number, to check that a change meant only to be faster moved the
results at rounding level: every file on both sides, the same number of points in each, every changed
number within |new - old| <= REL * max(|old|, the scale of its column). Byte-identical files are only
counted; every other file gets one line, sorted by path:
  - .csv: the same header, rows and text cells; a column's scale is max |x| over it in OLD's file;
  - .json: the same keys, list lengths, strings, booleans and nulls; a number's scale is max |x| over
    the numbers of its key path in OLD's file, list indices wildcarded (points[*].omega);
  - .md, .txt: the same text between the numbers; each number relative to itself, or, where it moved
    by at most one unit in its last printed digit, "printed digits changed" (listed, not failing; an
    integer has no such leeway: counts must match);
  - .png, .svg, .pdf: identical or differing (listed, not failing: figures move with their data);
  - anything else must be byte-identical.
nan and inf pass only when printed alike; a file on one side only fails. Exits 0 when every file
passes, 1 otherwise.

Usage: /usr/bin/python3 tools/compare_results.py OLD_DIR NEW_DIR [--relative 1e-12]"""
import argparse
import csv
import io
import json
import math
import os
import re
import sys
from decimal import Decimal

NUMBER = re.compile(r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)")
FIGURES = (".png", ".svg", ".pdf")


class Tally:
    """What comparing one file found: numbers seen and changed, the largest Δ/max(|x|, scale) and
    where, the printed digits that changed, and the first mismatch (which fails the file)."""

    def __init__(self, rel):
        self.rel, self.seen, self.changed, self.worst, self.where = rel, 0, 0, 0.0, ""
        self.digits, self.digits_worst, self.digits_where = 0, 0.0, ""
        self.mismatch = None

    def fail(self, message):
        if self.mismatch is None:
            self.mismatch = message

    def number(self, old, new, scale, where):
        """One pair of finite numbers; `scale` is that of its column (key path, token)."""
        self.seen += 1
        if new != old:
            self.changed += 1
            r = ratio(old, new, scale)
            if r > self.worst:
                self.worst, self.where = r, where

    def printed(self, r, where):
        self.digits += 1
        if r > self.digits_worst:
            self.digits_worst, self.digits_where = r, where

    def status(self):
        failed = self.mismatch is not None or self.worst > self.rel
        return "fail" if failed else "digits" if self.digits else "ok"

    def line(self, size):
        """The report's text for this file; `size` says what it holds (e.g. '25 rows')."""
        parts = [size]
        if self.changed:
            parts.append(f"{count(self.changed, 'number')} changed, max {self.worst:.2g} at {self.where}")
        elif not (self.digits or self.mismatch):
            parts.append("no number changed in value")
        if self.digits:
            parts.append(f"{count(self.digits, 'number')} with printed digits changed, "
                         f"max relative {self.digits_worst:.2g} at {self.digits_where}")
        if self.mismatch:
            parts.append(self.mismatch)
        return "; ".join(parts)


def count(n, noun):
    return f"{n} {noun}" + ("" if n == 1 else "s")


def ratio(old, new, scale):
    delta, size = abs(new - old), max(abs(old), scale)
    return delta / size if size > 0 else 0.0 if delta == 0 else math.inf


def finite(text):
    """The cell's number, or None when it is text, nan or inf."""
    try:
        x = float(text)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def shorten(value):
    return repr(value)[:40]


def csv_rows(text):
    return list(csv.reader(io.StringIO(text, newline="")))


def column_scales(rows):
    scales = {}
    for row in rows:
        for j, cell in enumerate(row):
            x = finite(cell)
            if x is not None:
                scales[j] = max(scales.get(j, 0.0), abs(x))
    return scales


def compare_csv(old_text, new_text, tally):
    old, new = csv_rows(old_text), csv_rows(new_text)
    if old[:1] != new[:1]:
        tally.fail("header differs")
    elif len(old) != len(new):
        tally.fail(f"{len(new) - 1} rows in NEW")
    header, scales = (old or [[]])[0], column_scales(old[1:])
    for i, (a, b) in enumerate(zip(old[1:], new[1:]) if tally.mismatch is None else (), 1):
        if len(a) != len(b):
            tally.fail(f"row {i}: {len(b)} cells in NEW, {len(a)} in OLD")
        for j, (x, y) in enumerate(zip(a, b)):
            where = f"{header[j] if j < len(header) else f'column {j + 1}'}, row {i}"
            compare_cell(x, y, scales.get(j, 0.0), where, tally)
    return count(len(old) - 1, "row")


def compare_cell(x, y, scale, where, tally):
    a, b = finite(x), finite(y)
    if a is not None and b is not None:
        tally.number(a, b, scale, where)
    elif x != y:
        tally.fail(f"{where}: {shorten(x)} in OLD, {shorten(y)} in NEW")


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def json_scales(value, where, scales):
    if isinstance(value, dict):
        for key, item in value.items():
            json_scales(item, f"{where}.{key}" if where else key, scales)
    elif isinstance(value, list):
        for item in value:
            json_scales(item, where + "[*]", scales)
    elif is_number(value) and math.isfinite(value):
        scales[where] = max(scales.get(where, 0.0), abs(value))


def compare_json(old, new, where, scales, tally):
    if isinstance(old, dict) and isinstance(new, dict):
        if old.keys() != new.keys():
            keys = ", ".join(sorted(old.keys() ^ new.keys()))
            return tally.fail(f"{where or 'top'}: keys {keys} on one side only")
        for key in old:
            compare_json(old[key], new[key], f"{where}.{key}" if where else key, scales, tally)
    elif isinstance(old, list) and isinstance(new, list):
        if len(old) != len(new):
            return tally.fail(f"{where}: {len(new)} items in NEW, {len(old)} in OLD")
        for i, (a, b) in enumerate(zip(old, new)):
            compare_json(a, b, f"{where}[{i}]", scales, tally)
    elif is_number(old) and is_number(new) and math.isfinite(old) and math.isfinite(new):
        tally.number(old, new, scales.get(re.sub(r"\[\d+\]", "[*]", where), 0.0), where)
    elif type(old) is not type(new) or (old != new and not (old != old and new != new)):
        tally.fail(f"{where}: {shorten(old)} in OLD, {shorten(new)} in NEW")


def compare_json_text(old_text, new_text, tally):
    try:
        old, new = json.loads(old_text), json.loads(new_text)
    except ValueError as error:
        tally.fail(f"not JSON: {error}")
        return "?"
    scales = {}
    json_scales(old, "", scales)
    compare_json(old, new, "", scales, tally)
    return count(tally.seen, "number")


def last_digit(token):
    """One unit in the last printed digit of a number token: 1e-4 for 0.1235, 1e-17 for 3.025e-14."""
    return Decimal(1).scaleb(Decimal(token).as_tuple().exponent)


def compare_token(x, y, where, tally):
    """Two differing number tokens of a text; a move by one unit in the last printed digit (exactly, in
    decimal) is a printed digit changed, an integer's move never is."""
    a, b = float(x), float(y)
    r = ratio(a, b, abs(a))
    moved = abs(Decimal(y) - Decimal(x)) <= max(last_digit(x), last_digit(y))
    if r > tally.rel and moved and not re.fullmatch(r"[-+]?\d+", x):
        tally.printed(r, where)
    else:
        tally.number(a, b, abs(a), where)


def compare_text(old_text, new_text, tally):
    old, new = old_text.splitlines(), new_text.splitlines()
    if len(old) != len(new):
        tally.fail(f"{len(new)} lines in NEW")
    for i, (a, b) in enumerate(zip(old, new) if tally.mismatch is None else (), 1):
        parts, other = NUMBER.split(a), NUMBER.split(b)
        if len(parts) != len(other) or parts[::2] != other[::2]:
            tally.fail(f"line {i}: text differs")
            break
        for x, y in zip(parts[1::2], other[1::2]):
            if x != y:
                compare_token(x, y, f"line {i} ({x} -> {y})", tally)
    return count(len(old), "line")


COMPARE = {".csv": compare_csv, ".json": compare_json_text, ".md": compare_text, ".txt": compare_text}


def compare_file(old_dir, new_dir, path, rel):
    """(status, line): status is identical, ok, digits, figure or fail; line is None when identical."""
    old_path, new_path = os.path.join(old_dir, path), os.path.join(new_dir, path)
    if not os.path.isfile(new_path):
        return "fail", f"{path}: FAIL only in OLD"
    if not os.path.isfile(old_path):
        return "fail", f"{path}: FAIL only in NEW"
    with open(old_path, "rb") as f, open(new_path, "rb") as g:
        old, new = f.read(), g.read()
    if old == new:
        return "identical", None
    extension = os.path.splitext(path)[1].lower()
    if extension in FIGURES:
        return "figure", f"{path}: figure differs"
    if extension not in COMPARE:
        return "fail", f"{path}: FAIL differs (no numeric comparison for {extension or 'this file'})"
    tally = Tally(rel)
    size = COMPARE[extension](old.decode("utf-8", "replace"), new.decode("utf-8", "replace"), tally)
    status = tally.status()
    label = {"fail": "FAIL", "digits": "ok, printed digits changed", "ok": "ok"}[status]
    return status, f"{path}: {label}: {tally.line(size)}"


def files(root):
    return {os.path.relpath(os.path.join(d, name), root) for d, _, names in os.walk(root) for name in names}


def main(old_dir, new_dir, rel):
    for d in (old_dir, new_dir):
        if not os.path.isdir(d):
            raise SystemExit(f"compare_results.py: {d} is not a directory")
    counts = dict.fromkeys(("identical", "ok", "digits", "figure", "fail"), 0)
    for path in sorted(files(old_dir) | files(new_dir)):
        status, line = compare_file(old_dir, new_dir, path, rel)
        counts[status] += 1
        if line:
            print(line)
    within = counts["ok"] + counts["digits"] + counts["figure"]
    print(f"{sum(counts.values())} files compared: {counts['identical']} identical, {within} changed within "
          f"tolerance ({counts['digits']} with printed digits changed, {counts['figure']} figures differing), "
          f"{counts['fail']} failing (relative tolerance {rel:g})")
    return 1 if counts["fail"] else 0


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\nUsage:")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old_dir")
    parser.add_argument("new_dir")
    parser.add_argument("--relative", type=float, default=1e-12, help="the relative tolerance (1e-12)")
    args = parser.parse_args()
    sys.exit(main(args.old_dir, args.new_dir, args.relative))
