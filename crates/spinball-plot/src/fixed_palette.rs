//! The one 256-colour palette every GIF frame is quantised to.
//!
//! A GIF holds at most 256 colours per frame. Films drawn by this crate use
//! few colours (white, the table fills, black walls and text, the
//! categorical [`PALETTE`](crate::PALETTE) for the balls), plus the greys of
//! anti-aliased text: a fixed palette that holds those exactly, a 6×6×6
//! colour cube and a grey ramp keeps every frame exact where it matters and
//! lets all frames share one global colour table (no per-frame palette, so
//! files stay small).

use std::sync::OnceLock;

use plotters::style::RGBColor;

use crate::colormap::PALETTE;
use crate::table_plot::{OBSTACLE_FILL, TABLE_FILL};

/// Colours kept exactly: white, black, the table fills and the ball palette.
fn exact_colours() -> Vec<RGBColor> {
    let mut c = vec![
        RGBColor(0xFF, 0xFF, 0xFF),
        RGBColor(0, 0, 0),
        TABLE_FILL,
        OBSTACLE_FILL,
    ];
    c.extend(PALETTE);
    c
}

/// The palette and a lookup from 15-bit colour to palette index.
#[derive(Debug)]
pub(crate) struct FixedPalette {
    /// `[r, g, b, r, g, b, ...]`, 256 entries, as a GIF colour table.
    rgb: Vec<u8>,
    /// Exact colours and their indices, tried first.
    exact: Vec<([u8; 3], u8)>,
    /// Nearest palette index of each 5-bit-per-channel colour cell.
    cells: Vec<u8>,
}

/// Levels of the colour cube on each channel.
const CUBE: [u8; 6] = [0, 51, 102, 153, 204, 255];

impl FixedPalette {
    /// The shared palette (built once).
    pub(crate) fn get() -> &'static FixedPalette {
        static PALETTE_CELL: OnceLock<FixedPalette> = OnceLock::new();
        PALETTE_CELL.get_or_init(FixedPalette::build)
    }

    fn build() -> FixedPalette {
        let mut colours: Vec<[u8; 3]> = exact_colours().iter().map(|c| [c.0, c.1, c.2]).collect();
        let n_exact = colours.len();
        for r in CUBE {
            for g in CUBE {
                for b in CUBE {
                    colours.push([r, g, b]);
                }
            }
        }
        // Fill the rest with greys between the cube's (anti-aliased text).
        let n_grey = 256 - colours.len();
        for i in 1..=n_grey {
            let v = (255 * i / (n_grey + 1)) as u8;
            colours.push([v, v, v]);
        }
        debug_assert_eq!(colours.len(), 256);
        let exact = colours[..n_exact]
            .iter()
            .enumerate()
            .map(|(i, c)| (*c, i as u8))
            .collect();
        let nearest = |target: [u8; 3]| -> u8 {
            let d2 = |c: &[u8; 3]| -> i32 {
                (0..3)
                    .map(|k| (i32::from(c[k]) - i32::from(target[k])).pow(2))
                    .sum()
            };
            let (i, _) = colours
                .iter()
                .enumerate()
                .min_by_key(|(_, c)| d2(c))
                .expect("256 colours");
            i as u8
        };
        let cells = (0..1usize << 15)
            .map(|cell| {
                let channel = |shift: usize| ((((cell >> shift) & 31) as u8) << 3) | 4;
                nearest([channel(10), channel(5), channel(0)])
            })
            .collect();
        FixedPalette {
            rgb: colours.iter().flatten().copied().collect(),
            exact,
            cells,
        }
    }

    /// The colour table, `[r, g, b, ...]` for 256 entries.
    pub(crate) fn rgb(&self) -> &[u8] {
        &self.rgb
    }

    /// The palette index for one colour: exact for the colours the crate
    /// draws with, the nearest of its 5-bit cell otherwise.
    pub(crate) fn index(&self, c: [u8; 3]) -> u8 {
        if let Some((_, i)) = self.exact.iter().find(|(e, _)| *e == c) {
            return *i;
        }
        let cell =
            (usize::from(c[0] >> 3) << 10) | (usize::from(c[1] >> 3) << 5) | usize::from(c[2] >> 3);
        self.cells[cell]
    }

    /// Quantise an RGB image (`[r, g, b, ...]`) into `out` (one index per pixel).
    pub(crate) fn quantise(&self, rgb: &[u8], out: &mut Vec<u8>) {
        out.clear();
        out.extend(rgb.chunks_exact(3).map(|p| self.index([p[0], p[1], p[2]])));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drawn_colours_are_exact_and_others_near() {
        let p = FixedPalette::get();
        assert_eq!(p.rgb().len(), 768);
        for c in exact_colours() {
            let i = usize::from(p.index([c.0, c.1, c.2]));
            assert_eq!(&p.rgb()[3 * i..3 * i + 3], &[c.0, c.1, c.2]);
        }
        // Any colour lands within half a cube step (plus the cell) per channel.
        for c in [[1u8, 2, 3], [200, 100, 50], [128, 128, 128], [77, 250, 13]] {
            let i = usize::from(p.index(c));
            for k in 0..3 {
                let d = (i32::from(p.rgb()[3 * i + k]) - i32::from(c[k])).abs();
                assert!(d <= 26 + 8, "{c:?} → {:?}", &p.rgb()[3 * i..3 * i + 3]);
            }
        }
    }
}
