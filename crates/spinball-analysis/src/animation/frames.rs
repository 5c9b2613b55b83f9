//! Several balls of one billiard, filmed together: the frames a GIF or MP4
//! writer draws.
//!
//! Documented in the group docs (`animation/mod.rs`).

use spinball_core::Billiard;
use spinball_geometry::Boundary;

use super::ball_track::{BallTrack, track_ball};
use super::frame_options::FrameOptions;
use crate::error::AnalysisError;
use crate::run::Starts;

/// Most balls one film may hold.
const MAX_BALLS: u64 = 1_000;

/// Balls of one billiard at the frames of one film.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Frames {
    /// Frames per second of film.
    pub fps: f64,
    /// Billiard time per second of film.
    pub speed: f64,
    /// Drawn ball radius (table lengths); the spin angle turns at `u / radius`.
    pub radius: f64,
    /// One track per ball, all with the same frames.
    pub balls: Vec<BallTrack>,
}

impl Frames {
    /// The number of frames.
    #[must_use]
    pub fn frame_count(&self) -> usize {
        self.balls.first().map_or(0, BallTrack::len)
    }

    /// Billiard time of frame `k`.
    #[must_use]
    pub fn time(&self, k: usize) -> f64 {
        k as f64 * self.speed / self.fps
    }
}

/// Balls `0..balls` of `starts` (drawn with `seed` exactly as an
/// [`Ensemble`](crate::run::Ensemble) draws initial conditions `0..balls`,
/// or the first `balls` given states) on `billiard`, sampled at the frames
/// of `options`.
///
/// ```
/// use spinball_analysis::animation::{FrameOptions, animation_frames};
/// use spinball_analysis::run::Starts;
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let options = FrameOptions::new(10.0, 6.0);
/// let frames = animation_frames(&billiard, &Starts::Sampled(Sampler::Paper), 3, 1, &options)?;
/// assert_eq!((frames.balls.len(), frames.frame_count()), (3, 60));
/// assert_eq!(frames.speed, 4.0); // default: 4 cap radii of billiard time a second
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for bad options, no ball, more than
/// 1000 balls or more balls than given states; [`AnalysisError::NoRoom`] if
/// the sampler finds no room; launch and step errors as [`track_ball`],
/// tagged with the ball's index.
pub fn animation_frames<B: Boundary>(
    billiard: &Billiard<B>,
    starts: &Starts,
    balls: u64,
    seed: u64,
    options: &FrameOptions,
) -> Result<Frames, AnalysisError> {
    options.validate()?;
    if !(1..=MAX_BALLS).contains(&balls) {
        return Err(AnalysisError::invalid(
            "balls",
            format!("{balls} balls; a film holds 1 to {MAX_BALLS}"),
        ));
    }
    let tracks = (0..balls)
        .map(|i| {
            let (start, _) = starts.draw(billiard.table(), billiard.law(), seed, i)?;
            track_ball(billiard, start, options).map_err(|e| e.at_index(i))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Frames {
        fps: options.fps,
        speed: options.speed_on(billiard.table()),
        radius: options.radius_on(billiard.table()),
        balls: tracks,
    })
}
