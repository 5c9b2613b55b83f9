"""Type stubs of the native module ``spinball._spinball`` (re-exported by ``spinball``)."""

import os
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
CHAOS_THRESHOLD: float
PAPER_DELTA0: float
THRESHOLD_BAND: List[float]

Point = Union[Tuple[float, float], Sequence[float], npt.ArrayLike]
TableLike = Union["Table", str]
Progress = Union[None, bool, Callable[[Dict[str, Any]], Any]]

class Table:
    """A billiard table (base class); lengths in the paper's units."""

    @property
    def spec(self) -> str: ...
    @property
    def area(self) -> float: ...
    @property
    def perimeter(self) -> float: ...
    @property
    def curved_length(self) -> float: ...
    @property
    def bounds(self) -> Tuple[float, float, float, float]: ...
    @property
    def shape(self) -> Dict[str, Any]: ...
    def contains(self, x: float, y: float) -> bool: ...
    def outline(self) -> List[Tuple[npt.NDArray[np.float64], bool]]: ...

class Circle(Table):
    def __init__(self, R: float = 1.0) -> None: ...
    @property
    def R(self) -> float: ...
    @property
    def radius(self) -> float: ...

class Rectangle(Table):
    def __init__(self, L: float = 1.0, H: float = 1.0) -> None: ...
    @property
    def L(self) -> float: ...
    @property
    def H(self) -> float: ...
    @property
    def l(self) -> float: ...
    @property
    def h(self) -> float: ...

class Stadium(Table):
    def __init__(self, a: float = 1.0) -> None: ...
    @property
    def a(self) -> float: ...

class Sinai(Table):
    def __init__(self, L: float = 2.0, R: float = 1.0) -> None: ...
    @property
    def L(self) -> float: ...
    @property
    def R(self) -> float: ...
    @property
    def l(self) -> float: ...
    @property
    def r(self) -> float: ...

class Line:
    def __init__(self, start: Point, end: Point) -> None: ...
    @property
    def start(self) -> Tuple[float, float]: ...
    @property
    def end(self) -> Tuple[float, float]: ...
    @property
    def length(self) -> float: ...

class Arc:
    def __init__(self, center: Point, radius: float, start_angle: float, sweep: float) -> None: ...
    @property
    def center(self) -> Tuple[float, float]: ...
    @property
    def radius(self) -> float: ...
    @property
    def start_angle(self) -> float: ...
    @property
    def sweep(self) -> float: ...
    @property
    def start(self) -> Tuple[float, float]: ...
    @property
    def end(self) -> Tuple[float, float]: ...
    @property
    def length(self) -> float: ...

class SegmentTable(Table):
    def __init__(
        self, outer: Sequence[Union[Line, Arc]], holes: Optional[Sequence[Sequence[Union[Line, Arc]]]] = None
    ) -> None: ...
    @staticmethod
    def polygon(vertices: npt.ArrayLike) -> "SegmentTable": ...
    @property
    def outer(self) -> List[Union[Line, Arc]]: ...
    @property
    def holes(self) -> List[List[Union[Line, Arc]]]: ...
    @property
    def kinds(self) -> List[str]:
        """What each wall does: ``"reflecting"``, ``"hole"`` or ``"periodic"``."""
    def with_hole(self, wall: int) -> "SegmentTable":
        """The same table with wall ``wall`` a hole (a ball reaching it leaves)."""
    def with_periodic(self, a: int, b: int) -> "SegmentTable":
        """The same table with walls ``a`` and ``b`` periodic partners."""
    def with_hole_at(self, s: float, size: float) -> "SegmentTable":
        """The same table with a hole of arc length ``size`` centred at Birkhoff ``s``."""
    @staticmethod
    def stadium_with_hole(a: float, s: float, size: float) -> "SegmentTable":
        """The stadium with a hole of arc length ``size`` centred at Birkhoff ``s``
        (the right cap's middle is ``2a + π/2``)."""
    @staticmethod
    def sinai_with_hole(L: float, R: float, s: float, size: float) -> "SegmentTable": ...
    @staticmethod
    def circle_with_hole(R: float, angle: float, size: float) -> "SegmentTable": ...

class LorentzGas:
    """Disks of radius ``R`` on a ``"square"`` or ``"triangular"`` lattice of
    spacing ``w``, run as one cell with periodic sides."""

    def __init__(self, lattice: str = "triangular", w: float = 1.0, R: float = 0.4) -> None: ...
    def table(self) -> SegmentTable:
        """The unit cell, its sides periodic partners."""
    @property
    def horizon(self) -> str:
        """``"finite"`` or ``"infinite"`` (corridors: no finite diffusion coefficient)."""
    @property
    def lattice(self) -> str: ...
    @property
    def w(self) -> float: ...
    @property
    def R(self) -> float: ...
    @property
    def spec(self) -> str:
        """``lorentz:lattice=…,w=…,R=…``, which ``table()`` and ``--table`` read."""

def plus_minus(value: float, error: float) -> str:
    """``value ± error``, the error to two significant digits and the value to
    the same decimal place: ``plus_minus(0.0003124, 0.0000412)`` is
    ``'0.000312 ± 0.000041'``."""

def table(spec: str) -> Table:
    """The built-in table a spec string names (``"stadium:a=1"``)."""

def table_file(path: Union[str, "os.PathLike[str]"]) -> Table:
    """The table a ``.toml`` or ``.json`` table file describes (docs/TABLE_FILES.md)."""

class Trajectory:
    """One trajectory, one array per quantity (length = collisions)."""

    @property
    def time(self) -> npt.NDArray[np.float64]: ...
    @property
    def x(self) -> npt.NDArray[np.float64]: ...
    @property
    def y(self) -> npt.NDArray[np.float64]: ...
    @property
    def vx(self) -> npt.NDArray[np.float64]: ...
    @property
    def vy(self) -> npt.NDArray[np.float64]: ...
    @property
    def u(self) -> npt.NDArray[np.float64]: ...
    @property
    def wall(self) -> npt.NDArray[np.int64]: ...
    @property
    def s(self) -> npt.NDArray[np.float64]: ...
    @property
    def v_par(self) -> npt.NDArray[np.float64]: ...
    @property
    def q(self) -> npt.NDArray[np.float64]: ...
    @property
    def start(self) -> Tuple[float, float, float, float, float]: ...
    def to_dict(self) -> Dict[str, np.ndarray]: ...
    def __len__(self) -> int: ...

class Billiard:
    """A table with the spin law of ``alpha`` (in [0, 1] unless ``extended``)."""

    def __init__(self, table: TableLike, alpha: float, extended: bool = False) -> None: ...
    @property
    def alpha(self) -> float: ...
    @property
    def extended(self) -> bool: ...
    @property
    def table(self) -> str: ...
    def energy(self, vx: float, vy: float, u: float) -> float: ...
    def trajectory(self, collisions: int, position: Point, velocity: Point, spin: float = 0.0) -> Trajectory: ...
    def initial_states(
        self, n: int, seed: int = 0, sampler: Optional[str] = None, first_index: int = 0
    ) -> npt.NDArray[np.float64]: ...

class FtleDistribution:
    def __init__(self, exponents: Sequence[float]) -> None: ...
    @property
    def exponents(self) -> npt.NDArray[np.float64]: ...
    @property
    def mean(self) -> float: ...
    @property
    def median(self) -> float: ...
    @property
    def std(self) -> Optional[float]: ...
    @property
    def sem(self) -> Optional[float]: ...
    @property
    def min(self) -> float: ...
    @property
    def max(self) -> float: ...
    def quantile(self, q: float) -> float: ...
    def conditional_mean(self, threshold: float = ...) -> Optional[float]: ...
    def chaotic_fraction(self, threshold: float = ...) -> Tuple[float, float]: ...
    def chaotic_fraction_band(self, thresholds: Optional[Sequence[float]] = None) -> Dict[str, Any]: ...
    def dhf_product(self, threshold: float = ...) -> float: ...
    def histogram(
        self, bins: int = 50, range: Optional[Tuple[float, float]] = None
    ) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.float64]]: ...
    def __len__(self) -> int: ...

class LyapunovResult:
    """An ensemble estimate of the largest Lyapunov exponent (per unit time)."""

    mean: float
    sem: float
    median: float
    std: float
    min: float
    max: float
    threshold: float
    conditional_mean: Optional[float]
    chaotic_fraction: float
    chaotic_fraction_sem: float
    per_collision_mean: float
    collision_rate: float
    total_time: float
    n_ics: int
    first_index: int
    collisions_per_ic: int
    wall_time_s: float
    seed: int
    table: str
    alpha: float
    method: str
    delta0: Optional[float]
    sampler: Optional[str]
    engine: str
    version: str
    stop: str
    rel_sem: float
    exponents: npt.NDArray[np.float64]
    per_collision: npt.NDArray[np.float64]
    times: npt.NDArray[np.float64]
    collisions: npt.NDArray[np.int64]
    indices: npt.NDArray[np.int64]
    provenance: Dict[str, Any]
    def ftle(self) -> FtleDistribution: ...
    def merge(self, other: "LyapunovResult") -> "LyapunovResult": ...
    def to_json(self, indent: Optional[int] = None) -> str:
        """The ``spinball.lyapunov`` document ``spinball lyapunov --json`` writes for the same run."""
        ...
    def to_dict(self) -> Dict[str, Any]: ...
    @staticmethod
    def from_json(text: str) -> "LyapunovResult":
        """A result from ``to_json`` text, a one-point result file, or a bare 0.2 result."""
        ...

class SpectrumResult:
    """The Lyapunov spectrum averaged over an ensemble."""

    mean: npt.NDArray[np.float64]
    sem: npt.NDArray[np.float64]
    per_collision_mean: npt.NDArray[np.float64]
    sum_mean: float
    sum_max_abs: float
    floored: int
    exponents: npt.NDArray[np.float64]
    per_collision: npt.NDArray[np.float64]
    times: npt.NDArray[np.float64]
    alpha: float
    table: str
    method: str
    delta0: Optional[float]
    qr_interval: int
    collisions_per_ic: int
    sampler: str
    seed: int
    n_ics: int
    first_index: int
    wall_time_s: float
    def to_json(self, indent: Optional[int] = None) -> str:
        """The ``spinball.spectrum`` document ``spinball spectrum --json`` writes for the same run."""
        ...
    def to_dict(self) -> Dict[str, Any]: ...

def read_results(text: str) -> List[LyapunovResult]:
    """The results of a ``spinball.lyapunov`` document (``spinball lyapunov --json``, ``to_json``)."""
    ...

def write_results(results: Sequence[LyapunovResult], pretty: bool = False) -> str:
    """``results`` as a ``spinball.lyapunov`` document (the command line's format)."""
    ...

def lyapunov(
    table: TableLike,
    alpha: float,
    *,
    ics: Optional[int] = None,
    collisions: int = 10_000,
    method: str = "fd",
    delta0: Optional[float] = None,
    seed: int = 0,
    sampler: Optional[str] = None,
    threads: Optional[int] = None,
    initial_states: Optional[npt.ArrayLike] = None,
    first_index: int = 0,
    threshold: float = 0.01,
    engine: str = "lanes",
    extended: bool = False,
    target_rel_sem: Optional[float] = None,
    batch: int = 96,
    time_budget: Optional[float] = None,
    progress: Progress = None,
    estimator: str = "plain",
    target_error: Optional[float] = None,
) -> Union[LyapunovResult, MultilevelResult]: ...
def alpha_sweep(
    table: TableLike,
    alphas: Sequence[float],
    *,
    ics: Optional[int] = None,
    collisions: int = 10_000,
    method: str = "fd",
    delta0: Optional[float] = None,
    seed: int = 0,
    sampler: Optional[str] = None,
    threads: Optional[int] = None,
    initial_states: Optional[npt.ArrayLike] = None,
    first_index: int = 0,
    threshold: float = 0.01,
    engine: str = "lanes",
    extended: bool = False,
    target_rel_sem: Optional[float] = None,
    batch: int = 96,
    time_budget: Optional[float] = None,
    progress: Progress = None,
) -> List[LyapunovResult]: ...
def spectrum(
    table: TableLike,
    alpha: float,
    *,
    ics: int = 50,
    collisions: int = 50_000,
    method: str = "tangent",
    delta0: Optional[float] = None,
    seed: int = 0,
    sampler: Optional[str] = None,
    threads: Optional[int] = None,
    first_index: int = 0,
    qr_interval: int = 1,
    extended: bool = False,
    progress: Progress = None,
) -> SpectrumResult: ...
def periodic_orbits(
    table: TableLike,
    period: int = 2,
    alphas: Optional[Sequence[float]] = None,
    *,
    precision: float = 1e-8,
    normal_samples: int = 4096,
    grid: Tuple[int, int, int] = (0, 0, 0),
) -> Dict[str, Any]: ...
def island_sizes(
    table: TableLike,
    s: float,
    alphas: Sequence[float],
    *,
    period: int = 2,
    v_par: float = 0.0,
    spin: float = 0.0,
    precision: float = 1e-8,
    cells: int = 41,
    collisions: int = 2000,
    seed: int = 0,
    point: int = 0,
) -> Dict[str, Any]: ...

class MultilevelResult:
    """The result of ``lyapunov(..., estimator="multilevel")``."""

    @property
    def mean(self) -> float: ...
    @property
    def sem(self) -> float: ...
    @property
    def total_error(self) -> float: ...
    @property
    def finite_time_bias(self) -> float: ...
    @property
    def method_bias(self) -> float: ...
    @property
    def limit(self) -> float: ...
    @property
    def limit_sem(self) -> float: ...
    @property
    def bias_law(self) -> str: ...
    @property
    def chaotic_fraction(self) -> float: ...
    @property
    def chaotic_fraction_sem(self) -> float: ...
    @property
    def chaotic_mean(self) -> Optional[float]: ...
    @property
    def chaotic_mean_sem(self) -> Optional[float]: ...
    @property
    def target_error(self) -> float: ...
    @property
    def target_met(self) -> bool: ...
    @property
    def wall_time_s(self) -> float: ...
    @property
    def levels(self) -> List[Dict[str, float]]: ...
def section(
    table: TableLike,
    alpha: float,
    *,
    orbits: int = 8,
    collisions: int = 1000,
    seed: int = 0,
    sampler: Optional[str] = None,
    spin_slice: Optional[float] = None,
    threads: Optional[int] = None,
    extended: bool = False,
) -> Dict[str, np.ndarray]:
    """The Birkhoff section of ``orbits`` orbits: one entry per collision in
    ``orbit``, ``s``, ``sin_theta``, ``v_par``, ``speed``, ``u``, ``wall``, ``q``
    (values just before the collision). ``sampler``: ``"paper"`` (default),
    ``"microcanonical"`` or ``"invariant"``; ``spin_slice=W`` keeps ``|√α u| < W``."""

def ftle_map(
    table: TableLike,
    alpha: float,
    *,
    columns: int = 64,
    rows: int = 64,
    spin: Optional[float] = None,
    q: Optional[float] = None,
    collisions: int = 2000,
    seed: int = 0,
    threshold: float = 0.01,
    threads: Optional[int] = None,
    extended: bool = False,
) -> Dict[str, Any]:
    """The FTLE of a ``rows × columns`` grid of starts on the section at fixed
    ``spin`` (default 0) or fixed ``q``: ``exponents`` (NaN off the shell),
    ``s``, ``row``, counts, the chaotic fraction, and ``predicted`` (the
    bouncing-ball cells on a stadium, else ``None``)."""

def kac(
    table: TableLike,
    alpha: float,
    *,
    s: Tuple[float, float],
    v_par: Tuple[float, float] = (-1.0, 1.0),
    w: Optional[Tuple[float, float]] = None,
    orbits: int = 16,
    collisions: int = 10_000,
    seed: int = 0,
    threads: Optional[int] = None,
    extended: bool = False,
) -> Dict[str, Any]:
    """Mean return times to the region (``s``, ``v_par``, ``w``) against Kac's
    ``1/μ(A)``: ``probability``, ``expected``, ``mean_return``, ``ratio`` (with
    SEMs), ``never_returned``, and per orbit ``index``, ``visits``,
    ``orbit_mean_return``, ``orbit_ratio``."""

def invariant_states(
    table: TableLike, alpha: float, n: int, *, seed: int = 0, first_index: int = 0, extended: bool = False
) -> npt.NDArray[np.float64]:
    """``(n, 5)`` starts ``(x, y, vx, vy, u)`` drawn from the invariant measure of
    the collision map (energy ½), start ``i`` from stream ``i`` of ``seed``."""

def bouncing_ball(
    table: TableLike, alpha: float, states: npt.ArrayLike, *, extended: bool = False
) -> npt.NDArray[np.bool_]:
    """Whether each state stays between the stadium's flat walls for ever (the
    rotation ``4·arctan √α`` per pair of flat collisions); stadium only."""

def pair_rotation(alpha: float) -> float:
    """``4·arctan √α``: the rotation of ``(v_x, √α u)`` per pair of flat collisions."""
def animate(
    table: TableLike,
    alpha: float,
    path: Union[str, "os.PathLike[str]"],
    *,
    balls: int = 1,
    initial_states: Optional[npt.ArrayLike] = None,
    seed: int = 1,
    sampler: Optional[str] = None,
    fps: float = 20.0,
    duration: float = 6.0,
    speed: Optional[float] = None,
    radius: Optional[float] = None,
    size: Tuple[int, int] = (480, 360),
    title: Optional[str] = None,
    extended: bool = False,
) -> Dict[str, Any]:
    """Write a film of balls moving on a table, each with a rotating spin marker.

    The balls are stepped exactly from wall to wall; frame ``k`` shows them
    at billiard time ``k * speed / fps``, on the straight chord between the
    two collisions around it (no wall is skipped). The ball is drawn with
    radius ``r`` and its marker turns at ``ω = u / r`` (``u = rω`` is the
    spin of the dynamics), counter-clockwise positive. The same film as
    ``spinball animate`` on the command line.

    Parameters
    ----------
    table : Table or str
        The table, e.g. ``Stadium(a=1)`` or ``"stadium:a=1"``.
    alpha : float
        Spin parameter ``α = I/(m r²)`` in ``[0, 1]`` (``extended=True``
        allows more).
    path : str or os.PathLike
        The file: ``.gif``, or ``.mp4`` (needs ``ffmpeg`` on ``PATH``).
        Parent directories are created.
    balls : int, optional
        How many balls, drawn as initial conditions ``0 .. balls`` of
        ``seed`` (as an ensemble draws them). Ignored with ``initial_states``.
    initial_states : array_like, optional
        Explicit starts, shape ``(n, 5)``: ``x, y, vx, vy, u``.
    seed : int, optional
        Seed of the drawn starts.
    sampler : str, optional
        ``"paper"`` (default) or ``"microcanonical"``.
    fps : float, optional
        Frames per second (a GIF takes at most 50).
    duration : float, optional
        Length of the film in seconds.
    speed : float, optional
        Billiard time per second of film (default: 4 times the table's unit
        length, 4 for the stadium with unit caps).
    radius : float, optional
        Drawn ball radius in table lengths (default: 0.1 of the unit length).
    size : tuple of int, optional
        ``(width, height)`` in pixels.
    title : str, optional
        Title above the table (default: the table and α; ``""`` for none).
    extended : bool, optional
        Allow α > 1.

    Returns
    -------
    dict
        ``path``; ``times`` (frames,) billiard time of each frame;
        ``positions`` (balls, frames, 2); ``angles`` (balls, frames) spin
        angle in radians from 0 at the start; ``spins`` (balls, frames)
        ``u`` of the flight each frame is in; ``collisions`` (balls,)
        collisions up to the last frame; ``fps``, ``speed``, ``radius``.

    Raises
    ------
    ValueError
        Invalid input: table, α, counts, options out of range, a start
        outside the table, a path that is not ``.gif``/``.mp4``, a GIF
        faster than 50 fps.
    RuntimeError
        A step failed, ``ffmpeg`` is missing for an ``.mp4``, or the file
        cannot be written.

    Examples
    --------
    >>> import spinball
    >>> film = spinball.animate("stadium:a=1", 0.5, "stadium.gif", balls=2, duration=2)
    >>> film["positions"].shape
    (2, 40, 2)
    """

class EscapeResult:
    """The result of ``escape``: every ball's record and the summary, in time
    and in collisions (``clock="time"`` or ``"collisions"``, the hole counted)."""

    @property
    def index(self) -> npt.NDArray[np.uint64]: ...
    @property
    def times(self) -> npt.NDArray[np.float64]:
        """Escape times (for a censored ball, the time it was last seen inside)."""
    @property
    def collisions(self) -> npt.NDArray[np.uint64]:
        """Collisions before the hole (or before the budget ran out)."""
    @property
    def censored(self) -> npt.NDArray[np.bool_]:
        """Whether each ball was still inside at the budget."""
    @property
    def exit_point(self) -> npt.NDArray[np.float64]:
        """``(n, 2)`` exit points (NaN for a censored ball)."""
    @property
    def exit_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def exit_v_par(self) -> npt.NDArray[np.float64]: ...
    @property
    def exit_spin(self) -> npt.NDArray[np.float64]: ...
    @property
    def escaped(self) -> int: ...
    @property
    def n_censored(self) -> int: ...
    def survival(self, clock: str = "time") -> Optional[Dict[str, npt.NDArray[np.float64]]]:
        """Kaplan–Meier ``P``: arrays ``t``, ``p``, ``sem``, ``lower``, ``upper`` (95 %
        log–log band), ``at_risk``; ``None`` if no ball escaped."""
    def escape_rate(self, clock: str = "time") -> Optional[Tuple[float, float]]:
        """``(γ, SEM)`` on the rate window; ``None`` if refused (see ``summary``)."""
    def mean_escape(self, clock: str = "time") -> Optional[Tuple[float, float, bool]]:
        """``(mean, SEM, complete)``: a lower bound when balls were censored."""
    def kac_ratio(self, clock: str = "time") -> Optional[Tuple[float, float]]:
        """Mean escape time over Kac's prediction ``(ratio, SEM)``."""
    def tail(self, clock: str = "time") -> Optional[Tuple[str, float, float]]:
        """``(law, β, SEM)``, law ``"algebraic"``, ``"exponential"`` or ``"undecided"``."""
    @property
    def summary(self) -> Dict[str, Any]:
        """The whole summary (a refused estimate is ``{"refused": reason}``)."""
    def to_json(self, indent: Optional[int] = None) -> str:
        """The ``spinball.escape`` document ``spinball escape --json`` writes."""

class DiffusionResult:
    """The result of ``diffuse``."""

    @property
    def times(self) -> npt.NDArray[np.float64]: ...
    @property
    def displacements(self) -> npt.NDArray[np.float64]:
        """``(ICs, checkpoints, 2)`` unwrapped displacements."""
    @property
    def msd(self) -> npt.NDArray[np.float64]: ...
    @property
    def msd_sem(self) -> npt.NDArray[np.float64]: ...
    @property
    def horizon(self) -> str: ...
    @property
    def diffusion_coefficient(self) -> Optional[Tuple[float, float]]:
        """``(D, SEM)`` for a finite horizon; ``None`` for an infinite one."""
    @property
    def marginal_coefficient(self) -> Optional[Tuple[float, float]]:
        """``(D_m, SEM)`` of ``⟨Δr²⟩ ≈ 4 D_m t ln t`` for an infinite horizon."""
    @property
    def window(self) -> Optional[Tuple[float, float]]: ...
    @property
    def summary(self) -> Dict[str, Any]: ...
    def to_json(self, indent: Optional[int] = None) -> str:
        """The ``spinball.diffusion`` document ``spinball diffuse --json`` writes."""

def escape(
    table: TableLike,
    alpha: float,
    *,
    ics: int = 1000,
    collisions: Optional[int] = None,
    time: Optional[float] = None,
    seed: int = 0,
    sampler: Optional[str] = None,
    threads: Optional[int] = None,
    window: Optional[Tuple[float, float]] = None,
    collision_window: Optional[Tuple[float, float]] = None,
    tail_from: Optional[float] = None,
    collision_tail_from: Optional[float] = None,
    extended: bool = False,
) -> EscapeResult:
    """How long ``ics`` balls take to leave a table with a hole; censored at the
    budget (``collisions``, default 100 000, and/or ``time``), never dropped."""

def diffuse(
    table: TableLike,
    alpha: float,
    *,
    ics: int = 1000,
    times: Optional[Sequence[float]] = None,
    until: float = 1000.0,
    checkpoints: int = 20,
    seed: int = 0,
    sampler: Optional[str] = None,
    threads: Optional[int] = None,
    window: Optional[Tuple[float, float]] = None,
    extended: bool = False,
) -> DiffusionResult:
    """Unwrapped displacements of ``ics`` balls through a periodic table at
    ``times``; ``⟨Δr²⟩`` and ``D`` (or the marginal coefficient)."""
