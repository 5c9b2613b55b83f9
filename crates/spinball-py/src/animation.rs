//! Films from Python: `spinball.animate` writes a GIF (or MP4) of balls on
//! a table through the same library code as `spinball animate`
//! (`spinball_analysis::animation` for the frames, `spinball_plot::Animation`
//! for the file), and returns the frames as NumPy arrays.

use numpy::IntoPyArray;
use numpy::ndarray::{Array2, Array3};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use spinball_analysis::animation::{DEFAULT_DURATION, DEFAULT_FPS, FrameOptions, animation_frames};
use spinball_analysis::run::Starts;
use spinball_core::Billiard;
use spinball_plot::{Animation, DEFAULT_FILM_SIZE, PlotError};

use crate::args::{self, count};
use crate::errors::{analysis, guarded, value_error};
use crate::tables::table_arg;
use crate::with_table;

// The signature writes the defaults as literals so that `help()` shows them.
const _: () = assert!(DEFAULT_FPS == 20.0 && DEFAULT_DURATION == 6.0);
const _: () = assert!(DEFAULT_FILM_SIZE.0 == 480 && DEFAULT_FILM_SIZE.1 == 360);

/// A film's error as a Python exception: bad input as `ValueError`, an
/// MP4 without ffmpeg or a file that cannot be written as `RuntimeError`.
fn film_error(e: PlotError) -> PyErr {
    match e {
        PlotError::Invalid { .. }
        | PlotError::TooSmall { .. }
        | PlotError::EmptyData(_)
        | PlotError::LengthMismatch { .. } => value_error(e.to_string()),
        other => PyRuntimeError::new_err(other.to_string()),
    }
}

/// Either error of a film: its frames, or its file.
enum FilmFailure {
    Frames(spinball_analysis::AnalysisError),
    File(PlotError),
}

/// Write a film of balls on `table` at spin `alpha` to `path` (`.gif`, or
/// `.mp4` where ffmpeg is on PATH) and return its frames; see the stub
/// (`_spinball.pyi`) for the arguments and the returned dict.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, path, *, balls = 1, initial_states = None, seed = 1, sampler = None,
    fps = 20.0, duration = 6.0, speed = None, radius = None, size = (480, 360),
    title = None, extended = false
))]
#[allow(clippy::too_many_arguments)]
pub fn animate<'py>(
    py: Python<'py>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    path: std::path::PathBuf,
    balls: i64,
    initial_states: Option<&Bound<'_, PyAny>>,
    seed: u64,
    sampler: Option<&str>,
    fps: f64,
    duration: f64,
    speed: Option<f64>,
    radius: Option<f64>,
    size: (u32, u32),
    title: Option<String>,
    extended: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let (starts, balls) = match initial_states {
        Some(obj) => {
            let states = args::states(obj)?;
            let n = states.len() as u64;
            (Starts::States(states), n)
        }
        None => (
            Starts::Sampled(args::sampler(sampler)?),
            count("balls", balls, 1)?,
        ),
    };
    let options = FrameOptions {
        speed,
        radius,
        ..FrameOptions::new(fps, duration)
    };
    let title = title.unwrap_or_else(|| format!("{}, α = {alpha}", table.spec()));
    let frames = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| {
                    let billiard = Billiard::new(t, law);
                    let frames = animation_frames(&billiard, &starts, balls, seed, &options)
                        .map_err(FilmFailure::Frames)?;
                    let film = frames.balls.iter().fold(
                        Animation::new(billiard.table(), frames.fps, frames.radius).title(title),
                        |film, b| film.ball(b.positions.iter().copied(), b.angles.iter().copied()),
                    );
                    film.save(&path, size.0, size.1, |_, _| {})
                        .map_err(FilmFailure::File)?;
                    Ok::<_, FilmFailure>(frames)
                })
            },
            |e| match e {
                FilmFailure::Frames(e) => analysis(e),
                FilmFailure::File(e) => film_error(e),
            },
        )
    })?;
    let (n_balls, n_frames) = (frames.balls.len(), frames.frame_count());
    let positions: Vec<f64> = frames
        .balls
        .iter()
        .flat_map(|b| b.positions.iter().flat_map(|p| [p.x, p.y]))
        .collect();
    let shape_error = |e: numpy::ndarray::ShapeError| PyRuntimeError::new_err(e.to_string());
    let per_frame =
        |values: Vec<f64>| Array2::from_shape_vec((n_balls, n_frames), values).map_err(shape_error);
    let angles = per_frame(frames.balls.iter().flat_map(|b| b.angles.clone()).collect())?;
    let spins = per_frame(frames.balls.iter().flat_map(|b| b.spins.clone()).collect())?;
    let times: Vec<f64> = (0..n_frames).map(|k| frames.time(k)).collect();
    let out = PyDict::new(py);
    out.set_item("path", path)?;
    out.set_item("times", times.into_pyarray(py))?;
    out.set_item(
        "positions",
        Array3::from_shape_vec((n_balls, n_frames, 2), positions)
            .map_err(shape_error)?
            .into_pyarray(py),
    )?;
    out.set_item("angles", angles.into_pyarray(py))?;
    out.set_item("spins", spins.into_pyarray(py))?;
    let collisions: Vec<i64> = frames
        .balls
        .iter()
        .map(|b| b.collisions.len() as i64 - 1)
        .collect();
    out.set_item("collisions", collisions.into_pyarray(py))?;
    out.set_item("fps", frames.fps)?;
    out.set_item("speed", frames.speed)?;
    out.set_item("radius", frames.radius)?;
    Ok(out)
}
