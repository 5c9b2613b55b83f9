//! One trajectory's collisions as columns of numbers: what a user plots,
//! saves as CSV or NPY, or hands to NumPy.
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Collision logs".

use spinball_core::{Billiard, Collision, State};
use spinball_geometry::Boundary;

use crate::error::AnalysisError;

/// The names of the columns, in order.
pub const COLLISION_COLUMNS: [&str; 10] =
    ["time", "x", "y", "vx", "vy", "u", "wall", "s", "v_par", "q"];

/// The collisions of one trajectory, a row of [`COLLISION_COLUMNS`] each.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CollisionLog {
    /// One row per collision.
    pub rows: Vec<[f64; 10]>,
}

impl CollisionLog {
    /// The row of `collision`, which happened at `time` and left the ball
    /// in `after`.
    #[must_use]
    pub fn row(time: f64, collision: &Collision, after: &State) -> [f64; 10] {
        let p = collision.point();
        [
            time,
            p.x,
            p.y,
            after.velocity.x,
            after.velocity.y,
            after.spin,
            f64::from(collision.wall()),
            collision.hit.s(),
            collision.v_par_before,
            collision.q,
        ]
    }

    /// Column `k` (see [`COLLISION_COLUMNS`]).
    #[must_use]
    pub fn column(&self, k: usize) -> Vec<f64> {
        self.rows.iter().map(|r| r[k]).collect()
    }

    /// The log as CSV text with a header line.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let mut out = COLLISION_COLUMNS.join(",");
        out.push('\n');
        for r in &self.rows {
            let line: Vec<String> = r.iter().map(f64::to_string).collect();
            out.push_str(&line.join(","));
            out.push('\n');
        }
        out
    }
}

/// The first `collisions` collisions of the ball launched from `start`.
///
/// ```
/// use spinball_analysis::diagnostics::collision_log;
/// use spinball_core::{Billiard, SpinLaw, State};
/// use spinball_geometry::{DVec2, Stadium};
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let start = State::new(DVec2::new(0.1, 0.2), DVec2::new(0.6, 0.8), 0.0);
/// let log = collision_log(&billiard, start, 100)?;
/// assert_eq!(log.rows.len(), 100);
/// // Q = v∥ − αu with v∥ and u just before each collision (the spin
/// // before collision k is the spin after collision k − 1).
/// for k in 1..log.rows.len() {
///     let (r, prev) = (log.rows[k], log.rows[k - 1]);
///     assert!((r[8] - 0.5 * prev[5] - r[9]).abs() < 1e-12);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// The launch error, or the first step error (with index 0).
pub fn collision_log<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    collisions: u64,
) -> Result<CollisionLog, AnalysisError> {
    let mut ball = billiard.launch(start)?;
    let mut rows = Vec::with_capacity(usize::try_from(collisions).unwrap_or(0).min(1 << 24));
    let mut time = 0.0;
    for _ in 0..collisions {
        let c = billiard.step(&mut ball)?;
        time += c.time();
        rows.push(CollisionLog::row(time, &c, ball.state()));
    }
    Ok(CollisionLog { rows })
}
