//! A stable content hash for the files a run writes (partial results,
//! checkpoints, spectrum results) and for a table's identity.
//!
//! FNV-1a (64 bits) over a canonical byte encoding: integers as 8 bytes
//! little-endian, floats as the 8 bytes of their bits (so `-0.0` and `0.0`,
//! and every last bit, count), strings as their length then their UTF-8
//! bytes, enum variants as a one-byte tag before their fields. The
//! algorithm and the encoding are written out here, so the same content
//! gives the same hash on every platform, compiler and build (unlike
//! `std`'s `DefaultHasher`, whose algorithm is not guaranteed). It detects
//! edits and damage, not a forger: anyone can recompute it.
//!
//! Documented in the group docs (`run/mod.rs`), section "Checksums".

// Without `serde` no file is written or read: only the table identity
// uses the hash, and the content encoders rest unused.
#![cfg_attr(not(feature = "serde"), allow(dead_code))]

use spinball_core::Sampler;
use spinball_geometry::{Segment, Shape, WallKind};
use thiserror::Error;

use super::engine::Engine;
use super::provenance::{Provenance, TableRecord};
use super::trajectory::TrajectoryStats;
use crate::estimators::{Method, Spectrum, SpectrumOptions};

/// The prefix of a checksum as written in a file: the algorithm's name.
pub(crate) const CHECKSUM_PREFIX: &str = "fnv1a64:";

/// Why a partial result, checkpoint or spectrum result read back (or
/// handed to a merge or a resume) is refused: its content does not hold
/// together, so it was edited or damaged after it was written.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum IntegrityError {
    /// No checksum: written before results carried one.
    #[error(
        "it has no checksum: it was written by spinball {version} before partial results, checkpoints and spectrum results carried one, and is refused (nothing shows it was not edited); rerun the shard or the run that wrote it"
    )]
    NoChecksum {
        /// The version the file says wrote it.
        version: String,
    },
    /// The checksum is not one this version computes.
    #[error("its checksum `{0}` is not a `fnv1a64:` followed by 16 hex digits")]
    BadChecksum(String),
    /// The count of per-IC values does not hold.
    #[error(
        "it says it holds {stated} per-initial-condition values but holds {found}: it was edited or damaged; rerun the shard or the run that wrote it"
    )]
    Count {
        /// The count written with the checksum.
        stated: u64,
        /// The values found.
        found: u64,
    },
    /// The checksum does not hold.
    #[error(
        "its checksum does not hold (written {stated}, the content gives {computed}): it was edited or damaged after it was written; rerun the shard or the run that wrote it"
    )]
    Checksum {
        /// The checksum written in the file.
        stated: String,
        /// The checksum of the content read.
        computed: String,
    },
    /// A per-initial-condition value is not a finite number.
    #[error(
        "initial condition {index}: its {what} is {value}, not a finite number (no run writes that)"
    )]
    NonFinite {
        /// The initial condition.
        index: u64,
        /// Which value.
        what: &'static str,
        /// The value.
        value: f64,
    },
    /// The per-IC values are not the consecutive indices of the range.
    #[error(
        "its values are not those of initial conditions {range:?} in order: {found} where {expected} is due"
    )]
    Indices {
        /// The range the values should cover from its start.
        range: std::ops::Range<u64>,
        /// The index due.
        expected: u64,
        /// The index found (or the count, past the end).
        found: u64,
    },
}

/// Check a checksum read from a file against the content's.
pub(crate) fn verify(
    stated: Option<&str>,
    computed: &Fnv1a,
    version: &str,
) -> Result<(), IntegrityError> {
    let stated = stated.ok_or_else(|| IntegrityError::NoChecksum {
        version: version.to_string(),
    })?;
    let hex = stated
        .strip_prefix(CHECKSUM_PREFIX)
        .filter(|h| h.len() == 16 && h.bytes().all(|b| b.is_ascii_hexdigit()))
        .ok_or_else(|| IntegrityError::BadChecksum(stated.to_string()))?;
    if u64::from_str_radix(hex, 16).ok() != Some(computed.finish()) {
        return Err(IntegrityError::Checksum {
            stated: stated.to_string(),
            computed: computed.text(),
        });
    }
    Ok(())
}

/// Refuse a non-finite value.
pub(crate) fn finite(index: u64, what: &'static str, value: f64) -> Result<(), IntegrityError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(IntegrityError::NonFinite { index, what, value })
    }
}

/// FNV-1a, 64 bits, fed through the canonical encoding.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Fnv1a(u64);

impl Fnv1a {
    const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
    const PRIME: u64 = 0x0000_0100_0000_01b3;

    /// A hash of `domain` (what is hashed: a file's kind), to which the
    /// content is then added.
    pub(crate) fn new(domain: &str) -> Self {
        let mut h = Fnv1a(Self::OFFSET);
        h.str(domain);
        h
    }

    fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(Self::PRIME);
        }
    }

    pub(crate) fn u64(&mut self, x: u64) {
        self.bytes(&x.to_le_bytes());
    }

    pub(crate) fn f64(&mut self, x: f64) {
        self.u64(x.to_bits());
    }

    pub(crate) fn f64s(&mut self, xs: &[f64]) {
        for &x in xs {
            self.f64(x);
        }
    }

    pub(crate) fn tag(&mut self, t: u8) {
        self.bytes(&[t]);
    }

    pub(crate) fn str(&mut self, s: &str) {
        self.u64(s.len() as u64);
        self.bytes(s.as_bytes());
    }

    pub(crate) fn finish(&self) -> u64 {
        self.0
    }

    /// The hash as written in a file: `fnv1a64:` and 16 hex digits.
    pub(crate) fn text(&self) -> String {
        format!("{CHECKSUM_PREFIX}{:016x}", self.0)
    }

    pub(crate) fn shape(&mut self, shape: &Shape) {
        match shape {
            Shape::Circle { radius } => {
                self.tag(0);
                self.f64(*radius);
            }
            Shape::Rectangle { l, h } => {
                self.tag(1);
                self.f64s(&[*l, *h]);
            }
            Shape::Stadium { a } => {
                self.tag(2);
                self.f64(*a);
            }
            Shape::Sinai { l, r } => {
                self.tag(3);
                self.f64s(&[*l, *r]);
            }
            Shape::Segments {
                outer,
                holes,
                kinds,
                ..
            } => {
                self.tag(4);
                self.walls(outer);
                self.u64(holes.len() as u64);
                for hole in holes {
                    self.walls(hole);
                }
                // Closed tables (no kinds) hash as they always did.
                if !kinds.is_empty() {
                    self.tag(5);
                    self.u64(kinds.len() as u64);
                    for kind in kinds {
                        match kind {
                            WallKind::Reflecting => self.tag(0),
                            WallKind::Hole => self.tag(1),
                            WallKind::Periodic { partner, shift, .. } => {
                                self.tag(2);
                                self.u64(u64::from(*partner));
                                self.f64s(&[shift.x, shift.y]);
                            }
                        }
                    }
                }
            }
        }
    }

    fn walls(&mut self, walls: &[Segment]) {
        self.u64(walls.len() as u64);
        for w in walls {
            match w {
                Segment::Line(l) => {
                    self.tag(0);
                    self.f64s(&[l.start().x, l.start().y, l.end().x, l.end().y]);
                }
                Segment::Arc(a) => {
                    self.tag(1);
                    let c = a.center();
                    self.f64s(&[c.x, c.y, a.radius(), a.start_angle(), a.sweep()]);
                }
            }
        }
    }

    pub(crate) fn method(&mut self, method: Method) {
        match method {
            Method::FiniteDifference { delta0 } => {
                self.tag(0);
                self.f64(delta0);
            }
            Method::Tangent => self.tag(1),
        }
    }

    pub(crate) fn sampler(&mut self, sampler: Option<Sampler>) {
        match sampler {
            None => self.tag(0),
            Some(s) => {
                self.tag(1);
                self.str(s.name());
            }
        }
    }

    fn engine(&mut self, engine: Engine) {
        self.str(engine.name());
    }

    pub(crate) fn table(&mut self, table: &TableRecord) {
        self.str(&table.name);
        match &table.shape {
            None => self.tag(0),
            Some(s) => {
                self.tag(1);
                self.shape(s);
            }
        }
    }

    pub(crate) fn provenance(&mut self, p: &Provenance) {
        self.table(&p.table);
        self.f64(p.alpha);
        self.method(p.method);
        self.sampler(p.sampler);
        self.u64(p.seed);
        self.u64(p.collisions_per_ic);
        self.f64(p.threshold);
        self.engine(p.engine);
    }

    pub(crate) fn trajectory(&mut self, t: &TrajectoryStats) {
        self.u64(t.index);
        self.f64s(&[t.exponent, t.per_collision, t.time]);
        self.u64(t.collisions);
    }

    pub(crate) fn spectrum_options(&mut self, o: &SpectrumOptions) {
        self.u64(o.collisions);
        self.method(o.method);
        self.u64(u64::from(o.qr_interval));
    }

    pub(crate) fn spectrum(&mut self, s: &Spectrum) {
        self.f64s(&s.exponents);
        self.f64s(&s.per_collision);
        self.f64s(&[s.sum, s.time]);
        self.u64(s.collisions);
        self.method(s.method);
        self.u64(s.floored);
    }
}

/// The fingerprint of a table's geometry: its kind and the exact bits of
/// its parameters (every wall's end points, centre, radius and angles for
/// a segment table).
pub(crate) fn shape_fingerprint(shape: &Shape) -> u64 {
    let mut h = Fnv1a::new("spinball.table");
    h.shape(shape);
    h.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_matches_the_reference_values() {
        // The published FNV-1a 64 test vectors ("" and "a"), on the raw
        // byte stream.
        let mut h = Fnv1a(Fnv1a::OFFSET);
        assert_eq!(h.finish(), 0xcbf2_9ce4_8422_2325);
        h.bytes(b"a");
        assert_eq!(h.finish(), 0xaf63_dc4c_8601_ec8c);
        let mut h = Fnv1a(Fnv1a::OFFSET);
        h.bytes(b"foobar");
        assert_eq!(h.finish(), 0x8594_4171_f739_67e8);
    }

    #[test]
    fn every_bit_counts() {
        let a = shape_fingerprint(&Shape::Stadium { a: 1.0 });
        assert_eq!(a, shape_fingerprint(&Shape::Stadium { a: 1.0 }));
        assert_ne!(
            a,
            shape_fingerprint(&Shape::Stadium {
                a: 1.0f64.next_up()
            })
        );
        assert_ne!(
            shape_fingerprint(&Shape::Circle { radius: 0.0 }),
            shape_fingerprint(&Shape::Circle { radius: -0.0 })
        );
        assert_ne!(
            shape_fingerprint(&Shape::Rectangle { l: 1.0, h: 2.0 }),
            shape_fingerprint(&Shape::Sinai { l: 1.0, r: 2.0 })
        );
    }
}
