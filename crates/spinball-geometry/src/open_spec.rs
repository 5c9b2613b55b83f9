//! Spec strings for the open and periodic built-in tables, so that a table
//! with a hole or a Lorentz gas is one argument (`--table` on the command
//! line, a string in Python) like the closed tables:
//!
//! - `stadium:a=1,hole=0.2` — the stadium with a hole of arc length 0.2,
//!   centred by default on its right cap (`at=S` sets the Birkhoff `s` of
//!   the centre): [`SegmentTable::stadium_with_hole`];
//! - `sinai:L=2,R=1,hole=0.2` — the Sinai table with a hole centred by
//!   default on the middle of its right side (`at=S`):
//!   [`SegmentTable::sinai_with_hole`];
//! - `circle:R=1,hole=0.2` — the circle with a hole centred at polar angle
//!   0 (`at=ANGLE`): [`SegmentTable::circle_with_hole`];
//! - `lorentz:lattice=triangular,w=1,R=0.45` — the unit cell of a Lorentz
//!   gas with periodic sides (`lattice=square` or `triangular`, the
//!   default; `w` 1 and `R` 0.4 by default): [`LorentzGas::table`].
//!
//! Every other spec is a closed table ([`Table`]'s grammar).

use std::f64::consts::PI;
use std::str::FromStr;

use crate::lorentz::{Lattice, LorentzGas};
use crate::segment_table::SegmentTable;
use crate::table::{Built, Table, TableSpecError};

/// The `key=value` pairs of a spec, keys lower-cased.
struct Pairs {
    pairs: Vec<(String, String)>,
}

impl Pairs {
    fn new(
        table: &'static str,
        allowed: &'static str,
        params: &str,
    ) -> Result<Self, TableSpecError> {
        let mut pairs = Vec::new();
        for pair in params.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            let (k, v) = pair
                .split_once('=')
                .ok_or_else(|| TableSpecError::BadPair(pair.to_string()))?;
            let k = k.trim().to_ascii_lowercase();
            if !allowed.split(", ").any(|a| a.eq_ignore_ascii_case(&k)) {
                return Err(TableSpecError::UnknownKey {
                    table,
                    key: k,
                    allowed,
                });
            }
            pairs.push((k, v.trim().to_string()));
        }
        Ok(Pairs { pairs })
    }

    fn word(&self, key: &str) -> Option<&str> {
        self.pairs
            .iter()
            .rev()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }

    fn number(&self, key: &str, default: f64) -> Result<f64, TableSpecError> {
        match self.word(key) {
            None => Ok(default),
            Some(v) => v
                .parse()
                .map_err(|_| TableSpecError::BadPair(format!("{key}={v}"))),
        }
    }
}

/// An open table's spec (one with `hole=`, or a `lorentz:` cell), or
/// `None` for a spec of the closed tables' grammar.
fn open_table(spec: &str) -> Result<Option<SegmentTable>, TableSpecError> {
    let (name, params) = spec.trim().split_once(':').unwrap_or((spec.trim(), ""));
    let name = name.trim().to_ascii_lowercase();
    let has_hole = params
        .split(',')
        .filter_map(|p| p.split_once('='))
        .any(|(k, _)| k.trim().eq_ignore_ascii_case("hole"));
    let table = match name.as_str() {
        "lorentz" => {
            let p = Pairs::new("lorentz", "lattice, w, R", params)?;
            let lattice = match p.word("lattice").map(str::to_ascii_lowercase).as_deref() {
                None | Some("triangular") => Lattice::Triangular,
                Some("square") => Lattice::Square,
                Some(other) => {
                    return Err(TableSpecError::BadWord {
                        key: "lattice",
                        value: other.to_string(),
                        allowed: "square, triangular",
                    });
                }
            };
            let (w, r) = (p.number("w", 1.0)?, p.number("r", 0.4)?);
            let gas = match lattice {
                Lattice::Square => LorentzGas::square(w, r)?,
                Lattice::Triangular => LorentzGas::triangular(w, r)?,
            };
            gas.table()?
        }
        "stadium" if has_hole => {
            let p = Pairs::new("stadium", "a, hole, at", params)?;
            let a = p.number("a", 1.0)?;
            let at = p.number("at", 2.0 * a + 0.5 * PI)?;
            SegmentTable::stadium_with_hole(a, at, p.number("hole", 0.0)?)?
        }
        "sinai" if has_hole => {
            let p = Pairs::new("sinai", "L, R, hole, at", params)?;
            let (l, r) = (p.number("l", 2.0)?, p.number("r", 1.0)?);
            let at = p.number("at", 3.0 * l)?;
            SegmentTable::sinai_with_hole(l, r, at, p.number("hole", 0.0)?)?
        }
        "circle" if has_hole => {
            let p = Pairs::new("circle", "R, hole, at", params)?;
            SegmentTable::circle_with_hole(
                p.number("r", 1.0)?,
                p.number("at", 0.0)?,
                p.number("hole", 0.0)?,
            )?
        }
        _ => return Ok(None),
    };
    Ok(Some(table))
}

impl FromStr for Built {
    type Err = TableSpecError;

    /// Read any built-in table: a closed one as [`Table`] reads it
    /// (`stadium:a=1`), an open one with a hole (`stadium:a=1,hole=0.2`,
    /// `sinai:L=2,R=1,hole=0.2,at=6`, `circle:R=1,hole=0.3`) or a Lorentz
    /// gas's cell (`lorentz:lattice=square,w=1,R=0.4`). Keys: `hole` (arc
    /// length) and `at` (the hole's centre: Birkhoff `s`, by default the
    /// middle of the stadium's right cap `2a + π/2` or of the Sinai table's
    /// right side `3L`; for the circle a polar angle, default 0);
    /// `lattice` (`square` or `triangular`, the default), `w` (1) and `R`
    /// (0.4).
    ///
    /// ```
    /// use spinball_geometry::{Boundary, Built};
    /// let open: Built = "stadium:a=1,hole=0.2".parse()?;
    /// assert!(open.has_holes());
    /// let gas: Built = "lorentz:lattice=triangular,w=1,R=0.45".parse()?;
    /// assert!(gas.lattice().is_some());
    /// assert!(matches!("stadium:a=1".parse::<Built>()?, Built::Table(_)));
    /// # Ok::<(), spinball_geometry::TableSpecError>(())
    /// ```
    fn from_str(spec: &str) -> Result<Self, Self::Err> {
        match open_table(spec)? {
            Some(table) => Ok(Built::Segments(table)),
            None => spec.parse::<Table>().map(Built::Table),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::boundary::Boundary;

    #[test]
    fn open_specs_build_the_tables_of_their_constructors() {
        let s: Built = "stadium:a=1,hole=0.2".parse().unwrap();
        let want = SegmentTable::stadium_with_hole(1.0, 2.0 + 0.5 * PI, 0.2).unwrap();
        assert_eq!(s, Built::Segments(want));
        let s: Built = "Sinai:L=2,R=1,hole=0.1,at=1".parse().unwrap();
        let want = SegmentTable::sinai_with_hole(2.0, 1.0, 1.0, 0.1).unwrap();
        assert_eq!(s, Built::Segments(want));
        let c: Built = "circle:R=2,hole=0.3,at=1".parse().unwrap();
        assert_eq!(
            c,
            Built::Segments(SegmentTable::circle_with_hole(2.0, 1.0, 0.3).unwrap())
        );
        let g: Built = "lorentz:lattice=square,w=1,R=0.4".parse().unwrap();
        let want = LorentzGas::square(1.0, 0.4).unwrap().table().unwrap();
        assert_eq!(g, Built::Segments(want));
        let g: Built = "lorentz".parse().unwrap();
        assert!(g.lattice().is_some());
        assert!(!g.has_holes());
        assert_eq!(
            "sinai:L=2,R=1".parse::<Built>().unwrap(),
            Built::Table("sinai:L=2,R=1".parse().unwrap())
        );
    }

    #[test]
    fn bad_open_specs_say_what_works() {
        let e = "lorentz:lattice=hexagonal".parse::<Built>().unwrap_err();
        assert!(e.to_string().contains("square, triangular"), "{e}");
        let e = "stadium:a=1,hole=0.2,b=3".parse::<Built>().unwrap_err();
        assert!(e.to_string().contains("a, hole, at"), "{e}");
        let e = "lorentz:w=1,R=0.6".parse::<Built>().unwrap_err();
        assert!(matches!(e, TableSpecError::Geometry(_)), "{e}");
        assert!("stadium:a=1,hole=x".parse::<Built>().is_err());
        assert!("stadium:a=1,hole=0".parse::<Built>().is_err());
    }
}
