//! Why a table could not be built.
//!
//! Every constructor in this crate validates its input and returns one of these
//! variants instead of building a table that would produce NaNs or let a ball out.

use thiserror::Error;

/// An invalid table or wall description.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum GeometryError {
    /// A parameter is NaN or infinite.
    #[error("table parameter `{name}` must be finite, got {value}")]
    NonFinite {
        /// Name of the parameter, as in the constructor.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A length that must be strictly positive is zero or negative.
    #[error("table parameter `{name}` must be > 0, got {value}")]
    NonPositive {
        /// Name of the parameter, as in the constructor.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// The Sinai obstacle does not fit strictly inside the square.
    #[error("Sinai obstacle radius r = {r} must be smaller than the half-side l = {l}")]
    ObstacleTooLarge {
        /// Obstacle radius.
        r: f64,
        /// Half-side of the square.
        l: f64,
    },
    /// A size that `f64` cannot run: its square (times the square of any
    /// speed `launch` accepts) would overflow or become subnormal, or the
    /// table's coordinates could not resolve its thinnest part.
    #[error(
        "table parameter `{name}` = {value:e} is outside the range that f64 can run, [{min:e}, {max:e}]: {why}"
    )]
    OutOfRange {
        /// Name of the parameter, as in the constructor.
        name: &'static str,
        /// The offending value.
        value: f64,
        /// Smallest accepted value.
        min: f64,
        /// Largest accepted value.
        max: f64,
        /// Why the range is what it is.
        why: &'static str,
    },
    /// Two walls of a table built from walls cross or touch away from a
    /// shared end (a self-intersecting loop, a hole crossing the outer loop
    /// or another hole).
    #[error(
        "wall {second_index} of loop {second_loop} meets wall {first_index} of loop {first_loop} at ({x}, {y}): walls may only meet at the shared end of consecutive walls"
    )]
    Crossing {
        /// Loop of the first wall (0 = outer, 1.. = holes).
        first_loop: usize,
        /// Index of the first wall within its loop.
        first_index: usize,
        /// Loop of the second wall.
        second_loop: usize,
        /// Index of the second wall within its loop.
        second_index: usize,
        /// A point where they meet, x.
        x: f64,
        /// A point where they meet, y.
        y: f64,
    },
    /// Two walls run along each other for a stretch: a zero-width spike or
    /// slit (a wall that turns back on itself), or two loops sharing a wall.
    #[error(
        "wall {second_index} of loop {second_loop} runs along wall {first_index} of loop {first_loop} (a zero-width spike or slit): the table would have no width there"
    )]
    Overlap {
        /// Loop of the first wall.
        first_loop: usize,
        /// Index of the first wall within its loop.
        first_index: usize,
        /// Loop of the second wall.
        second_loop: usize,
        /// Index of the second wall within its loop.
        second_index: usize,
    },
    /// A hole lies outside the outer loop, or inside another hole.
    #[error(
        "hole {hole} (loop {hole}) lies {where_}: every hole must lie inside the outer loop and outside every other hole"
    )]
    MisplacedHole {
        /// Loop index of the hole (1 = first hole).
        hole: usize,
        /// `outside the outer loop` or `inside hole k`.
        where_: String,
    },
    /// A wall has (numerically) zero length.
    #[error("wall {index} is degenerate (zero length)")]
    DegenerateWall {
        /// Index of the wall in the list given to the constructor.
        index: usize,
    },
    /// A wall shorter than the smallest length a table accepts
    /// ([`MIN_LENGTH`]), but not of zero length.
    #[error(
        "wall {index} is {length:e} long, below the smallest length that works, {min:e}: squares of lengths times squares of speeds (1e-60..=1e60) must stay normal f64 (scale the table up)"
    )]
    WallTooShort {
        /// Index of the wall in the list given to the constructor.
        index: usize,
        /// Its length.
        length: f64,
        /// The smallest length that works, [`MIN_LENGTH`].
        min: f64,
    },
    /// An arc of a table built from walls whose radius the casts cannot run
    /// exactly on that table: below [`MIN_ARC_RATIO`] of the table's size,
    /// above [`MAX_ARC_RATIO`] sizes, or above [`MAX_ARC_CHORD_RATIO`] times
    /// its own chord (so flat that it is a line segment to the table's
    /// rounding).
    #[error(
        "arc {index} of loop {lp} has radius {radius:e}, outside the radii that run exactly for it, [{min:.3e}, {max:.3e}] (table size {size:.3e}, chord {chord:.3e}, sagitta {sagitta:.3e}): {why}"
    )]
    ArcRadius {
        /// Loop of the arc (0 = outer, 1.. = holes).
        lp: usize,
        /// Index of the arc within its loop.
        index: usize,
        /// Its radius.
        radius: f64,
        /// Smallest radius that works: [`MIN_ARC_RATIO`] times the table's
        /// size (half its box's diagonal).
        min: f64,
        /// Largest radius that works for this arc: the smaller of
        /// [`MAX_ARC_RATIO`] times the size the walls' tolerance follows
        /// (the table's size or its largest coordinate) and
        /// [`MAX_ARC_CHORD_RATIO`] times the arc's chord.
        max: f64,
        /// The table's size the bounds are relative to (for `max`, the
        /// length the walls' tolerance follows).
        size: f64,
        /// The arc's chord (distance from its start to its end; 0 for a
        /// full circle).
        chord: f64,
        /// The arc's sagitta (distance of its middle from its chord).
        sagitta: f64,
        /// Which bound it breaks and why it is there.
        why: &'static str,
    },
    /// An arc sweeps more than a full turn or nothing at all.
    #[error("arc {index} sweep {sweep} must satisfy 0 < |sweep| <= 2*pi")]
    BadSweep {
        /// Index of the wall in the list given to the constructor.
        index: usize,
        /// The sweep angle given.
        sweep: f64,
    },
    /// A table built from walls has fewer walls than it needs.
    #[error("a table needs at least {needed} walls, got {got}")]
    TooFewWalls {
        /// Minimum number of walls.
        needed: usize,
        /// Number of walls given.
        got: usize,
    },
    /// Consecutive walls of a boundary loop do not meet.
    #[error(
        "boundary loop {lp} is open: wall {index} ends at ({x1}, {y1}) but the next starts at ({x2}, {y2}) (walls must meet within 1e-9 of the table size, two arcs within 64 machine epsilons of it)"
    )]
    OpenLoop {
        /// Index of the loop.
        lp: usize,
        /// Index of the wall (within the loop) whose end does not meet the next start.
        index: usize,
        /// End point x.
        x1: f64,
        /// End point y.
        y1: f64,
        /// Next start x.
        x2: f64,
        /// Next start y.
        y2: f64,
    },
    /// The walls enclose no area, or the outer loop is oriented clockwise.
    #[error(
        "boundary loop {lp} must enclose the table counter-clockwise (outer loop) or clockwise (holes); signed area {area}"
    )]
    WrongOrientation {
        /// Index of the loop.
        lp: usize,
        /// Signed area enclosed by the loop (positive = counter-clockwise).
        area: f64,
    },
    /// A wall kind was given for a wall the table does not have.
    #[error("wall {wall} does not exist: the table has walls 0..{walls}")]
    NoSuchWall {
        /// The wall id given.
        wall: u32,
        /// Number of walls of the table.
        walls: usize,
    },
    /// A wall was made a hole or periodic, but it already is a hole or
    /// periodic: holes may not overlap each other or a periodic wall.
    #[error(
        "wall {wall} cannot be made {wanted}: it is already {current} (a hole may not overlap another hole or a periodic wall; split the wall to give its parts different kinds)"
    )]
    KindOverlap {
        /// The wall.
        wall: u32,
        /// What it was asked to become (`a hole`, `periodic`).
        wanted: &'static str,
        /// What it is (`a hole`, `periodic`).
        current: &'static str,
    },
    /// Two walls given as periodic partners are not translates of each other
    /// facing each other across the table.
    #[error(
        "walls {a} and {b} cannot be periodic partners: {why} (partners are straight walls of equal length, parallel with opposite inward normals, each the other's translate, facing each other across the table; mismatch {mismatch:e})"
    )]
    NotPartners {
        /// First wall.
        a: u32,
        /// Second wall.
        b: u32,
        /// What is wrong.
        why: &'static str,
        /// How far from a translate (a length; 0 if not a length test).
        mismatch: f64,
    },
    /// The translations of a table's periodic walls are not integer
    /// combinations of two lattice vectors, so a ball's cell could not be
    /// kept as integers.
    #[error(
        "the translation ({x}, {y}) of periodic wall {wall} is not an integer combination of the lattice basis taken from the first two non-parallel translations: its cell could not be counted exactly"
    )]
    NotALattice {
        /// The periodic wall.
        wall: u32,
        /// Its translation, x.
        x: f64,
        /// Its translation, y.
        y: f64,
    },
    /// The horizon of a periodic table could not be decided: the lattice
    /// directions a corridor could run along cannot be bounded, or are too
    /// many to check.
    #[error("the horizon of this periodic table cannot be decided: {why}")]
    HorizonUndecided {
        /// Why, and what would make it decidable.
        why: String,
    },
    /// A periodic cell's obstacle fills it: no room is left for the ball,
    /// or the obstacles of neighbouring cells touch.
    #[error(
        "a disk of radius R = {r} does not fit a lattice of spacing w = {w}: R must lie in (0, {max}) ({why})"
    )]
    NoRoom {
        /// Disk radius.
        r: f64,
        /// Lattice spacing.
        w: f64,
        /// Largest radius (exclusive) that leaves room.
        max: f64,
        /// Why.
        why: &'static str,
    },
}

/// Smallest length a table accepts: lengths and speeds (at least
/// `spinball_core`'s `MIN_SPEED = 1e-60`) multiply into squares of order
/// `1e-240`, far above the subnormal range (`2.2e-308`).
pub const MIN_LENGTH: f64 = 1e-60;
/// Largest length (and coordinate) a table accepts: squares of lengths times
/// speeds (at most `1e60`) stay below `1e245`, far below overflow (`1.8e308`).
pub const MAX_LENGTH: f64 = 1e60;
/// Largest flat half-length of a [`Stadium`](crate::Stadium): its caps have
/// radius 1, and coordinates of size `a` resolve them only to `ε a`
/// (`2.2e-8` of the radius at `a = 1e8`).
pub const MAX_STADIUM_A: f64 = 1e8;
/// Smallest `r / l` of a [`Sinai`](crate::Sinai) table: below it the
/// obstacle's `r²` drowns in the rounding of `|x|² ~ l²` and the ball flies
/// through it.
pub const MIN_SINAI_RATIO: f64 = 1e-6;
/// Smallest radius of an arc of a [`SegmentTable`](crate::SegmentTable),
/// as a fraction of the table's size (half its box's diagonal): as for the
/// Sinai obstacle, a smaller arc's `r²` drowns in the rounding of squared
/// distances across the table.
pub const MIN_ARC_RATIO: f64 = 1e-6;
/// Largest radius of an arc of a [`SegmentTable`](crate::SegmentTable),
/// in table sizes (the size its walls' tolerance follows: half its box's
/// diagonal, or its largest coordinate if that is larger). An arc's cast
/// works relative to its centre, `R` away: its contacts and the test of
/// whether a contact lies between its ends round by a few `ε R` (measured:
/// up to `1.3 ε R` off the circle), and the walls' tolerance is `64 ε` of
/// the size. At 8 sizes the rounding stays inside the tolerance with room
/// to spare; beyond about 100 sizes balls found no wall at the arc's ends
/// (a unit square with a top wall of radius 1e2: 3 of 12 000 shots at its
/// corners; 1e6: a run ended with `NoWall` within 3e4 collisions).
pub const MAX_ARC_RATIO: f64 = 8.0;
/// Largest radius of an arc of a [`SegmentTable`](crate::SegmentTable) in
/// units of its chord (a sweep of at least `2 asin(1/64)` = 1.8°; a full
/// circle has no ends and no such bound): an arc meets its chord at half
/// its sweep, so the test of whether a contact lies between its ends,
/// tolerant by the walls' tolerance across the chord, places the ends only
/// to that tolerance over `sin(sweep / 2)` along the wall, `64 ×` it at
/// this bound (`9e-13` of the table's size). A flatter arc is a line
/// segment to the table's rounding.
pub const MAX_ARC_CHORD_RATIO: f64 = 32.0;
/// Largest distance of a [`SegmentTable`](crate::SegmentTable)'s
/// coordinates from the origin, in table sizes: coordinates round by `ε`
/// of their size, and the walls' tolerance follows them (`64 ε` of the
/// largest coordinate, `1.4e-8` of the table at this bound).
pub const MAX_OFFSET_RATIO: f64 = 1e6;
/// Smallest channel `(l − r) / l` of a [`Sinai`](crate::Sinai) table: the
/// four corners must stay wider than the walls' tolerance (`64 ε l`).
pub const MIN_SINAI_GAP: f64 = 1e-12;

const LENGTH_WHY: &str =
    "squares of lengths times squares of speeds (1e-60..=1e60) must stay normal, finite f64";

/// Reject NaN, infinities, zero, negative values and lengths outside
/// `[MIN_LENGTH, MAX_LENGTH]`.
pub(crate) fn length(name: &'static str, value: f64) -> Result<f64, GeometryError> {
    let value = positive(name, value)?;
    within(name, value, MIN_LENGTH, MAX_LENGTH, LENGTH_WHY)
}

/// Reject a coordinate with `|value| > MAX_LENGTH`.
pub(crate) fn coordinate(name: &'static str, value: f64) -> Result<f64, GeometryError> {
    let value = finite(name, value)?;
    if value.abs() > MAX_LENGTH {
        return Err(GeometryError::OutOfRange {
            name,
            value,
            min: -MAX_LENGTH,
            max: MAX_LENGTH,
            why: LENGTH_WHY,
        });
    }
    Ok(value)
}

/// Reject `value` outside `[min, max]`, saying `why`.
pub(crate) fn within(
    name: &'static str,
    value: f64,
    min: f64,
    max: f64,
    why: &'static str,
) -> Result<f64, GeometryError> {
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(GeometryError::OutOfRange {
            name,
            value,
            min,
            max,
            why,
        })
    }
}

/// Reject NaN and infinities.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, GeometryError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(GeometryError::NonFinite { name, value })
    }
}

/// Reject NaN, infinities, zero and negative values.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, GeometryError> {
    let value = finite(name, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(GeometryError::NonPositive { name, value })
    }
}
