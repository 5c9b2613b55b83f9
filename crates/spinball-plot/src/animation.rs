//! A film of balls on a table, each drawn as a disk with a rotating marker,
//! written as a GIF (always) or an MP4 (where `ffmpeg` is installed).
//!
//! The positions and spin angles come from the caller (in spinball, from
//! `spinball_analysis::animation`, which samples the exact dynamics at the
//! frame times); this module only draws them. The table is drawn once, with
//! the same outline and fills as [`TablePlot`](crate::TablePlot); each frame
//! is that background with the balls on top.

use std::path::Path;

use glam::DVec2;
use plotters::prelude::*;

use crate::colormap::PALETTE;
use crate::error::PlotError;
use crate::font;
use crate::gif_writer::GifWriter;
use crate::mp4_writer::Mp4Writer;
use crate::plot::{MAX_SIDE, MIN_SIDE, titled};
use crate::style::Style;
use crate::table_plot::{draw_walls, table_chart};
use spinball_geometry::{Outline, ToOutline};

/// The file kinds a film is written as, told by the path's extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FilmFormat {
    /// An animated GIF (`.gif`): written by this crate, one global
    /// 256-colour palette, frame delays in whole hundredths of a second.
    Gif,
    /// An H.264 MP4 (`.mp4`): raw frames piped to `ffmpeg`, which must be
    /// on `PATH`.
    Mp4,
}

impl FilmFormat {
    /// The format of `path` (`.gif` or `.mp4`, any case).
    ///
    /// # Errors
    /// [`PlotError::Invalid`] for any other extension.
    pub fn of_path(path: &Path) -> Result<FilmFormat, PlotError> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("gif") => Ok(FilmFormat::Gif),
            Some("mp4") => Ok(FilmFormat::Mp4),
            _ => Err(PlotError::Invalid {
                what: "path",
                why: format!("{} does not end in .gif or .mp4", path.display()),
            }),
        }
    }

    /// Check, before anything is computed, that a film at `fps` can be
    /// written in this format: a GIF at most [`MAX_GIF_FPS`] frames per
    /// second, an MP4 with `ffmpeg` on `PATH`.
    ///
    /// # Errors
    /// [`PlotError::Invalid`] for a GIF faster than [`MAX_GIF_FPS`];
    /// [`PlotError::FfmpegMissing`] for an MP4 without `ffmpeg`.
    pub fn check(self, fps: f64) -> Result<(), PlotError> {
        match self {
            FilmFormat::Gif if fps > MAX_GIF_FPS => Err(PlotError::Invalid {
                what: "fps",
                why: format!(
                    "{fps} frames per second: a GIF's frame delays are whole hundredths of a \
                     second and players slow those under 2/100 s down; give at most \
                     {MAX_GIF_FPS} fps for a GIF, or write an .mp4"
                ),
            }),
            FilmFormat::Gif => Ok(()),
            FilmFormat::Mp4 => crate::mp4_writer::check_ffmpeg(),
        }
    }
}

/// Default size of a film in pixels, `(width, height)`.
pub const DEFAULT_FILM_SIZE: (u32, u32) = (480, 360);

/// Highest frame rate a GIF can show: its delays are whole hundredths of a
/// second, and players slow delays below two hundredths down.
pub const MAX_GIF_FPS: f64 = 50.0;

/// One filmed ball.
#[derive(Debug, Clone, PartialEq)]
struct FilmBall {
    positions: Vec<DVec2>,
    angles: Vec<f64>,
}

/// A film: balls moving on a table, drawn as disks of radius `radius` (in
/// table lengths, at least 3 px) in the colours of [`PALETTE`], each with a
/// white marker from the centre to the rim at its spin angle
/// (counter-clockwise from `+x`, as on the table).
///
/// ```no_run
/// use spinball_geometry::{DVec2, Stadium};
/// use spinball_plot::Animation;
///
/// let positions: Vec<DVec2> = (0..50).map(|k| DVec2::new(-1.5 + 0.06 * k as f64, 0.2)).collect();
/// let angles: Vec<f64> = (0..50).map(|k| 0.3 * k as f64).collect();
/// Animation::new(&Stadium::new(1.0)?, 10.0, 0.1)
///     .title("stadium, α = 0.5")
///     .ball(positions, angles)
///     .save("out/film.gif", 360, 220, |_, _| {})?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
#[must_use]
pub struct Animation {
    outline: Outline,
    fps: f64,
    radius: f64,
    title: Option<String>,
    balls: Vec<FilmBall>,
}

impl Animation {
    /// A film of `table` at `fps` frames per second, balls of radius
    /// `radius` (table lengths).
    pub fn new(table: &impl ToOutline, fps: f64, radius: f64) -> Self {
        Animation {
            outline: table.outline(),
            fps,
            radius,
            title: None,
            balls: Vec::new(),
        }
    }

    /// A title above the table.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// One more ball: its centre and spin angle (radians) at each frame.
    pub fn ball(
        mut self,
        positions: impl IntoIterator<Item = DVec2>,
        angles: impl IntoIterator<Item = f64>,
    ) -> Self {
        self.balls.push(FilmBall {
            positions: positions.into_iter().collect(),
            angles: angles.into_iter().collect(),
        });
        self
    }

    /// The number of frames (of the first ball; [`validate`](Self::validate)
    /// checks they agree).
    #[must_use]
    pub fn frame_count(&self) -> usize {
        self.balls.first().map_or(0, |b| b.positions.len())
    }

    /// Check the film without drawing it.
    ///
    /// # Errors
    /// [`PlotError::EmptyData`] for no ball or no frame;
    /// [`PlotError::LengthMismatch`] for balls with different frame counts
    /// or angles that do not match the positions; [`PlotError::Invalid`]
    /// for a frame rate or radius that is not positive and finite, or a
    /// non-finite position or angle.
    pub fn validate(&self) -> Result<(), PlotError> {
        for (what, v) in [("fps", self.fps), ("radius", self.radius)] {
            if !(v > 0.0 && v.is_finite()) {
                return Err(PlotError::Invalid {
                    what,
                    why: format!("{v}; give a positive, finite value"),
                });
            }
        }
        let n = self.frame_count();
        if n == 0 {
            return Err(PlotError::EmptyData("film (no ball or no frame)".into()));
        }
        for (i, b) in self.balls.iter().enumerate() {
            for (what, got) in [("positions", b.positions.len()), ("angles", b.angles.len())] {
                if got != n {
                    return Err(PlotError::LengthMismatch {
                        what: format!("{what} of ball {i}"),
                        expected: n,
                        got,
                    });
                }
            }
            if !(b.positions.iter().all(|p| p.is_finite())
                && b.angles.iter().all(|a| a.is_finite()))
            {
                return Err(PlotError::Invalid {
                    what: "ball",
                    why: format!("ball {i} has a non-finite position or angle"),
                });
            }
        }
        Ok(())
    }

    /// Draw every frame as `width × height` RGB pixels (`[r, g, b, ...]`,
    /// rows from the top) and hand it to `each` with its index.
    ///
    /// # Errors
    /// As [`validate`](Self::validate), [`PlotError::TooSmall`] for a side
    /// outside 64–16384 px, drawing failures, and whatever `each` returns.
    pub fn render<F>(&self, width: u32, height: u32, mut each: F) -> Result<(), PlotError>
    where
        F: FnMut(usize, &[u8]) -> Result<(), PlotError>,
    {
        self.validate()?;
        if !(MIN_SIDE..=MAX_SIDE).contains(&width) || !(MIN_SIDE..=MAX_SIDE).contains(&height) {
            return Err(PlotError::TooSmall {
                what: "film",
                width,
                height,
            });
        }
        font::ensure()?;
        let style = Style::for_size(width, height);
        let (background, to_pixel) = self.background(width, height, &style)?;
        let ball_px = (self.radius * to_pixel.scale).max(3.0);
        let marker = ((ball_px / 4.0).round() as u32).clamp(1, 4);
        let mut frame = background.clone();
        for k in 0..self.frame_count() {
            frame.copy_from_slice(&background);
            {
                let root =
                    BitMapBackend::with_buffer(&mut frame, (width, height)).into_drawing_area();
                for (i, b) in self.balls.iter().enumerate() {
                    let colour = PALETTE[i % PALETTE.len()];
                    let c = to_pixel.apply(b.positions[k]);
                    let centre = (c.x.round() as i32, c.y.round() as i32);
                    root.draw(&Circle::new(
                        centre,
                        ball_px.round() as i32,
                        colour.filled(),
                    ))?;
                    // Screen y runs down: counter-clockwise on the table is
                    // counter-clockwise on the screen.
                    let rim = c + 0.9 * ball_px * DVec2::new(b.angles[k].cos(), -b.angles[k].sin());
                    root.draw(&PathElement::new(
                        vec![centre, (rim.x.round() as i32, rim.y.round() as i32)],
                        WHITE.stroke_width(marker),
                    ))?;
                }
                root.present()?;
            }
            each(k, &frame)?;
        }
        Ok(())
    }

    /// The table without balls, and the map from table to pixel coordinates.
    fn background(
        &self,
        width: u32,
        height: u32,
        style: &Style,
    ) -> Result<(Vec<u8>, PixelMap), PlotError> {
        let mut buf = vec![0u8; 3 * width as usize * height as usize];
        let map = {
            let root = BitMapBackend::with_buffer(&mut buf, (width, height)).into_drawing_area();
            root.fill(&WHITE)?;
            let area = titled(&root, self.title.as_deref(), style.title_px)?;
            // Room for a ball touching a wall: its centre is on the wall.
            let r = DVec2::splat(self.radius);
            let also = self
                .outline
                .bounds()
                .into_iter()
                .flat_map(|(lo, hi)| [lo - r, hi + r]);
            let mut chart = table_chart(&area, &self.outline, also, false, style)?;
            draw_walls(&mut chart, &self.outline, style)?;
            let pixel = |x: f64, y: f64| {
                let (px, py) = chart.backend_coord(&(x, y));
                DVec2::new(f64::from(px), f64::from(py))
            };
            // Equal aspect: one scale for both axes, measured over a long
            // span so that pixel rounding does not matter.
            let (lo, hi) = self.outline.bounds().unwrap_or((DVec2::ZERO, DVec2::ONE));
            let span = (hi.x - lo.x).max(f64::MIN_POSITIVE);
            let scale = (pixel(hi.x, lo.y).x - pixel(lo.x, lo.y).x) / span;
            let origin = pixel(lo.x, lo.y) - DVec2::new(scale * lo.x, -scale * lo.y);
            root.present()?;
            PixelMap { origin, scale }
        };
        Ok((buf, map))
    }

    /// Write the film to `path`, a GIF or an MP4 by its extension (parent
    /// directories are created), `progress(done, total)` after each frame.
    /// On error no file is left behind.
    ///
    /// # Errors
    /// As [`render`](Self::render); [`PlotError::Invalid`] for another
    /// extension, or a GIF faster than [`MAX_GIF_FPS`];
    /// [`PlotError::FfmpegMissing`] for an MP4 without `ffmpeg`;
    /// [`PlotError::Io`] and [`PlotError::Encoding`] for a file that cannot
    /// be written.
    pub fn save<P: FnMut(usize, usize)>(
        &self,
        path: impl AsRef<Path>,
        width: u32,
        height: u32,
        mut progress: P,
    ) -> Result<(), PlotError> {
        let path = path.as_ref();
        let format = FilmFormat::of_path(path)?;
        self.validate()?;
        format.check(self.fps)?;
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|source| PlotError::Io {
                path: dir.to_path_buf(),
                source,
            })?;
        }
        let total = self.frame_count();
        let result = match format {
            FilmFormat::Gif => {
                let mut gif = GifWriter::create(path, width, height, self.fps)?;
                self.render(width, height, |k, rgb| {
                    gif.push(rgb)?;
                    progress(k + 1, total);
                    Ok(())
                })
                .and_then(|()| gif.finish())
            }
            FilmFormat::Mp4 => {
                let mut mp4 = Mp4Writer::spawn(path, width, height, self.fps)?;
                let drawn = self.render(width, height, |k, rgb| {
                    mp4.push(rgb)?;
                    progress(k + 1, total);
                    Ok(())
                });
                match drawn {
                    Ok(()) => mp4.finish(),
                    Err(e) => {
                        mp4.abandon();
                        Err(e)
                    }
                }
            }
        };
        if result.is_err() {
            let _ = std::fs::remove_file(path);
        }
        result
    }
}

/// Table coordinates to pixel coordinates (y down), equal aspect.
#[derive(Debug, Clone, Copy)]
struct PixelMap {
    origin: DVec2,
    scale: f64,
}

impl PixelMap {
    fn apply(self, p: DVec2) -> DVec2 {
        self.origin + self.scale * DVec2::new(p.x, -p.y)
    }
}
