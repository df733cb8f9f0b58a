#!/usr/bin/python3
"""The frequency response of the section 5.1 orbit from Python: the branch continued in omega both
ways from the paper's orbit and a brute-force sweep overlaid (the motions simulation settles on),
drawn by stickslip.plot as `stickslip plot` draws stored results (stable solid, unstable dashed,
special points labelled, max |x2| over a period against omega).

    PYTHONPATH=build/release/lib/python /usr/bin/python3 tools/frequency_response.py [out.png|.pdf|.svg]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import stickslip  # noqa: E402


def main(out):
    up = stickslip.continue_orbit("omega", (0.3, 0.9), preset="paper-5.1", ds=0.005, ds_max=0.05, output="up")
    down = stickslip.continue_orbit("omega", (0.3, 0.9), preset="paper-5.1", direction="down", ds=0.005,
                                    ds_max=0.05, output="down")
    sweep = stickslip.sweep(preset="paper-5.1", range=(0.55, 0.6), steps=50, transients=500, periods=20, chains=4)
    stickslip.plot(up, down, sweep, output=out, title="Section 5.1: 'slip- slip+ stick slip+' (Pascal 2014) and the "
                   "brute force")
    print(f"{up}\n{down}\nsweep: {len(sweep)} rows on {sweep.threads} threads\nwritten to {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "frequency-response.png")
