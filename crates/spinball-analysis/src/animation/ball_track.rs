//! One ball through the frames of a film: its exact collisions, and its
//! position and spin angle at every frame time.
//!
//! Documented in the group docs (`animation/mod.rs`).

use glam::DVec2;
use spinball_core::{Billiard, State};
use spinball_geometry::Boundary;

use super::frame_options::{FrameOptions, MAX_COLLISIONS_PER_BALL};
use crate::error::AnalysisError;

/// One exact collision of a filmed ball.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CollisionMark {
    /// Billiard time of the collision (from the start, 0).
    pub time: f64,
    /// Contact point.
    pub point: DVec2,
    /// Spin `u` after the collision (what the ball turns with until the next).
    pub spin: f64,
}

/// One ball at every frame of a film.
///
/// Frame `k` is at billiard time [`time(k)`](Self::time); between two
/// entries of [`collisions`](Self::collisions) the ball flies straight, so
/// every frame position lies on the chord from the last collision before it
/// (or the start) to the first after it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BallTrack {
    /// The start (time 0).
    pub start: State,
    /// Billiard time between two frames, `speed / fps`.
    pub frame_step: f64,
    /// The centre at each frame.
    pub positions: Vec<DVec2>,
    /// The spin angle `φ` at each frame (radians, counter-clockwise, from 0
    /// at the start, not wrapped).
    pub angles: Vec<f64>,
    /// The spin `u` at each frame (of the flight the frame falls in).
    pub spins: Vec<f64>,
    /// Every collision up to the last frame, and the first one after it (so
    /// that every frame is bracketed by the start or a collision before it
    /// and a collision after it), in time order.
    pub collisions: Vec<CollisionMark>,
}

impl BallTrack {
    /// Billiard time of frame `k`, `k · speed / fps`.
    #[must_use]
    pub fn time(&self, k: usize) -> f64 {
        k as f64 * self.frame_step
    }

    /// The number of frames.
    #[must_use]
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Whether there is no frame (never for a track from [`track_ball`]).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }
}

/// The ball launched from `start` on `billiard`, sampled at the frames of
/// `options` (see the group docs for the time and spin conventions).
///
/// ```
/// use spinball_analysis::animation::{FrameOptions, track_ball};
/// use spinball_core::{Billiard, SpinLaw, State};
/// use spinball_geometry::{DVec2, Stadium};
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let start = State::new(DVec2::ZERO, DVec2::new(0.6, 0.7), 0.3);
/// let options = FrameOptions::new(10.0, 3.0).with_speed(1.0).with_radius(0.1);
/// let track = track_ball(&billiard, start, &options)?;
/// assert_eq!(track.len(), 30);
/// // Before the first wall the ball flies straight and turns at ω = u/r = 3.
/// assert!((track.positions[1] - DVec2::new(0.06, 0.07)).length() < 1e-15);
/// assert!((track.angles[1] - 0.3).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for bad options (see
/// [`FrameOptions::validate`]) or a ball that needs more than
/// [`MAX_COLLISIONS_PER_BALL`] collisions; [`AnalysisError::Launch`] for a
/// start that cannot be launched (outside the table, at rest, not finite);
/// [`AnalysisError::Step`] if a step fails.
pub fn track_ball<B: Boundary>(
    billiard: &Billiard<B>,
    start: State,
    options: &FrameOptions,
) -> Result<BallTrack, AnalysisError> {
    options.validate()?;
    let frames = options.frame_count()?;
    let frame_step = options.speed_on(billiard.table()) / options.fps;
    let radius = options.radius_on(billiard.table());
    let mut ball = billiard.launch(start)?;
    let mut track = BallTrack {
        start,
        frame_step,
        positions: Vec::with_capacity(frames),
        angles: Vec::with_capacity(frames),
        spins: Vec::with_capacity(frames),
        collisions: Vec::new(),
    };
    // The flight in progress left `from` at time `t_from` with spin angle
    // `phi_from`, and ends at the collision `next`, at `t_next`.
    let mut from = start;
    let (mut t_from, mut phi_from) = (0.0, 0.0);
    let mut next = billiard.step(&mut ball)?;
    let mut t_next = next.time();
    track.collisions.push(CollisionMark {
        time: t_next,
        point: next.point(),
        spin: ball.spin(),
    });
    for k in 0..frames {
        let t = track.time(k);
        // Every collision before the frame is taken, however many there are.
        while t > t_next {
            if track.collisions.len() as u64 >= MAX_COLLISIONS_PER_BALL {
                return Err(AnalysisError::invalid(
                    "speed",
                    format!(
                        "the ball needs more than {MAX_COLLISIONS_PER_BALL} collisions before \
                         billiard time {t}; show less billiard time (a lower speed or a shorter \
                         duration) or start a slower ball"
                    ),
                ));
            }
            phi_from += from.spin * (t_next - t_from) / radius;
            from = *ball.state();
            t_from = t_next;
            next = billiard.step(&mut ball)?;
            t_next = t_from + next.time();
            track.collisions.push(CollisionMark {
                time: t_next,
                point: next.point(),
                spin: ball.spin(),
            });
        }
        let dt = t - t_from;
        track.positions.push(from.position + dt * from.velocity);
        track.angles.push(phi_from + from.spin * dt / radius);
        track.spins.push(from.spin);
    }
    Ok(track)
}
