//! Animated GIFs: frames quantised to one fixed palette, each stored as the
//! smallest rectangle that changed since the frame before.
//!
//! A billiard film changes little from frame to frame (a few balls move on
//! a still table), so after the first frame only the rectangle around what
//! changed is written, over the frame before (disposal "keep"): a few
//! hundred bytes a frame instead of the whole picture.

use std::borrow::Cow;
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use gif::{DisposalMethod, Encoder, Frame, Repeat};

use crate::error::PlotError;
use crate::fixed_palette::FixedPalette;

/// Writes the frames of one film to a GIF file, looping forever.
pub(crate) struct GifWriter {
    path: PathBuf,
    encoder: Encoder<BufWriter<File>>,
    width: u16,
    height: u16,
    delay: u16,
    previous: Option<Vec<u8>>,
    current: Vec<u8>,
}

/// The delay between frames at `fps`, in hundredths of a second (at least
/// 1): what a GIF can store.
pub(crate) fn gif_delay(fps: f64) -> u16 {
    (100.0 / fps).round().clamp(1.0, f64::from(u16::MAX)) as u16
}

impl GifWriter {
    /// A new GIF of `width × height` at `path`, frames `1/fps` apart
    /// (rounded to hundredths of a second).
    pub(crate) fn create(
        path: &Path,
        width: u32,
        height: u32,
        fps: f64,
    ) -> Result<Self, PlotError> {
        let side = |v: u32| {
            u16::try_from(v).map_err(|_| PlotError::TooSmall {
                what: "GIF (sides up to 65535 px)",
                width,
                height,
            })
        };
        let (w, h) = (side(width)?, side(height)?);
        let io = |source| PlotError::Io {
            path: path.to_path_buf(),
            source,
        };
        let file = File::create(path).map_err(io)?;
        let mut encoder = Encoder::new(BufWriter::new(file), w, h, FixedPalette::get().rgb())
            .map_err(|e| encoding(path, &e))?;
        encoder
            .set_repeat(Repeat::Infinite)
            .map_err(|e| encoding(path, &e))?;
        Ok(GifWriter {
            path: path.to_path_buf(),
            encoder,
            width: w,
            height: h,
            delay: gif_delay(fps),
            previous: None,
            current: Vec::new(),
        })
    }

    /// Add one frame: RGB pixels, rows from the top.
    pub(crate) fn push(&mut self, rgb: &[u8]) -> Result<(), PlotError> {
        let (w, h) = (usize::from(self.width), usize::from(self.height));
        if rgb.len() != 3 * w * h {
            return Err(PlotError::LengthMismatch {
                what: "frame bytes".into(),
                expected: 3 * w * h,
                got: rgb.len(),
            });
        }
        FixedPalette::get().quantise(rgb, &mut self.current);
        let (left, top, cw, ch) = match &self.previous {
            None => (0, 0, w, h),
            Some(prev) => changed_rect(prev, &self.current, w, h),
        };
        let mut buffer = Vec::with_capacity(cw * ch);
        for y in top..top + ch {
            buffer.extend_from_slice(&self.current[y * w + left..y * w + left + cw]);
        }
        let frame = Frame {
            delay: self.delay,
            dispose: DisposalMethod::Keep,
            left: left as u16,
            top: top as u16,
            width: cw as u16,
            height: ch as u16,
            buffer: Cow::Owned(buffer),
            ..Frame::default()
        };
        self.encoder
            .write_frame(&frame)
            .map_err(|e| encoding(&self.path, &e))?;
        match &mut self.previous {
            Some(prev) => std::mem::swap(prev, &mut self.current),
            None => self.previous = Some(std::mem::take(&mut self.current)),
        }
        Ok(())
    }

    /// Write the trailer and flush the file.
    pub(crate) fn finish(self) -> Result<(), PlotError> {
        let path = self.path;
        let mut out = self.encoder.into_inner().map_err(|e| encoding(&path, &e))?;
        std::io::Write::flush(&mut out).map_err(|source| PlotError::Io { path, source })
    }
}

fn encoding(path: &Path, e: &gif::EncodingError) -> PlotError {
    PlotError::Encoding {
        path: path.to_path_buf(),
        why: e.to_string(),
    }
}

/// The smallest rectangle `(left, top, width, height)` holding every pixel
/// that differs between `a` and `b` (`w × h` images); one pixel if none
/// does (a GIF frame cannot be empty, and it still carries the delay).
fn changed_rect(a: &[u8], b: &[u8], w: usize, h: usize) -> (usize, usize, usize, usize) {
    let (mut x0, mut y0, mut x1, mut y1) = (w, h, 0, 0);
    for y in 0..h {
        let (ra, rb) = (&a[y * w..(y + 1) * w], &b[y * w..(y + 1) * w]);
        if ra == rb {
            continue;
        }
        let first = ra.iter().zip(rb).position(|(p, q)| p != q).unwrap_or(0);
        let last = w
            - 1
            - ra.iter()
                .rev()
                .zip(rb.iter().rev())
                .position(|(p, q)| p != q)
                .unwrap_or(0);
        x0 = x0.min(first);
        x1 = x1.max(last);
        y0 = y0.min(y);
        y1 = y;
    }
    if x0 > x1 {
        return (0, 0, 1, 1);
    }
    (x0, y0, x1 - x0 + 1, y1 - y0 + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn changed_rect_is_tight() {
        let (w, h) = (6, 5);
        let a = vec![0u8; w * h];
        let mut b = a.clone();
        assert_eq!(changed_rect(&a, &b, w, h), (0, 0, 1, 1));
        b[w + 2] = 1;
        b[3 * w + 4] = 2;
        assert_eq!(changed_rect(&a, &b, w, h), (2, 1, 3, 3));
    }

    #[test]
    fn delays_are_whole_hundredths() {
        assert_eq!(gif_delay(10.0), 10);
        assert_eq!(gif_delay(30.0), 3);
        assert_eq!(gif_delay(50.0), 2);
        assert_eq!(gif_delay(0.5), 200);
    }
}
