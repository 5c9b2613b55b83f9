//! Animation frames: where each ball is, and how far it has turned, at the
//! frame times of a film.
//!
//! A picture of a trajectory shows where the ball went; a film shows how
//! fast, and with spin, how the ball turns. This group samples the exact
//! dynamics at evenly spaced frame times, so that a front (the command line,
//! Python, the GIF writer of `spinball-plot`) only draws what it is given.
//!
//! - [`FrameOptions`]: frame rate, duration, how much billiard time one
//!   second of film shows ([`FrameOptions::speed`]) and the drawn ball
//!   radius ([`FrameOptions::radius`]), each checked with the range that
//!   works;
//! - [`BallTrack`]: one ball at every frame (position, spin angle, spin),
//!   with the exact collisions it passed;
//! - [`Frames`] and [`animation_frames`]: several balls of one billiard,
//!   started from [`Starts`](crate::run::Starts) like an ensemble.
//!
//! # Time
//! Frame `k` (from 0) shows the billiard at time `t_k = k · speed / fps`,
//! for `k < round(duration · fps)`. Collisions are **exact in time**: the
//! balls are stepped from wall to wall with
//! [`Billiard::step`](spinball_core::Billiard::step), and a frame that falls
//! between two collisions shows the ball on the straight chord between
//! them, at `x_c + (t_k − t_c) v` from the last collision `c` before it. No
//! wall is skipped, however many collisions fall between two frames: every
//! one of them is taken, and listed in [`BallTrack::collisions`].
//!
//! # Spin
//! The dynamics carry the spin as the surface speed `u = r ω` (ω the
//! angular velocity about the axis normal to the table, counter-clockwise
//! positive: at a wall whose inward normal is `n̂`, the contact point moves
//! along the tangent `t̂ = (n_y, −n_x)` at `v∥ + u`). The ball's radius does
//! not enter the motion (the table is the region the centre reaches), so a
//! film chooses one: the ball is drawn with radius `r`
//! ([`FrameOptions::radius`]) and turns at `ω = u / r`. The spin angle is
//! integrated exactly, `φ(t_k) = Σ u_i τ_i / r + u_c (t_k − t_c) / r` over
//! the flights `τ_i` before the last collision, starting from `φ = 0`
//! (the marker pointing along `+x`), counter-clockwise positive, in
//! radians and not wrapped.

mod ball_track;
mod frame_options;
mod frames;

pub use ball_track::{BallTrack, CollisionMark, track_ball};
pub use frame_options::{
    DEFAULT_DURATION, DEFAULT_FPS, FrameOptions, MAX_COLLISIONS_PER_BALL, MAX_FPS, MAX_FRAMES,
};
pub use frames::{Frames, animation_frames};
