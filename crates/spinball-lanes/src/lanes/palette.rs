//! The constant tables lanes index by a wall's id: a [`Palette`] holds one
//! constant per entry ([`Lanes::lookup`]), [`Records`] eight per entry
//! ([`Lanes::fetch`]). Both are padded alike, so that every instruction-set
//! level reads the same entry for the same index, which keeps the lane
//! kernels bitwise equal to the scalar path.
//!
//! [`Lanes::lookup`]: super::Lanes::lookup
//! [`Lanes::fetch`]: super::Lanes::fetch

/// A table of constants that lanes index ([`Lanes::lookup`]), padded with
/// zeros to a multiple of 8 entries (at least 8), so that AVX-512 holds a
/// table of up to 16 entries in one or two registers.
///
/// [`Lanes::lookup`]: super::Lanes::lookup
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Palette(Vec<f64>);

impl Palette {
    /// The entries `values`, in order, then zeros up to a multiple of 8.
    pub fn new(values: impl IntoIterator<Item = f64>) -> Self {
        let mut v: Vec<f64> = values.into_iter().collect();
        v.resize(v.len().div_ceil(8).max(1) * 8, 0.0);
        Palette(v)
    }

    /// The entries, padding included (a multiple of 8, at least 8).
    pub fn entries(&self) -> &[f64] {
        &self.0
    }

    /// The entry at `index` (an integer in `0..len`; a NaN, a negative index
    /// or one past the end reads some entry of the table, which one being
    /// unspecified).
    #[inline(always)]
    pub fn get(&self, index: f64) -> f64 {
        // `as usize` saturates (NaN and negatives to 0).
        self.0[(index as usize).min(self.0.len() - 1)]
    }
}

/// Eight constants per entry (a wall's, by its id) for [`Lanes::fetch`],
/// kept twice: as rows, an entry's eight side by side, and as columns, one
/// [`Palette`] per constant. Both are padded with zeros to the palettes'
/// length, so that every level reads, for any index, the entry its
/// [`Lanes::lookup`] reads.
///
/// [`Lanes::fetch`]: super::Lanes::fetch
/// [`Lanes::lookup`]: super::Lanes::lookup
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Records {
    rows: Vec<[f64; 8]>,
    columns: [Palette; 8],
}

impl Records {
    /// The entries `rows`, in order.
    pub fn new(rows: Vec<[f64; 8]>) -> Self {
        let columns: [Palette; 8] =
            std::array::from_fn(|c| Palette::new(rows.iter().map(|r| r[c])));
        let mut rows = rows;
        rows.resize(columns[0].entries().len(), [0.0; 8]);
        Records { rows, columns }
    }

    /// The rows, padding included (as many as a column's entries).
    pub fn rows(&self) -> &[[f64; 8]] {
        &self.rows
    }

    /// The row at `index`, read as [`Palette::get`] reads an entry.
    #[inline(always)]
    pub fn row(&self, index: f64) -> &[f64; 8] {
        // `as usize` saturates (NaN and negatives to 0).
        &self.rows[(index as usize).min(self.rows.len() - 1)]
    }

    /// Column `c` (`c < 8`).
    pub fn column(&self, c: usize) -> &Palette {
        &self.columns[c]
    }
}
