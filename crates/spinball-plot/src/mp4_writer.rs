//! MP4 films through `ffmpeg`: raw RGB frames piped to its standard input.
//!
//! Encoding H.264 is not something to rewrite here; `ffmpeg` does it, where
//! it is installed. Where it is not, writing an MP4 is a
//! [`PlotError::FfmpegMissing`] that says to install it or write a GIF.

use std::io::{ErrorKind, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};

use crate::error::PlotError;

/// The program run to encode MP4s (looked up on `PATH`).
pub const FFMPEG: &str = "ffmpeg";

/// Whether `ffmpeg` runs (`ffmpeg -version` exits successfully).
///
/// # Errors
/// [`PlotError::FfmpegMissing`] if it does not.
pub(crate) fn check_ffmpeg() -> Result<(), PlotError> {
    let ran = Command::new(FFMPEG)
        .arg("-version")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status();
    match ran {
        Ok(status) if status.success() => Ok(()),
        _ => Err(PlotError::FfmpegMissing),
    }
}

/// An `ffmpeg` process encoding the frames it is fed into an MP4.
pub(crate) struct Mp4Writer {
    path: PathBuf,
    child: Child,
    stdin: Option<ChildStdin>,
}

impl Mp4Writer {
    /// Start `ffmpeg` writing `path` (replaced if it exists) from
    /// `width × height` RGB frames at `fps`.
    pub(crate) fn spawn(path: &Path, width: u32, height: u32, fps: f64) -> Result<Self, PlotError> {
        let mut child = Command::new(FFMPEG)
            .args(["-hide_banner", "-loglevel", "error", "-y"])
            .args(["-f", "rawvideo", "-pixel_format", "rgb24"])
            .args(["-video_size", &format!("{width}x{height}")])
            .args(["-framerate", &format!("{fps}")])
            .args(["-i", "pipe:0"])
            // H.264 in yuv420p (what every player plays) needs even sides.
            .args(["-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white"])
            .args(["-pix_fmt", "yuv420p", "-movflags", "+faststart"])
            .arg(path)
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| match e.kind() {
                ErrorKind::NotFound => PlotError::FfmpegMissing,
                _ => PlotError::Encoding {
                    path: path.to_path_buf(),
                    why: format!("cannot start {FFMPEG}: {e}"),
                },
            })?;
        let stdin = child.stdin.take();
        Ok(Mp4Writer {
            path: path.to_path_buf(),
            child,
            stdin,
        })
    }

    /// Feed one frame (RGB, rows from the top).
    pub(crate) fn push(&mut self, rgb: &[u8]) -> Result<(), PlotError> {
        let written = match &mut self.stdin {
            Some(stdin) => stdin.write_all(rgb),
            None => Err(std::io::Error::from(ErrorKind::BrokenPipe)),
        };
        written.map_err(|e| {
            // ffmpeg stopped reading: what it said is the reason.
            self.stdin = None;
            let said = self.stderr_text();
            PlotError::Encoding {
                path: self.path.clone(),
                why: format!("{FFMPEG} stopped taking frames ({e}): {said}"),
            }
        })
    }

    /// Close the input and wait for `ffmpeg` to write the file.
    pub(crate) fn finish(mut self) -> Result<(), PlotError> {
        drop(self.stdin.take());
        let status = self.child.wait().map_err(|source| PlotError::Io {
            path: self.path.clone(),
            source,
        })?;
        if status.success() {
            Ok(())
        } else {
            Err(PlotError::Encoding {
                path: self.path.clone(),
                why: format!("{FFMPEG} failed ({status}): {}", self.stderr_text()),
            })
        }
    }

    /// Stop `ffmpeg` without a file (the film could not be drawn).
    pub(crate) fn abandon(mut self) {
        drop(self.stdin.take());
        let _ = self.child.kill();
        let _ = self.child.wait();
    }

    fn stderr_text(&mut self) -> String {
        let _ = self.child.wait();
        let mut text = String::new();
        if let Some(mut err) = self.child.stderr.take() {
            let _ = std::io::Read::read_to_string(&mut err, &mut text);
        }
        let text = text.trim();
        if text.is_empty() {
            "no message".to_owned()
        } else {
            text.to_owned()
        }
    }
}
