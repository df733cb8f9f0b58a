#!/usr/bin/python3
"""The frequency response of the section 5.1 orbit from Python: the branch continued in omega both
ways from the paper's orbit (stable solid, unstable dashed, special points labelled), and a
brute-force sweep overlaid (the motions simulation settles on, up and down in omega).

    PYTHONPATH=build/release/lib/python /usr/bin/python3 tools/frequency_response.py [out.png]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import stickslip


def amplitude(states):
    """max |x1| over one period."""
    return np.max(np.abs(states[:, 0]))


def plot_branch(ax, branch):
    """max |x1| along the branch, solid where stable, dashed where not; the boundary point is drawn
    in both pieces so the curve has no gap."""
    omega = branch["omega"]
    amp = np.array([amplitude(branch.sample(i, 400)[1]) for i in range(len(branch))])
    stable = branch["stable"].astype(bool)
    start = 0
    for i in range(1, len(omega) + 1):
        if i == len(omega) or stable[i] != stable[start]:
            end = min(i + 1, len(omega))
            ax.plot(omega[start:end], amp[start:end], "-" if stable[start] else "--", color="C0", lw=1.5)
            start = i
    for s in branch.special_points:
        if s["test_function"] in ("start",) or s["type"] == "EP":
            continue
        i = s["pt"] - 1
        ax.plot(omega[i], amp[i], "o", color="C3", ms=4)
        ax.annotate(s["label"], (omega[i], amp[i]), textcoords="offset points", xytext=(4, 4), fontsize=8)


def main(out):
    up = stickslip.continue_orbit("omega", (0.3, 0.9), preset="paper-5.1", ds=0.005, ds_max=0.05, output="up")
    down = stickslip.continue_orbit("omega", (0.3, 0.9), preset="paper-5.1", direction="down", ds=0.005,
                                    ds_max=0.05, output="down")
    preset = stickslip.presets["paper-5.1"]
    sweep = stickslip.sweep(preset="paper-5.1", range=(0.55, 0.6), steps=50, transients=500, periods=20, chains=4)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    plot_branch(ax, up)
    plot_branch(ax, down)
    # Brute force: one period simulated from each settled section state, at that step's omega.
    for marker, pass_name in (("^", "up"), ("v", "down")):
        rows = [i for i, p in enumerate(sweep.passes) if p == pass_name]
        amp = []
        for i in rows:
            p = preset.parameters.replace(omega=sweep.value[i])
            motion = stickslip.simulate(p, state=sweep.section[i, -1], phi=sweep.section_phase, periods=1)
            amp.append(amplitude(motion.samples["state"]))
        ax.plot(sweep.value[rows], amp, marker, color="C1", ms=3, alpha=0.6, ls="none",
                label=f"brute force, omega {pass_name} ({sweep.chains} chains)")
    ax.plot([], [], "-", color="C0", label="continuation, stable")
    ax.plot([], [], "--", color="C0", label="continuation, unstable")
    ax.set_xlabel("omega")
    ax.set_ylabel("max |x1| over a period")
    ax.set_title("Section 5.1: slip- slip+ stick slip+ (Pascal 2014)")
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"{up}\n{down}\nsweep: {len(sweep)} rows on {sweep.threads} threads\nwritten to {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "frequency-response.png")
