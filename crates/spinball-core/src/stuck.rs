//! A ball that stops moving: runs of zero-time collisions.
//!
//! Some collisions legitimately take no time (the second wall of a corner,
//! a few in a narrow wedge). A ball started on a wall and moving along it,
//! though, slides to where a curved wall meets that wall tangentially (the
//! stadium's junctions) and stays there: every later cast finds the curved
//! wall at distance zero and the collision leaves the velocity tangent to
//! it. The run would report `Ok` forever with no time passing (and a
//! Lyapunov exponent of 0/0). Both engines count zero-time collisions in a
//! row and stop with `StepError::Stuck` past [`MAX_ZERO_TIME_RUN`].

use spinball_geometry::Hit;

use crate::error::StepError;
use crate::state::Ball;

/// Most zero-time collisions in a row before a ball counts as stuck. A
/// corner takes one; a wedge of angle `π/n` takes about `n`.
pub const MAX_ZERO_TIME_RUN: u32 = 64;

/// The ball's run of zero-time collisions after taking `hit`, or
/// [`StepError::Stuck`] when it exceeds [`MAX_ZERO_TIME_RUN`].
#[inline]
pub(crate) fn watch_zero_time(ball: &Ball, hit: &Hit) -> Result<u32, StepError> {
    let run = if hit.time == 0.0 {
        ball.zero_run + 1
    } else {
        0
    };
    if run > MAX_ZERO_TIME_RUN {
        return Err(StepError::Stuck {
            position: ball.state.position,
            velocity: ball.state.velocity,
            collisions: run,
        });
    }
    Ok(run)
}
