//! Which implementation runs an ensemble's trajectories.
//!
//! Documented in the group docs (`run/mod.rs`), section "Which engine runs".

use std::fmt;

/// Which implementation runs an ensemble's trajectories. Both give the same
/// trajectories (the lane kernels reproduce the scalar reference trajectory
/// bitwise); the summed logarithms agree to rounding, because the lanes
/// accumulate growth factors and take one logarithm at the end: measured
/// relative differences are about `1e-13` for finite differences, `1e-16` for
/// the tangent method on chaotic orbits, up to `5e-11` on regular ones after
/// 5000 collisions, and up to `3e-6` for a ball sliding along a wall at a
/// grazing angle of `1e-9` (which amplifies rounding by about `1e9`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Engine {
    /// Many trajectories in lockstep vector lanes (`spinball-lanes`), the
    /// instruction set (AVX-512, AVX2, baseline) chosen at run time. The
    /// default; a table without a lane form
    /// ([`Boundary::shape`](spinball_geometry::Boundary::shape) is `None`)
    /// runs on the scalar path instead, and the result says so.
    #[default]
    Lanes,
    /// One trajectory at a time, the readable specification.
    Scalar,
}

impl Engine {
    /// `lanes` or `scalar`.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Engine::Lanes => "lanes",
            Engine::Scalar => "scalar",
        }
    }
}

impl fmt::Display for Engine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
