//! What every plot can do: check its data, draw into an area, save a PNG.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::PlotError;
use crate::font;
use crate::style::Style;

/// Smallest image side accepted (pixels).
pub(crate) const MIN_SIDE: u32 = 64;
/// Largest image side accepted (pixels).
pub(crate) const MAX_SIDE: u32 = 16_384;

/// A picture that can be drawn into any plotters drawing area.
pub trait Plot {
    /// Check the data without drawing: the errors [`draw`](Plot::draw) would
    /// return for bad data ([`PlotError::EmptyData`],
    /// [`PlotError::LengthMismatch`], [`PlotError::Invalid`]).
    ///
    /// # Errors
    /// As described.
    fn validate(&self) -> Result<(), PlotError>;

    /// Draw into `area` (a whole image or a panel of one) with `style`.
    ///
    /// # Errors
    /// Bad data as in [`validate`](Plot::validate), an area too small to hold
    /// the plot ([`PlotError::TooSmall`]), backend failures
    /// ([`PlotError::Drawing`]).
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &Style,
    ) -> Result<(), PlotError>;

    /// Draw into a new `width × height` PNG at `path` (parent directories
    /// are created), with [`Style::for_size`]. Nothing is written if the data
    /// are bad.
    ///
    /// # Errors
    /// As [`draw`](Plot::draw), and [`render_png`]'s.
    fn save_png(&self, path: impl AsRef<Path>, width: u32, height: u32) -> Result<(), PlotError>
    where
        Self: Sized,
    {
        self.validate()?;
        let style = Style::for_size(width, height);
        render_png(path.as_ref(), width, height, |area| self.draw(area, &style))
    }
}

/// Render a PNG with a white background by calling `draw` on the whole
/// image: the building block for figures composed by hand (any plotters
/// drawing works inside; the bundled font is registered first).
///
/// # Errors
/// [`PlotError::Invalid`] if `path` does not end in `.png`,
/// [`PlotError::TooSmall`] for a side below 64 px (or above 16384 px),
/// [`PlotError::Io`] if the directory cannot be created, and whatever `draw`
/// returns. On error no file is left behind.
pub fn render_png<F>(path: &Path, width: u32, height: u32, draw: F) -> Result<(), PlotError>
where
    F: FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), PlotError>,
{
    let is_png = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !is_png {
        return Err(PlotError::Invalid {
            what: "path",
            why: format!("{} does not end in .png", path.display()),
        });
    }
    if !(MIN_SIDE..=MAX_SIDE).contains(&width) || !(MIN_SIDE..=MAX_SIDE).contains(&height) {
        return Err(PlotError::TooSmall {
            what: "image",
            width,
            height,
        });
    }
    font::ensure()?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|source| PlotError::Io {
            path: dir.to_path_buf(),
            source,
        })?;
    }
    let result = {
        let root = BitMapBackend::new(path, (width, height)).into_drawing_area();
        root.fill(&WHITE)
            .map_err(PlotError::from)
            .and_then(|()| draw(&root))
            .and_then(|()| root.present().map_err(PlotError::from))
    };
    if result.is_err() {
        // The backend writes what it has when dropped; do not leave half a
        // picture behind.
        let _ = std::fs::remove_file(path);
    }
    result
}

/// Put a title on top of `area` and return the rest.
pub(crate) fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: Option<&str>,
    px: f64,
) -> Result<DrawingArea<DB, Shift>, PlotError> {
    match title {
        Some(t) if !t.is_empty() => {
            // The ab_glyph renderer draws glyphs about a quarter of the size
            // above the top of their layout box: leave room for them.
            let room = area.margin((0.3 * px).ceil() as i32, 0, 0, 0);
            Ok(room.titled(t, (font::FAMILY, px).into_font().color(&BLACK))?)
        }
        _ => Ok(area.clone()),
    }
}

/// Pixel size of `area` after margins and label areas, or an error if
/// nothing is left.
pub(crate) fn inner_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    margin: u32,
    left: u32,
    bottom: u32,
) -> Result<(u32, u32), PlotError> {
    let (w, h) = area.dim_in_pixel();
    let iw = w.saturating_sub(2 * margin + left);
    let ih = h.saturating_sub(2 * margin + bottom);
    if iw < 16 || ih < 16 {
        return Err(PlotError::TooSmall {
            what: "plotting area",
            width: w,
            height: h,
        });
    }
    Ok((iw, ih))
}
