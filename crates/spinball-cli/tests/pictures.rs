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

#[test]
fn lyapunov_draws_lambda_of_alpha() {
    let dir = scratch("png-lyapunov");
    let png = dir.join("lambda.png");
    ok(&[
        "lyapunov",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0,0.5,1",
        "--ics",
        "8",
        "--collisions",
        "300",
        "--quiet",
        "--png",
        png.to_str().unwrap(),
    ]);
    assert_picture(&png, 8);
}

#[test]
fn ftle_draws_one_histogram_per_alpha() {
    let dir = scratch("png-ftle");
    let png = dir.join("h.png");
    ok(&[
        "ftle",
        "--table",
        "sinai:L=2,R=1",
        "--alpha",
        "0,0.5",
        "--ics",
        "16",
        "--collisions",
        "300",
        "--quiet",
        "--png",
        png.to_str().unwrap(),
    ]);
    for name in ["h.alpha-0.png", "h.alpha-0.5.png"] {
        assert_picture(&dir.join(name), 8);
    }
}

#[test]
fn trajectory_draws_the_path_coloured_by_spin() {
    let dir = scratch("png-trajectory");
    let png = dir.join("t.png");
    let out = ok(&[
        "trajectory",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--collisions",
        "60",
        "--png",
        png.to_str().unwrap(),
    ]);
    assert!(out.stdout.is_empty(), "--png alone prints no CSV");
    // Viridis legs and the colour bar: many colours.
    assert_picture(&png, 30);
}

#[test]
fn section_draws_points_coloured_by_spin() {
    let dir = scratch("png-section");
    let png = dir.join("s.png");
    ok(&[
        "section",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--orbits",
        "4",
        "--collisions",
        "200",
        "--quiet",
        "--png",
        png.to_str().unwrap(),
    ]);
    assert_picture(&png, 30);
}

#[test]
fn ftle_map_draws_an_image() {
    let dir = scratch("png-map");
    let png = dir.join("m.png");
    ok(&[
        "ftle-map",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--columns",
        "12",
        "--rows",
        "8",
        "--collisions",
        "100",
        "--quiet",
        "--png",
        png.to_str().unwrap(),
    ]);
    assert_picture(&png, 30);
}

#[test]
fn an_unwritable_png_is_refused_before_the_run() {
    let dir = scratch("png-refused");
    let missing = dir.join("no-such-dir").join("x.png");
    let m = missing.to_str().unwrap();
    let runs: [&[&str]; 4] = [
        &[
            "lyapunov",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--png",
            m,
        ],
        &[
            "trajectory",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--png",
            m,
        ],
        &[
            "section",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--png",
            m,
        ],
        &[
            "ftle-map",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--png",
            m,
        ],
    ];
    for args in runs {
        let out = spinball(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains("--png") && err.contains("does not exist"),
            "{err}"
        );
    }
    // A directory in the way is refused too.
    let out = spinball(&[
        "ftle",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--png",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    // So is a name that is not a PNG's.
    let out = spinball(&[
        "section",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--png",
        dir.join("s.jpg").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("must end in .png"));
}
