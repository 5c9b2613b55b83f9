//! The bundled font.
//!
//! plotters' `ab_glyph` renderer draws text without any system font library,
//! but only with fonts registered by name. This module registers DejaVu Sans
//! (regular, bold, oblique; from the `dejavu` crate, which ships the TTF files
//! under the DejaVu/Bitstream Vera licence) as the family [`FAMILY`], and also
//! under plotters' default family names, so that every text plotters draws
//! finds a font. Every drawing entry point of this crate calls [`ensure`];
//! call it yourself only if you draw with plotters directly.

use std::sync::OnceLock;

use plotters::style::{FontStyle, register_font};

use crate::error::PlotError;

/// The font family name used by this crate.
pub const FAMILY: &str = "sans-serif";

/// Register the bundled font (once per process; later calls are free).
///
/// # Errors
/// [`PlotError::Font`] if the bundled font data cannot be parsed (never
/// expected: the data is compiled in).
pub fn ensure() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        let mut ok = true;
        for family in [FAMILY, "serif", "monospace"] {
            ok &= register_font(family, FontStyle::Normal, dejavu::sans::regular()).is_ok();
            ok &= register_font(family, FontStyle::Bold, dejavu::sans::bold()).is_ok();
            ok &= register_font(family, FontStyle::Italic, dejavu::sans::oblique()).is_ok();
            ok &= register_font(family, FontStyle::Oblique, dejavu::sans::oblique()).is_ok();
        }
        ok
    });
    if ok { Ok(()) } else { Err(PlotError::Font) }
}
