//! `spinball animate`: a GIF (or MP4) of balls on a table, the spin shown
//! by a rotating marker.

use std::path::PathBuf;

use clap::Args;
use spinball_analysis::animation::{DEFAULT_DURATION, DEFAULT_FPS, FrameOptions, animation_frames};
use spinball_analysis::run::Starts;
use spinball_core::{Billiard, Sampler, State};
use spinball_geometry::DVec2;
use spinball_plot::{Animation, DEFAULT_FILM_SIZE, FilmFormat};

use crate::error::CliError;
use crate::files::check_outputs;
use crate::phase_args::SceneArgs;
use crate::run_args::SamplerArg;
use crate::stdout::print;
use crate::watch::progress_bar_counting;

/// The arguments of `spinball animate`.
#[derive(Debug, Clone, Args)]
pub struct AnimateArgs {
    /// The table and α.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// How many balls, drawn as initial conditions 0..N of --seed (as an
    /// ensemble draws them).
    #[arg(long, default_value_t = 1, conflicts_with = "start")]
    pub balls: u64,
    /// An explicit start `x,y,vx,vy[,u]` (repeat for several balls)
    /// instead of drawn ones.
    #[arg(long, allow_hyphen_values = true, value_parser = parse_start)]
    pub start: Vec<State>,
    /// Seed of the drawn starts.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Sampler of the drawn starts.
    #[arg(long, value_enum, default_value_t = SamplerArg::Paper)]
    pub sampler: SamplerArg,
    /// Frames per second (a GIF takes at most 50).
    #[arg(long, default_value_t = DEFAULT_FPS, allow_negative_numbers = true)]
    pub fps: f64,
    /// Length of the film in seconds.
    #[arg(long, default_value_t = DEFAULT_DURATION, allow_negative_numbers = true)]
    pub duration: f64,
    /// Billiard time shown per second of film [default: 4 × the table's
    /// unit length, e.g. 4 for the stadium with unit caps].
    #[arg(long, allow_negative_numbers = true)]
    pub speed: Option<f64>,
    /// Drawn ball radius r in table lengths; the marker turns at ω = u/r
    /// [default: 0.1 × the table's unit length].
    #[arg(long, allow_negative_numbers = true)]
    pub radius: Option<f64>,
    /// Film size in pixels, `WIDTHxHEIGHT`.
    #[arg(long, value_parser = parse_size, default_value = "480x360")]
    pub size: (u32, u32),
    /// Title above the table [default: the table and α; "" for none].
    #[arg(long)]
    pub title: Option<String>,
    /// The film: `.gif`, or `.mp4` (needs ffmpeg on PATH).
    #[arg(long, short)]
    pub output: PathBuf,
    /// No progress bar and no summary on stdout.
    #[arg(long, short)]
    pub quiet: bool,
}

// The `--size` default above is the library's.
const _: () = assert!(DEFAULT_FILM_SIZE.0 == 480 && DEFAULT_FILM_SIZE.1 == 360);

/// Parse `--size WIDTHxHEIGHT`.
fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("{s}: give the size as WIDTHxHEIGHT in pixels, e.g. 480x360");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    Ok((
        w.trim().parse().map_err(|_| bad())?,
        h.trim().parse().map_err(|_| bad())?,
    ))
}

/// `spinball animate`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table, α, start, option or output path
/// (checked before anything runs, ffmpeg's presence for an MP4 too);
/// [`CliError::Failed`] if a step fails or the film cannot be written.
pub fn animate(args: &AnimateArgs) -> Result<(), CliError> {
    let (table, law) = args.scene.setup()?;
    let format =
        FilmFormat::of_path(&args.output).map_err(|e| CliError::Usage(format!("--output: {e}")))?;
    format
        .check(args.fps)
        .map_err(|e| CliError::Usage(format!("--output {}: {e}", args.output.display())))?;
    check_outputs(None, &[("output", Some(args.output.as_path()))])?;
    let (starts, balls) = if args.start.is_empty() {
        let sampler = match args.sampler {
            SamplerArg::Paper => Sampler::Paper,
            SamplerArg::Microcanonical => Sampler::Microcanonical,
        };
        (Starts::Sampled(sampler), args.balls)
    } else {
        let n = args.start.len() as u64;
        (Starts::States(args.start.clone()), n)
    };
    let mut options = FrameOptions::new(args.fps, args.duration);
    options.speed = args.speed;
    options.radius = args.radius;
    let title = args
        .title
        .clone()
        .unwrap_or_else(|| format!("{table}, α = {}", args.scene.alpha));
    let billiard = Billiard::new(table, law);
    let frames =
        animation_frames(&billiard, &starts, balls, args.seed, &options).map_err(|e| match e {
            spinball_analysis::AnalysisError::Step { .. } => CliError::failed(e),
            e => CliError::usage(e),
        })?;
    let film = frames.balls.iter().fold(
        Animation::new(billiard.table(), frames.fps, frames.radius).title(title),
        |film, ball| film.ball(ball.positions.iter().copied(), ball.angles.iter().copied()),
    );
    let bar = progress_bar_counting(args.quiet, "frames");
    bar.set_prefix("animate");
    let (width, height) = args.size;
    film.save(&args.output, width, height, |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    })
    .map_err(|e| match e {
        spinball_plot::PlotError::TooSmall { .. } | spinball_plot::PlotError::Invalid { .. } => {
            CliError::Usage(format!("--output {}: {e}", args.output.display()))
        }
        e => CliError::failed(e),
    })?;
    bar.finish_and_clear();
    if args.quiet {
        return Ok(());
    }
    let collisions: usize = frames.balls.iter().map(|b| b.collisions.len() - 1).sum();
    print(&format!(
        "wrote {}: {} frames at {} fps, {width}x{height} px, {} balls, {collisions} collisions in {} time units\n",
        args.output.display(),
        frames.frame_count(),
        frames.fps,
        frames.balls.len(),
        frames.time(frames.frame_count() - 1),
    ))
}

/// Parse one `--start x,y,vx,vy[,u]` (spin 0 if left out).
fn parse_start(s: &str) -> Result<State, String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("{s}: {e}; give x,y,vx,vy or x,y,vx,vy,u"))?;
    match v[..] {
        [x, y, vx, vy] => Ok(State::new(DVec2::new(x, y), DVec2::new(vx, vy), 0.0)),
        [x, y, vx, vy, u] => Ok(State::new(DVec2::new(x, y), DVec2::new(vx, vy), u)),
        _ => Err(format!(
            "{s}: {} numbers; give x,y,vx,vy or x,y,vx,vy,u",
            v.len()
        )),
    }
}
