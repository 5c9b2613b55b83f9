//! How a film samples the billiard: frame rate, duration, billiard time per
//! second of film, and the drawn ball radius.
//!
//! Documented in the group docs (`animation/mod.rs`).

use spinball_geometry::Boundary;

use crate::error::AnalysisError;

/// Highest frame rate accepted (frames per second of film).
pub const MAX_FPS: f64 = 100.0;
/// Most frames one film may have (about 28 minutes at 60 fps).
pub const MAX_FRAMES: usize = 100_000;
/// Most collisions one ball may take during a film: a guard against a
/// start so fast, or a `speed` so high, that the film would run for hours.
pub const MAX_COLLISIONS_PER_BALL: u64 = 10_000_000;

/// Default frame rate of a film (what the command line and Python use).
pub const DEFAULT_FPS: f64 = 20.0;
/// Default length of a film in seconds.
pub const DEFAULT_DURATION: f64 = 6.0;

/// Default billiard time per second of film, in units of the table's
/// [`unit_length`](Boundary::unit_length) (a ball with all of its energy
/// ½ in translation crosses one unit of length per unit of time).
const DEFAULT_SPEED: f64 = 4.0;
/// Default drawn ball radius, in units of the table's
/// [`unit_length`](Boundary::unit_length).
const DEFAULT_RADIUS: f64 = 0.1;

/// How to sample a film: `fps` frames per second for `duration` seconds,
/// each second showing `speed` units of billiard time, the ball drawn with
/// radius `radius` (which sets `ω = u / r`, see the group docs).
///
/// ```
/// use spinball_analysis::animation::FrameOptions;
/// use spinball_geometry::Stadium;
///
/// let options = FrameOptions::new(10.0, 6.0).with_speed(2.0);
/// assert_eq!(options.frame_count()?, 60);
/// let stadium = Stadium::new(1.0)?;
/// assert_eq!(options.speed_on(&stadium), 2.0);
/// assert_eq!(options.radius_on(&stadium), 0.1); // default: 0.1 cap radius
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[must_use]
pub struct FrameOptions {
    /// Frames per second of film, in `(0, MAX_FPS]`.
    pub fps: f64,
    /// Length of the film in seconds: `round(duration · fps)` frames, at
    /// least one and at most [`MAX_FRAMES`].
    pub duration: f64,
    /// Billiard time shown per second of film (`None`: 4 units of the
    /// table's [`unit_length`](Boundary::unit_length)).
    pub speed: Option<f64>,
    /// Drawn ball radius `r`, in table lengths (`None`: 0.1 of the table's
    /// [`unit_length`](Boundary::unit_length)).
    pub radius: Option<f64>,
}

impl Default for FrameOptions {
    /// [`DEFAULT_FPS`] for [`DEFAULT_DURATION`], default speed and radius.
    fn default() -> Self {
        FrameOptions::new(DEFAULT_FPS, DEFAULT_DURATION)
    }
}

impl FrameOptions {
    /// `fps` frames per second for `duration` seconds, default speed and
    /// radius.
    pub fn new(fps: f64, duration: f64) -> Self {
        FrameOptions {
            fps,
            duration,
            speed: None,
            radius: None,
        }
    }

    /// Show `speed` units of billiard time per second of film.
    pub fn with_speed(mut self, speed: f64) -> Self {
        self.speed = Some(speed);
        self
    }

    /// Draw the ball with radius `radius` (so that it turns at `ω = u/r`).
    pub fn with_radius(mut self, radius: f64) -> Self {
        self.radius = Some(radius);
        self
    }

    /// The number of frames, `round(duration · fps)`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] as [`validate`](Self::validate).
    pub fn frame_count(&self) -> Result<usize, AnalysisError> {
        if !(self.fps > 0.0 && self.fps <= MAX_FPS) {
            return Err(AnalysisError::invalid(
                "fps",
                format!(
                    "{} frames per second; give a rate in (0, {MAX_FPS}]",
                    self.fps
                ),
            ));
        }
        if !(self.duration > 0.0 && self.duration.is_finite()) {
            return Err(AnalysisError::invalid(
                "duration",
                format!("{} s; give a positive, finite duration", self.duration),
            ));
        }
        let frames = (self.duration * self.fps).round();
        if !(1.0..=MAX_FRAMES as f64).contains(&frames) {
            return Err(AnalysisError::invalid(
                "duration",
                format!(
                    "{} s at {} fps is {frames} frames; a film has 1 to {MAX_FRAMES} frames",
                    self.duration, self.fps
                ),
            ));
        }
        Ok(frames as usize)
    }

    /// Check every option.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for a frame rate outside
    /// `(0, MAX_FPS]`, a duration that is not positive and finite or gives
    /// no frame or more than [`MAX_FRAMES`], a speed or radius that is not
    /// positive and finite.
    pub fn validate(&self) -> Result<(), AnalysisError> {
        self.frame_count()?;
        for (name, value) in [("speed", self.speed), ("radius", self.radius)] {
            if let Some(v) = value
                && !(v > 0.0 && v.is_finite())
            {
                return Err(AnalysisError::invalid(
                    name,
                    format!("{v}; give a positive, finite value"),
                ));
            }
        }
        Ok(())
    }

    /// The billiard time per second of film on `table`.
    #[must_use]
    pub fn speed_on<B: Boundary + ?Sized>(&self, table: &B) -> f64 {
        self.speed
            .unwrap_or_else(|| DEFAULT_SPEED * table.unit_length())
    }

    /// The drawn ball radius on `table`.
    #[must_use]
    pub fn radius_on<B: Boundary + ?Sized>(&self, table: &B) -> f64 {
        self.radius
            .unwrap_or_else(|| DEFAULT_RADIUS * table.unit_length())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_count_rounds_and_refuses_out_of_range() {
        assert_eq!(FrameOptions::new(10.0, 5.5).frame_count().unwrap(), 55);
        assert_eq!(FrameOptions::new(24.0, 0.03).frame_count().unwrap(), 1);
        for (fps, duration) in [
            (0.0, 1.0),
            (-1.0, 1.0),
            (f64::NAN, 1.0),
            (101.0, 1.0),
            (10.0, 0.0),
            (10.0, f64::INFINITY),
            (10.0, 0.01),
            (100.0, 1e4),
        ] {
            let e = FrameOptions::new(fps, duration).validate().unwrap_err();
            assert!(
                matches!(e, AnalysisError::InvalidOption { .. }),
                "{fps} fps, {duration} s: {e}"
            );
        }
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(
                FrameOptions::new(10.0, 1.0)
                    .with_speed(bad)
                    .validate()
                    .is_err()
            );
            assert!(
                FrameOptions::new(10.0, 1.0)
                    .with_radius(bad)
                    .validate()
                    .is_err()
            );
        }
    }
}
