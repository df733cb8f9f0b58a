"""Figures from Python: Branch.plot(), Trace.plot(), SweepResult.plot(), MapSweepResult.plot() and
stickslip.plot() return matplotlib Figures (the module stickslip.plotting, the same file as
tools/stickslip_plot.py, which `stickslip plot` runs), bad options raise ValueError with the command
line's one line, and Trace.to_pandas() carries the branches' measure columns."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

import stickslip  # noqa: E402
from conftest import RESULTS  # noqa: E402


def test_branch_plot_is_a_figure_of_the_branch():
    branch = stickslip.Branch.load(RESULTS / "paper-5.1-omega-up")
    fig = branch.plot()
    assert isinstance(fig, matplotlib.figure.Figure)
    ax = fig.axes[0]
    assert ax.get_yscale() == "linear" and "omega" in ax.get_xlabel()
    labels = {t.get_text() for t in ax.texts}
    assert {"LP4", "TR2"} <= labels, labels
    plt.close(fig)
    fig = branch.plot(y="stick-fraction", yscale="log", size=(4, 3))
    assert fig.axes[0].get_yscale() == "log" and tuple(fig.get_size_inches()) == (4, 3)
    plt.close(fig)
    with pytest.raises(ValueError, match=r"^dpi = '5' is invalid: valid 10 to 1200"):
        branch.plot(dpi=5)
    with pytest.raises(ValueError, match=r"^y = 'nope' is invalid: valid a numeric column"):
        branch.plot(y="nope")


def test_trace_plot_and_to_pandas():
    trace = stickslip.Trace.load(RESULTS / "paper-4.1-omega-trace")
    fig = trace.plot(xlim=(0.3, 0.8))
    ax = fig.axes[0]
    # omega1 = 0.7012 (eq. 56) lies inside the limits: a dotted line there.
    omega1, _ = stickslip.plotting.natural_frequencies(0.3, 4.0)
    assert any(line.get_linestyle() == ":" and abs(line.get_xdata()[0] - omega1) < 1e-12 for line in ax.get_lines())
    plt.close(fig)
    frame = trace.to_pandas()
    assert {"branch", "signature", "omega", "amplitude:x2", "peak-to-peak:x2", "stick-fraction"} <= set(frame.columns)
    assert len(frame) == sum(len(b) for b in trace.branches)


def test_sweep_and_map_plots_and_overlays():
    sweep = stickslip.sweep(preset="paper-5.1", range=(0.56, 0.58), steps=4, transients=50, periods=4, chains=1)
    fig = sweep.plot()
    assert isinstance(fig, matplotlib.figure.Figure)
    plt.close(fig)
    branch = stickslip.Branch.load(RESULTS / "paper-5.1-omega-up")
    fig = stickslip.plot(branch, sweep, RESULTS / "paper-5.1-omega-down")
    assert len(fig.axes) == 1
    plt.close(fig)
    m = stickslip.map_sweep(preset="paper-6", first_range=(0.55, 0.56), second_range=(1.3, 1.4), first_steps=1,
                            second_steps=1, transients=20, periods=4, starts=0)
    fig = m.plot()
    assert len([a for a in fig.axes if a.get_label() != "<colorbar>"]) >= 2
    plt.close(fig)


def test_plot_writes_the_format_of_its_extension(tmp_path):
    branch = stickslip.Branch.load(RESULTS / "paper-5.1-fold-curve")
    for extension, magic in ((".png", b"\x89PNG"), (".pdf", b"%PDF"), (".svg", b"<?xml")):
        path = tmp_path / f"curve{extension}"
        stickslip.plot(branch, output=path)
        assert path.read_bytes().startswith(magic), extension
    with pytest.raises(ValueError, match=r"output = '.*curve.jpg' is invalid: valid a file name ending in .png, .pdf or .svg"):
        stickslip.plot(branch, output=tmp_path / "curve.jpg")
    assert not (tmp_path / "curve.jpg").exists()


def test_plot_keeps_a_file_it_did_not_write(tmp_path):
    # stickslip.plot(output=) replaced any file (a thesis.pdf) before; now only a figure it wrote,
    # or any with force=True; a missing directory is refused before the drawing.
    branch = stickslip.Branch.load(RESULTS / "paper-5.1-fold-curve")
    thesis = tmp_path / "thesis.pdf"
    thesis.write_bytes(b"%PDF-1.4 the user's\n")
    with pytest.raises(ValueError, match=r"^output = '.*thesis.pdf' is invalid: valid a new file or a figure stickslip plot wrote"):
        stickslip.plot(branch, output=thesis)
    assert thesis.read_bytes() == b"%PDF-1.4 the user's\n"
    figure = tmp_path / "figure.svg"
    stickslip.plot(branch, output=figure)
    stickslip.plot(branch, output=figure, title="again")  # its own figure is replaced
    assert b"again" in figure.read_bytes()
    stickslip.plot(branch, output=thesis, force=True)
    assert thesis.read_bytes().startswith(b"%PDF") and b"the user's" not in thesis.read_bytes()
    with pytest.raises(ValueError, match=r"a file in an existing directory"):
        stickslip.plot(branch, output=tmp_path / "missing" / "figure.png")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["figure.svg", "thesis.pdf"]
