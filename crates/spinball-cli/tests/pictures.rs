//! `--png` on `lyapunov`, `ftle`, `trajectory`, `section` and `ftle-map`:
//! each writes a PNG of the promised 1200 × 800 px with a picture in it
//! (many colours: markers, bars, a colour map), and refuses an unwritable
//! path before the run.

mod common;

use std::collections::HashSet;
use std::path::Path;

use common::{ok, scratch, spinball};

/// Width, height and the number of distinct colours of the PNG at `path`.
fn decode(path: &Path) -> (u32, u32, usize) {
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .expect("a PNG");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("one frame");
    let samples = info.color_type.samples();
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    let colours: HashSet<&[u8]> = buf[..info.buffer_size()].chunks(samples).collect();
    (info.width, info.height, colours.len())
}

/// A picture of the size promised with at least `colours` colours.
fn assert_picture(path: &Path, colours: usize) {
    let (w, h, n) = decode(path);
    assert_eq!((w, h), (1200, 800), "{}", path.display());
    assert!(
        n >= colours,
        "{}: {n} colours, expected at least {colours}",
        path.display()
    );
}

/// `command --table stadium:a=1 --alpha ALPHA` then `rest`.
fn run(command: &str, alpha: &str, rest: &[&str]) -> Vec<String> {
    [command, "--table", "stadium:a=1", "--alpha", alpha]
        .iter()
        .chain(rest)
        .map(|s| (*s).to_string())
        .collect()
}

/// Run `args` with `--png path` added, and check it succeeded.
fn draw(mut args: Vec<String>, path: &Path) -> std::process::Output {
    args.extend(["--png".to_string(), path.display().to_string()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    ok(&args)
}

#[test]
fn lyapunov_draws_lambda_of_alpha() {
    let png = scratch("png-lyapunov").join("lambda.png");
    let rest = ["--ics", "8", "--collisions", "300", "--quiet"];
    draw(run("lyapunov", "0,0.5,1", &rest), &png);
    assert_picture(&png, 8);
}

#[test]
fn ftle_draws_one_histogram_per_alpha() {
    let dir = scratch("png-ftle");
    let mut args = run("ftle", "0,0.5", &["--ics", "16", "--collisions", "300"]);
    args[2] = "sinai:L=2,R=1".into();
    args.push("--quiet".into());
    draw(args, &dir.join("h.png"));
    for name in ["h.alpha-0.png", "h.alpha-0.5.png"] {
        assert_picture(&dir.join(name), 8);
    }
}

#[test]
fn trajectory_draws_the_path_coloured_by_spin() {
    let png = scratch("png-trajectory").join("t.png");
    let out = draw(run("trajectory", "0.5", &["--collisions", "60"]), &png);
    assert!(out.stdout.is_empty(), "--png alone prints no CSV");
    // Viridis legs and the colour bar: many colours.
    assert_picture(&png, 30);
}

#[test]
fn section_draws_points_coloured_by_spin() {
    let png = scratch("png-section").join("s.png");
    let rest = ["--orbits", "4", "--collisions", "200", "--quiet"];
    draw(run("section", "0.5", &rest), &png);
    assert_picture(&png, 30);
}

#[test]
fn ftle_map_draws_an_image() {
    let png = scratch("png-map").join("m.png");
    let rest = [
        "--columns",
        "12",
        "--rows",
        "8",
        "--collisions",
        "100",
        "--quiet",
    ];
    draw(run("ftle-map", "0.5", &rest), &png);
    assert_picture(&png, 30);
}

#[test]
fn an_unwritable_png_is_refused_before_the_run() {
    let dir = scratch("png-refused");
    let refused = |command: &str, png: &Path, why: &str| {
        let mut args = run(command, "0.5", &["--png"]);
        args.push(png.display().to_string());
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = spinball(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("--png") && err.contains(why), "{err}");
    };
    let missing = dir.join("no-such-dir").join("x.png");
    for command in ["lyapunov", "ftle", "trajectory", "section", "ftle-map"] {
        refused(command, &missing, "does not exist");
    }
    // A directory in the way, and a name that is not a PNG's.
    let in_the_way = dir.join("d.png");
    std::fs::create_dir(&in_the_way).unwrap();
    refused("ftle", &in_the_way, "is a directory");
    refused("section", &dir.join("s.jpg"), "must end in .png");
}
