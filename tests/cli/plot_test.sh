#!/usr/bin/env bash
# Smoke test of the figures: tools/plot_figures.py runs on a copy of the shipped results and
# writes every expected PNG, non-empty, 800 x 600 pixels (the bifurcation diagrams 1150 x 600, their
# legend beside the axes; the traces' frequency responses as `stickslip plot` draws them, 1350 x 750). (What they show is checked by eye; the
# README.md and results/README.md embed or link them.)
set -euo pipefail
bin=${STICKSLIP:?set STICKSLIP to the stickslip program}
root=${STICKSLIP_SOURCE:?set STICKSLIP_SOURCE to the source tree}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/results" "$work/results"
rm -rf "$work/results/figures"
/usr/bin/python3 "$root/tools/plot_figures.py" --stickslip "$bin" --results "$work/results" > /dev/null
/usr/bin/python3 - "$work/results" <<'PY'
import os, sys
import matplotlib.image as image
results = sys.argv[1]
expected = [f"paper-{p}-phase.png" for p in ("4.1", "4.2", "5.1", "5.2", "6")]
expected += [f"paper-{p}-velocity.png" for p in ("4.1", "4.2", "5.1", "5.2", "6")]
expected += [f"paper-{p}-constraints.png" for p in ("5.1", "5.2", "6")]
expected += [f"{run}-bifurcation.png" for run in sorted(os.listdir(results))
             if os.path.isfile(os.path.join(results, run, "summary.json"))]
traces = [f"{run}-frequency-response.png" for run in sorted(os.listdir(results))
          if os.path.isfile(os.path.join(results, run, "trace.json"))]
assert len(traces) >= 5, traces
expected += traces
for name in expected:
    path = os.path.join(results, "figures", name)
    assert os.path.getsize(path) > 10000, name
    height, width = image.imread(path).shape[:2]
    size = (1150, 600) if name.endswith("-bifurcation.png") else (
        (1350, 750) if name.endswith("-frequency-response.png") else (800, 600))
    assert (width, height) == size, (name, width, height)
print(f"{len(expected)} figures, 800 x 600, the bifurcation diagrams 1150 x 600, the frequency responses 1350 x 750")
PY
