"""Spinning billiards from Python, over the Rust engine of spinball.

A ball that carries spin ``u = rω`` moves freely inside a table; at each
wall it trades tangential velocity for spin through ``alpha = I/(m r²)``
(0 specular, 0.4 solid sphere, 0.5 disk, 1 thin ring). This package gives
the tables, single trajectories as NumPy arrays, and ensemble estimates of
the largest Lyapunov exponent (``lyapunov``, ``alpha_sweep``), its
distribution (``LyapunovResult.ftle()``) and the full spectrum
(``spectrum``), with standard errors, the cost and the parameters of every
number; and phase space as NumPy arrays: Birkhoff sections (``section``),
FTLE maps at fixed spin or fixed Q with the predicted bouncing-ball island
(``ftle_map``), return times against Kac's lemma (``kac``), starts drawn
from the invariant measure of the collision map (``invariant_states``) and
the bouncing-ball prediction (``bouncing_ball``, ``pair_rotation``); and
films of balls on a table with their spin (``animate``, a GIF or MP4).
Exponents are per unit time at energy ½ (the paper's units: J. S.
Lund, J. Murugan, J. P. Shock, *Spinning Billiards and Chaos*,
arXiv:2505.15335).

Pictures: ``spinball.plot`` draws tables, trajectories coloured by spin,
sections, FTLE maps and λ(α) with error bars on matplotlib (the optional
``plot`` extra; ``import spinball`` alone does not import matplotlib).

Tables: ``Circle(R=1)``, ``Rectangle(L=1, H=1)``, ``Stadium(a=1)``,
``Sinai(L=2, R=1)`` (the keywords of the spec strings ``circle:R=1``,
``rectangle:L=1,H=1``, ``stadium:a=1``, ``sinai:L=2,R=1``), ``SegmentTable(outer, holes)`` from ``Line`` and
``Arc`` walls (or ``SegmentTable.polygon(vertices)``), ``table("stadium:a=1")``.

Defaults are those of the library and of the ``spinball`` command line
(seed 0, the paper's sampler and finite-difference method, 1000 initial
conditions of 10 000 collisions, threshold 0.01; docs/DEFAULTS.md lists
them all with the parameter names of every front), so the same run gives
the same numbers from Python, Rust and the shell.

Errors: invalid input raises ``ValueError`` with the Rust message, a run
that fails ``RuntimeError``; Ctrl-C during a run raises
``KeyboardInterrupt`` after the current batch.

>>> import spinball
>>> r = spinball.lyapunov("stadium:a=1", 0.5, ics=200, collisions=5000, seed=1)
>>> 0.15 < r.mean < 0.22
True
"""

from ._spinball import (
    CHAOS_THRESHOLD,
    PAPER_DELTA0,
    THRESHOLD_BAND,
    Arc,
    Billiard,
    Circle,
    DiffusionResult,
    EscapeResult,
    FtleDistribution,
    Line,
    LorentzGas,
    LyapunovResult,
    MultilevelResult,
    Rectangle,
    SegmentTable,
    Sinai,
    SpectrumResult,
    Stadium,
    Table,
    Trajectory,
    __version__,
    alpha_sweep,
    animate,
    bouncing_ball,
    diffuse,
    escape,
    ftle_map,
    invariant_states,
    kac,
    lyapunov,
    pair_rotation,
    plus_minus,
    periodic_orbits,
    island_sizes,
    read_results,
    section,
    spectrum,
    table,
    table_file,
    write_results,
)

__all__ = [
    "CHAOS_THRESHOLD",
    "PAPER_DELTA0",
    "THRESHOLD_BAND",
    "Arc",
    "Billiard",
    "Circle",
    "DiffusionResult",
    "EscapeResult",
    "FtleDistribution",
    "Line",
    "LorentzGas",
    "LyapunovResult",
    "MultilevelResult",
    "Rectangle",
    "SegmentTable",
    "Sinai",
    "SpectrumResult",
    "Stadium",
    "Table",
    "Trajectory",
    "__version__",
    "alpha_sweep",
    "animate",
    "bouncing_ball",
    "diffuse",
    "escape",
    "ftle_map",
    "invariant_states",
    "kac",
    "lyapunov",
    "pair_rotation",
    "plus_minus",
    "periodic_orbits",
    "island_sizes",
    "read_results",
    "section",
    "spectrum",
    "table",
    "table_file",
    "write_results",
]
