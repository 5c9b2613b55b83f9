//! FTLE maps in shards: a large map computed a block of its cells at a
//! time (on several machines, or as the tasks of a job array) and joined
//! into the map one run gives, bitwise.
//!
//! The cells on the energy shell are numbered in row-major order, and cell
//! `k`'s trajectory is index `k` of one ensemble over all of them (its
//! tangent direction comes from the seed and `k`), so a cell's exponent does
//! not depend on which shard ran it. A shard runs the block
//! [`Shard::range`] of those indices; [`FtleMapPart::merge`] checks that
//! the parts are of one map and tile the indices, and joins them.

use std::ops::Range;

use spinball_core::SpinLaw;
use spinball_geometry::Boundary;

use super::ftle_map::{FtleMap, FtleMapOptions, grid_starts};
use crate::error::AnalysisError;
use crate::estimators::Method;
use crate::run::{Ensemble, RunDifference, Shard, TableRecord};

/// One shard of an FTLE map: the exponents of its block of cells, the
/// others `None`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FtleMapPart {
    /// The table (merging checks that every part is of the same one).
    pub table: TableRecord,
    /// Which shard this is.
    pub shard: Shard,
    /// The block of on-shell cells this part ran (indices in row-major
    /// order of the cells on the energy shell).
    pub starts: Range<u64>,
    /// Cells on the energy shell, in the whole map.
    pub on_shell: u64,
    /// The version of spinball that computed it.
    pub version: String,
    /// The map, with exponents only in this part's cells.
    pub map: FtleMap,
}

/// The cells of shard `shard` of the FTLE map of `table` under `law`
/// ([`ftle_map`](fn@super::ftle_map) is the whole map as one shard).
///
/// ```
/// use spinball_analysis::phase_space::{FtleMapOptions, FtleMapPart, Slice, ftle_map, ftle_map_part};
/// use spinball_analysis::run::Shard;
/// use spinball_core::SpinLaw;
/// use spinball_geometry::Stadium;
///
/// let options = FtleMapOptions::new(6, 5, Slice::Spin(0.1)).with_collisions(200);
/// let law = SpinLaw::new(0.5)?;
/// let table = Stadium::new(1.0)?;
/// let parts = (0..3)
///     .map(|k| ftle_map_part(table, law, &options, Shard::new(k, 3)?))
///     .collect::<Result<Vec<_>, _>>()?;
/// assert_eq!(FtleMapPart::merge(parts)?, ftle_map(table, law, &options)?);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`ftle_map`](fn@super::ftle_map); a failing start's error carries its
/// cell index `j·columns + i`.
pub fn ftle_map_part<B: Boundary + Sync>(
    table: B,
    law: SpinLaw,
    options: &FtleMapOptions,
    shard: Shard,
) -> Result<FtleMapPart, AnalysisError> {
    let (mut map, starts, cell_of) = grid_starts(&table, &law, options)?;
    let on_shell = starts.len() as u64;
    let block = shard.range(0..on_shell);
    let record = TableRecord::of(&table);
    let ensemble = Ensemble::from_states(table, law, starts)
        .with_method(Method::Tangent)
        .with_collisions(options.collisions)
        .with_seed(options.seed)
        .with_threads(options.threads);
    let cell = |index: u64| cell_of[index as usize] as u64;
    let stats = ensemble.trajectories(block.clone()).map_err(|e| match e {
        AnalysisError::Launch { index, source } => AnalysisError::Launch {
            index: cell(index),
            source,
        },
        AnalysisError::Step { index, source } => AnalysisError::Step {
            index: cell(index),
            source,
        },
        other => other,
    })?;
    for t in stats {
        map.exponents[cell_of[t.index as usize]] = Some(t.exponent);
    }
    Ok(FtleMapPart {
        table: record,
        shard,
        starts: block,
        on_shell,
        version: env!("CARGO_PKG_VERSION").to_string(),
        map,
    })
}

impl FtleMapPart {
    /// Whether `other` is a part of the same map as `self`: the first field
    /// that differs (table by its geometry, version, α, grid, slice,
    /// collisions, seed, threshold; numbers bit for bit). The threads may
    /// differ: they change no number.
    ///
    /// # Errors
    /// [`RunDifference::Field`] naming the field and both values;
    /// [`RunDifference::NoShape`] for a table without a shape.
    pub fn same_map(&self, other: &FtleMapPart) -> Result<(), RunDifference> {
        self.table.same_table(&other.table)?;
        let (a, b) = (&self.map, &other.map);
        let (oa, ob) = (&a.options, &b.options);
        let fields: [(&'static str, String, String); 9] = [
            ("version", self.version.clone(), other.version.clone()),
            ("alpha", format!("{:?}", a.alpha), format!("{:?}", b.alpha)),
            ("columns", oa.columns.to_string(), ob.columns.to_string()),
            ("rows", oa.rows.to_string(), ob.rows.to_string()),
            (
                "slice",
                format!("{:?}", oa.slice),
                format!("{:?}", ob.slice),
            ),
            (
                "collisions per start",
                oa.collisions.to_string(),
                ob.collisions.to_string(),
            ),
            ("seed", oa.seed.to_string(), ob.seed.to_string()),
            (
                "threshold",
                format!("{:?}", oa.threshold),
                format!("{:?}", ob.threshold),
            ),
            (
                "cells on the shell",
                self.on_shell.to_string(),
                other.on_shell.to_string(),
            ),
        ];
        match fields.into_iter().find(|(_, x, y)| x != y) {
            Some((what, first, other)) => Err(RunDifference::Field { what, first, other }),
            None => Ok(()),
        }
    }

    /// Join the parts of one map (in any order) into the whole map, the map
    /// [`ftle_map`](fn@super::ftle_map) gives in one run, bitwise.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] (`shards`) for no parts, parts of
    /// different maps (naming the field and both values), a part whose
    /// exponents do not match its block, and blocks that overlap or leave
    /// cells out (naming them).
    pub fn merge(mut parts: Vec<FtleMapPart>) -> Result<FtleMap, AnalysisError> {
        let bad = |reason: String| AnalysisError::invalid("shards", reason);
        let Some(first) = parts.first() else {
            return Err(bad("no parts to merge".into()));
        };
        for p in &parts[1..] {
            first
                .same_map(p)
                .map_err(|e| bad(format!("the parts are of different maps: {e}")))?;
        }
        for p in &parts {
            let filled = p.map.exponents.iter().flatten().count() as u64;
            let expected = p.starts.end.saturating_sub(p.starts.start);
            if p.map.exponents.len() != first.map.exponents.len() || filled != expected {
                return Err(bad(format!(
                    "shard {} holds {filled} exponents for its {expected} cells {:?}: damaged or edited",
                    p.shard, p.starts
                )));
            }
        }
        parts.sort_by_key(|p| (p.starts.start, p.starts.end));
        let mut next = 0;
        for p in &parts {
            if p.starts.start > next {
                return Err(bad(format!(
                    "on-shell cells {:?} are missing (give every shard)",
                    next..p.starts.start
                )));
            }
            if p.starts.start < next && p.starts.end > p.starts.start {
                return Err(bad(format!(
                    "on-shell cells from {} are in two parts: each cell must come from one shard",
                    p.starts.start
                )));
            }
            next = next.max(p.starts.end);
        }
        let on_shell = parts[0].on_shell;
        if next < on_shell {
            return Err(bad(format!(
                "on-shell cells {:?} are missing (give every shard)",
                next..on_shell
            )));
        }
        let mut map = parts[0].map.clone();
        for p in &parts[1..] {
            for (cell, x) in map.exponents.iter_mut().zip(&p.map.exponents) {
                if x.is_some() {
                    *cell = *x;
                }
            }
        }
        Ok(map)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::phase_space::ftle_map::Slice;
    use spinball_geometry::{Sinai, Stadium};

    fn options() -> FtleMapOptions {
        FtleMapOptions::new(7, 4, Slice::Q(0.2)).with_collisions(150)
    }

    #[test]
    fn shards_join_bitwise_and_refuse_gaps_overlaps_and_other_maps() {
        let law = SpinLaw::new(0.5).unwrap();
        let table = Stadium::new(1.0).unwrap();
        let whole = crate::phase_space::ftle_map(table, law, &options()).unwrap();
        let part = |k, n| ftle_map_part(table, law, &options(), Shard::new(k, n).unwrap()).unwrap();
        let parts: Vec<_> = (0..4).map(|k| part(k, 4)).collect();
        // In any order.
        let reversed: Vec<_> = parts.iter().rev().cloned().collect();
        assert_eq!(FtleMapPart::merge(reversed).unwrap(), whole);
        // A missing shard.
        let e = FtleMapPart::merge(parts[..3].to_vec()).unwrap_err();
        assert!(e.to_string().contains("are missing"), "{e}");
        // The same block twice.
        let twice = vec![parts[0].clone(), parts[0].clone(), parts[1].clone()];
        let e = FtleMapPart::merge(twice).unwrap_err();
        assert!(e.to_string().contains("two parts"), "{e}");
        // Another seed, another table.
        let other = ftle_map_part(
            table,
            law,
            &options().with_seed(9),
            Shard::new(1, 4).unwrap(),
        )
        .unwrap();
        let e = FtleMapPart::merge(vec![parts[0].clone(), other]).unwrap_err();
        assert!(
            e.to_string().contains("seed 0 in one, 9 in the other"),
            "{e}"
        );
        let sinai = ftle_map_part(
            Sinai::new(2.0, 1.0).unwrap(),
            law,
            &options(),
            Shard::new(1, 4).unwrap(),
        )
        .unwrap();
        let e = FtleMapPart::merge(vec![parts[0].clone(), sinai]).unwrap_err();
        assert!(e.to_string().contains("table"), "{e}");
        // An edited part.
        let mut edited = parts[2].clone();
        edited.map.exponents.iter_mut().for_each(|x| *x = None);
        let mut all = parts.clone();
        all[2] = edited;
        assert!(FtleMapPart::merge(all).is_err());
        assert!(FtleMapPart::merge(Vec::new()).is_err());
    }
}
