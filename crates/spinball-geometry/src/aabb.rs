//! Axis-aligned bounding boxes: where a table lies, for sampling and for
//! the size its tolerances scale with.

use glam::DVec2;

/// An axis-aligned bounding box.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Aabb {
    /// Lower-left corner.
    pub min: DVec2,
    /// Upper-right corner.
    pub max: DVec2,
}

impl Aabb {
    /// The box spanned by two corners.
    pub fn new(min: DVec2, max: DVec2) -> Self {
        Aabb { min, max }
    }
    /// Centre of the box.
    pub fn center(&self) -> DVec2 {
        0.5 * (self.min + self.max)
    }
    /// Full extents (width, height).
    pub fn size(&self) -> DVec2 {
        self.max - self.min
    }
    /// The smallest box holding both.
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb::new(self.min.min(other.min), self.max.max(other.max))
    }
}
