"""Pictures of spinning billiards on matplotlib: tables, trajectories,
Birkhoff sections, FTLE maps and λ(α) with error bars.

An optional part of the package: it needs matplotlib, installed with the
``plot`` extra (``pip install 'spinball[plot]'``, or from a clone
``pip install './crates/spinball-py[plot]'``). ``import spinball`` never
imports matplotlib; ``import spinball.plot`` does, and says how to install
it when it is missing.

Every function draws into ``ax`` (a new figure's axes when ``ax`` is
``None``) and returns the axes, so pictures compose::

    import matplotlib.pyplot as plt
    import spinball
    from spinball import plot

    table = spinball.Stadium(a=1)
    b = spinball.Billiard(table, 0.5)
    traj = b.trajectory(50, (0.1, 0.2), (0.6, 0.8))
    ax = plot.trajectory(table, traj)        # the path, coloured by spin
    ax.figure.savefig("stadium.png")

The data come from the library: the outline of a table from
``Table.outline()`` (computed in Rust), the points of a section from
``spinball.section``, the map from ``spinball.ftle_map``, the estimates from
``spinball.lyapunov`` or ``spinball.alpha_sweep``. This module only draws.
"""

try:
    import matplotlib  # noqa: F401
except ImportError as e:  # pragma: no cover - exercised in a subprocess
    raise ImportError(
        "spinball.plot needs matplotlib: install the plot extra, "
        "pip install 'spinball[plot]' (from a clone of the repository: "
        "pip install './crates/spinball-py[plot]'), or pip install matplotlib"
    ) from e

import numpy as np

from . import _spinball

__all__ = ["table", "trajectory", "section", "ftle_map", "lyapunov", "animate"]

#: Fill of a table's interior and of its obstacles.
TABLE_FILL = "#f4f5f8"
OBSTACLE_FILL = "#c8cbd2"
#: How far error-bar caps reach beyond their marker (points).
CAP_OVERHANG = 3.0


def _axes(ax):
    """``ax``, or the axes of a new figure."""
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots()
    return ax


def _as_table(t):
    """A table object from a table or a spec string."""
    if isinstance(t, _spinball.Table):
        return t
    if isinstance(t, str):
        return _spinball.table(t)
    raise TypeError(f"expected a spinball Table or a spec string, got {type(t).__name__}")


def table(table, ax=None, *, edgecolor="black", linewidth=1.5):
    """Draw a table to scale: its interior, its obstacles and its walls.

    Parameters
    ----------
    table : spinball.Table or str
        The table, or a spec string such as ``"stadium:a=1"``.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: a new figure).
    edgecolor : color, optional
        Colour of the walls.
    linewidth : float, optional
        Width of the walls (points).

    Returns
    -------
    matplotlib.axes.Axes
        The axes, with equal aspect and the table's spec as title.

    Examples
    --------
    >>> ax = plot.table(spinball.Sinai(L=2, R=1))
    """
    from matplotlib.patches import Polygon

    t = _as_table(table)
    ax = _axes(ax)
    loops = t.outline()
    # Interiors first, obstacles over them, walls on top.
    for points, hole in sorted(loops, key=lambda lp: lp[1]):
        ax.add_patch(
            Polygon(points, closed=True, facecolor=OBSTACLE_FILL if hole else TABLE_FILL,
                    edgecolor="none", zorder=0)
        )
    for points, _ in loops:
        ax.plot(points[:, 0], points[:, 1], color=edgecolor, linewidth=linewidth, zorder=3)
    xmin, ymin, xmax, ymax = t.bounds
    pad = 0.03 * max(xmax - xmin, ymax - ymin)
    ax.set_xlim(xmin - pad, xmax + pad)
    ax.set_ylim(ymin - pad, ymax + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    if not ax.get_title():
        ax.set_title(t.spec)
    return ax


_draw_table = table


def trajectory(table, trajectory, ax=None, *, cmap="viridis", colorbar=True, linewidth=1.2):
    """Draw a trajectory on its table, each flight coloured by the spin it carries.

    Parameters
    ----------
    table : spinball.Table or str
        The table the trajectory ran on.
    trajectory : spinball.Trajectory
        From ``Billiard.trajectory``: the start and every collision.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: a new figure).
    cmap : str or Colormap, optional
        Colour map of the spin ``u = rω``.
    colorbar : bool, optional
        Add a colour bar of the spin beside the axes.
    linewidth : float, optional
        Width of the path (points).

    Returns
    -------
    matplotlib.axes.Axes
        The axes: the table (as :func:`table`), the path as a
        ``LineCollection`` and the start as a black dot.

    Notes
    -----
    The flight from the start to the first collision carries the start's
    spin; the flight after collision ``k`` carries ``trajectory.u[k]``, the
    spin just after it. At α = 0 the spin never changes and every flight
    has one colour.
    """
    from matplotlib.collections import LineCollection
    from matplotlib.colors import Normalize

    ax = _draw_table(table, ax)
    x0, y0, _, _, u0 = trajectory.start
    xs = np.concatenate([[x0], np.asarray(trajectory.x)])
    ys = np.concatenate([[y0], np.asarray(trajectory.y)])
    spins = np.concatenate([[u0], np.asarray(trajectory.u)[:-1]])
    segments = np.stack([np.column_stack([xs[:-1], ys[:-1]]), np.column_stack([xs[1:], ys[1:]])], axis=1)
    lo, hi = float(np.min(spins)), float(np.max(spins))
    if not hi > lo:
        # One spin throughout: still a scale around it.
        w = 0.1 * abs(lo) if lo != 0 else 0.5
        lo, hi = lo - w, hi + w
    lines = LineCollection(segments, cmap=cmap, norm=Normalize(lo, hi), linewidths=linewidth, zorder=2)
    lines.set_array(spins)
    ax.add_collection(lines)
    ax.plot([x0], [y0], "o", color="black", markersize=5, zorder=4)
    if colorbar:
        ax.figure.colorbar(lines, ax=ax, label="spin u = rω")
    return ax


def section(section, ax=None, *, table=None, color_by="u", cmap="viridis", size=2.0, colorbar=True):
    """Draw a Birkhoff section: the points ``(s, sin θ)``, coloured by spin.

    Parameters
    ----------
    section : dict
        From ``spinball.section``: arrays ``s``, ``sin_theta``, ``u``, ...
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: a new figure).
    table : spinball.Table or str, optional
        The table, to fix the s axis to its perimeter (default: the data).
    color_by : str, optional
        The column that colours the points (``"u"``, ``"q"``, ``"orbit"``,
        ...), or ``None`` for one colour.
    cmap : str or Colormap, optional
        Colour map.
    size : float, optional
        Marker area (points²).
    colorbar : bool, optional
        Add a colour bar.

    Returns
    -------
    matplotlib.axes.Axes
        The axes, holding one ``PathCollection`` of the points.
    """
    ax = _axes(ax)
    s = np.asarray(section["s"])
    y = np.asarray(section["sin_theta"])
    c = None if color_by is None else np.asarray(section[color_by])
    points = ax.scatter(s, y, c=c, s=size, cmap=cmap if c is not None else None, linewidths=0)
    if table is not None:
        ax.set_xlim(0.0, _as_table(table).perimeter)
    ax.set_ylim(-1.0, 1.0)
    ax.set_xlabel("arc length s")
    ax.set_ylabel("sin θ = v∥/|v|")
    if colorbar and c is not None:
        label = "spin u = rω" if color_by == "u" else color_by
        ax.figure.colorbar(points, ax=ax, label=label)
    return ax


def ftle_map(ftle_map, ax=None, *, cmap="viridis", colorbar=True, predicted=True):
    """Draw an FTLE map as an image, with the predicted bouncing-ball island.

    Parameters
    ----------
    ftle_map : dict
        From ``spinball.ftle_map``: ``exponents`` of shape ``(rows, columns)``
        (row 0 at the bottom, NaN off the energy shell), ``perimeter``,
        ``row_label``, ``predicted``.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: a new figure).
    cmap : str or Colormap, optional
        Colour map of the exponent (cells off the shell stay blank).
    colorbar : bool, optional
        Add a colour bar of the FTLE.
    predicted : bool, optional
        Outline, in red, the cells the bouncing-ball rotation predicts
        regular (stadiums only; nothing otherwise).

    Returns
    -------
    matplotlib.axes.Axes
        The axes, holding the map as an ``AxesImage``.
    """
    ax = _axes(ax)
    grid = np.asarray(ftle_map["exponents"], dtype=float)
    extent = (0.0, float(ftle_map["perimeter"]), -1.0, 1.0)
    image = ax.imshow(
        np.ma.masked_invalid(grid), origin="lower", extent=extent, aspect="auto", cmap=cmap,
        vmin=0.0, interpolation="nearest",
    )
    mask = ftle_map.get("predicted")
    if predicted and mask is not None and np.any(mask):
        rows, columns = grid.shape
        s = (np.arange(columns) + 0.5) * extent[1] / columns
        r = -1.0 + 2.0 * (np.arange(rows) + 0.5) / rows
        ax.contour(s, r, np.asarray(mask, dtype=float), levels=[0.5], colors="red", linewidths=1.5)
    ax.set_xlabel("arc length s")
    ax.set_ylabel(ftle_map.get("row_label", "row"))
    if colorbar:
        ax.figure.colorbar(image, ax=ax, label="FTLE λ (1/time)")
    return ax


def _two_digits(x):
    """``x`` to two significant digits, as a legend shows it."""
    return f"{x:.2g}"


def lyapunov(results, ax=None, *, label=None, color=None, marker="o", markersize=6.0):
    """Draw λ(α) with its standard errors, the bars over the markers.

    Parameters
    ----------
    results : spinball.LyapunovResult or sequence of them
        From ``spinball.lyapunov`` or ``spinball.alpha_sweep``: one point
        per result, at its ``alpha``.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: a new figure).
    label : str, optional
        Legend entry (default: the table's spec); the largest SEM is
        appended, since bars can be shorter than the markers.
    color : color, optional
        Colour of the markers and line (default: the next of the cycle).
    marker : str, optional
        Marker style.
    markersize : float, optional
        Marker size (points).

    Returns
    -------
    matplotlib.axes.Axes
        The axes: the line with markers, then the error bars drawn over
        them in a darker shade with caps wider than the markers (a bar
        shorter than its marker still shows its caps).
    """
    from matplotlib.colors import to_rgb

    if isinstance(results, _spinball.LyapunovResult):
        results = [results]
    results = sorted(results, key=lambda r: r.alpha)
    if not results:
        raise ValueError("lyapunov: no result to draw")
    ax = _axes(ax)
    alpha = np.array([r.alpha for r in results])
    mean = np.array([r.mean for r in results])
    sem = np.array([r.sem for r in results])
    name = label if label is not None else results[0].table
    text = f"{name}: mean λ ± SEM (largest SEM {_two_digits(float(np.max(sem)))})"
    (line,) = ax.plot(alpha, mean, marker=marker, markersize=markersize, color=color, label=text, zorder=2)
    shade = tuple(0.45 * c for c in to_rgb(line.get_color()))
    ax.errorbar(
        alpha, mean, yerr=sem, fmt="none", ecolor=shade, elinewidth=1.5,
        capsize=markersize / 2 + CAP_OVERHANG, capthick=1.5, zorder=3,
    )
    ax.set_xlabel("spin parameter α = I/(m r²)")
    ax.set_ylabel("λ (1/time)")
    ax.legend()
    return ax


def animate(table, alpha, path, **options):
    """Write a film (GIF, or MP4 where ``ffmpeg`` is installed) of balls on a table.

    The same film as ``spinball.animate`` and ``spinball animate`` on the
    command line: the frames are computed and drawn by the library (exact
    collisions, a marker turning with each ball's spin), so the file does
    not depend on matplotlib's version. Offered here beside the pictures
    so a user finds every picture in one module.

    Parameters
    ----------
    table : Table or str
        The table, e.g. ``Stadium(a=1)`` or ``"stadium:a=1"``.
    alpha : float
        Spin parameter ``α = I/(m r²)``.
    path : str or os.PathLike
        ``.gif`` or ``.mp4``.
    **options
        As for :func:`spinball.animate`: ``balls``, ``initial_states``,
        ``seed``, ``fps``, ``duration``, ``speed``, ``radius``, ``size``,
        ``title``, ...

    Returns
    -------
    dict
        The frames written (``times``, ``positions``, ``angles``, ``spins``,
        ``collisions``) as NumPy arrays, as :func:`spinball.animate` returns.
    """
    return _spinball.animate(table, alpha, path, **options)
