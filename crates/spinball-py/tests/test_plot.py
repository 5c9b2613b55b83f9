"""spinball.plot: each function returns the Axes with what it drew; the
module is optional (matplotlib is an extra) and ``import spinball`` does
not load matplotlib."""

import subprocess
import sys

import numpy as np
import pytest

import spinball

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PathCollection  # noqa: E402
from matplotlib.image import AxesImage  # noqa: E402

from spinball import plot  # noqa: E402


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def test_importing_spinball_does_not_import_matplotlib():
    code = "import sys, spinball; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_without_matplotlib_the_error_says_how_to_install():
    # A None entry in sys.modules makes `import matplotlib` fail.
    code = (
        "import sys; sys.modules['matplotlib'] = None\n"
        "try:\n    import spinball.plot\nexcept ImportError as e:\n    print(e)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "pip install" in out.stdout and "[plot]" in out.stdout


def test_table_draws_walls_and_holes_from_the_rust_outline():
    t = spinball.Sinai(L=2, R=1)
    loops = t.outline()
    assert [hole for _, hole in loops] == [False, True]
    outer, disk = loops[0][0], loops[1][0]
    assert outer.shape == (5, 2)
    np.testing.assert_allclose(np.hypot(disk[:, 0], disk[:, 1]), 1.0, atol=1e-12)
    ax = plot.table(t)
    assert isinstance(ax, mpl.axes.Axes)
    assert len(ax.lines) == 2 and len(ax.patches) == 2
    assert ax.get_title() == t.spec
    assert ax.get_xlabel() == "x" and ax.get_ylabel() == "y"


def test_trajectory_is_a_line_collection_coloured_by_spin():
    table = spinball.Stadium(a=1)
    traj = spinball.Billiard(table, 0.5).trajectory(40, (0.1, 0.2), (0.6, 0.8), spin=0.3)
    ax = plot.trajectory(table, traj)
    (lines,) = [c for c in ax.collections if isinstance(c, LineCollection)]
    assert len(lines.get_segments()) == 40
    spins = lines.get_array()
    assert spins[0] == pytest.approx(0.3)
    np.testing.assert_allclose(spins[1:], np.asarray(traj.u)[:-1])
    # The colour bar is a second axes of the figure.
    assert len(ax.figure.axes) == 2
    # At α = 0 the spin never changes: still one scale, no error.
    flat = spinball.Billiard(table, 0.0).trajectory(10, (0.1, 0.2), (0.6, 0.8))
    plot.trajectory(table, flat, colorbar=False)


def test_section_is_a_scatter_of_s_and_sin_theta():
    sec = spinball.section("stadium:a=1", 0.5, orbits=2, collisions=100, seed=1)
    ax = plot.section(sec, table="stadium:a=1")
    (points,) = [c for c in ax.collections if isinstance(c, PathCollection)]
    assert len(points.get_offsets()) == len(sec["s"]) == 200
    assert ax.get_xlim() == pytest.approx((0.0, spinball.Stadium(a=1).perimeter))
    assert "sin θ" in ax.get_ylabel() and ax.get_xlabel() == "arc length s"


def test_ftle_map_is_an_image_with_the_island_outlined():
    m = spinball.ftle_map("stadium:a=1", 0.5, columns=12, rows=8, collisions=100, seed=1)
    ax = plot.ftle_map(m)
    (image,) = [i for i in ax.get_images() if isinstance(i, AxesImage)]
    assert image.get_array().shape == (8, 12)
    assert image.get_extent() == pytest.approx([0.0, m["perimeter"], -1.0, 1.0])
    assert ax.get_ylabel() == m["row_label"]
    if m["predicted"] is not None and np.any(m["predicted"]):
        assert len(ax.collections) >= 1


def test_lyapunov_draws_bars_over_markers_and_names_the_sem():
    results = spinball.alpha_sweep("stadium:a=1", [0.0, 0.5, 1.0], ics=8, collisions=300, seed=1)
    ax = plot.lyapunov(results)
    (line,) = ax.lines[:1]
    np.testing.assert_allclose(line.get_xdata(), [0.0, 0.5, 1.0])
    np.testing.assert_allclose(line.get_ydata(), [r.mean for r in results])
    # The error bars: a LineCollection above the line's markers.
    bars = [c for c in ax.collections if isinstance(c, LineCollection)]
    assert bars and all(b.get_zorder() > line.get_zorder() for b in bars)
    (legend,) = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "SEM" in legend and f"{max(r.sem for r in results):.2g}" in legend
    assert "α" in ax.get_xlabel() and "λ" in ax.get_ylabel()
    # One result is a point.
    ax2 = plot.lyapunov(results[1])
    assert len(ax2.lines[0].get_xdata()) == 1


def test_plot_animate_writes_the_library_film(tmp_path):
    # plot.animate is the library's film (the same bytes as spinball.animate).
    a = tmp_path / "a.gif"
    b = tmp_path / "b.gif"
    film = plot.animate("stadium:a=1", 0.5, a, balls=2, fps=10, duration=1.0, size=(160, 100))
    spinball.animate("stadium:a=1", 0.5, b, balls=2, fps=10, duration=1.0, size=(160, 100))
    assert a.read_bytes() == b.read_bytes()
    assert a.read_bytes()[:6] == b"GIF89a"
    assert film["positions"].shape == (2, 10, 2)
