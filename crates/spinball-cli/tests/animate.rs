//! `spinball animate` end to end: the GIF it writes decodes to the frames,
//! size and delay asked for; explicit starts; bad input is exit code 2
//! before anything is computed.

mod common;
use common::{ok, scratch, spinball};

use std::io::Write;
use std::path::Path;

/// Screen size, frame count and delays of a GIF (the `gif` crate's decoder).
fn gif_shape(path: &Path) -> ((u16, u16), usize, Vec<u16>) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options
        .read_info(std::fs::File::open(path).unwrap())
        .unwrap();
    let size = (decoder.width(), decoder.height());
    let mut delays = Vec::new();
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        delays.push(frame.delay);
    }
    (size, delays.len(), delays)
}

fn refused(args: &[&str], words: &[&str]) {
    let out = spinball(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    for w in words {
        assert!(err.contains(w), "{args:?}: `{w}` not in: {err}");
    }
}

#[test]
fn a_gif_of_drawn_balls_has_the_frames_size_and_delay_asked_for() {
    let dir = scratch("animate");
    let path = dir.join("stadium.gif");
    const FILM: [&str; 13] = [
        "animate",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--balls",
        "3",
        "--fps",
        "10",
        "--duration",
        "1.5",
        "--size",
        "200x150",
    ];
    let out = ok(&[FILM.as_slice(), &["-o", path.to_str().unwrap()]].concat());
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        said.contains("15 frames at 10 fps") && said.contains("3 balls"),
        "{said}"
    );
    let (size, frames, delays) = gif_shape(&path);
    assert_eq!((size, frames), ((200, 150), 15));
    assert!(delays.iter().all(|&d| d == 10), "{delays:?}");
    // The same seed gives the same film, byte for byte.
    let again = dir.join("again.gif");
    ok(&[FILM.as_slice(), &["--quiet", "-o", again.to_str().unwrap()]].concat());
    assert_eq!(
        std::fs::read(&path).unwrap(),
        std::fs::read(&again).unwrap()
    );
}

#[test]
fn explicit_starts_are_one_ball_each() {
    let dir = scratch("animate-starts");
    let path = dir.join("sinai.gif");
    let out = ok(&[
        "animate",
        "--table",
        "sinai:L=2,R=1",
        "--alpha",
        "0.4",
        "--start",
        "-1.5,-1.5,0.6,0.8,0.3",
        "--start",
        "1.5,1.5,-0.8,0.6",
        "--fps",
        "8",
        "--duration",
        "1",
        "--speed",
        "2",
        "--radius",
        "0.2",
        "--title",
        "",
        "-o",
        path.to_str().unwrap(),
    ]);
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        said.contains("8 frames") && said.contains("2 balls"),
        "{said}"
    );
    assert_eq!(gif_shape(&path).1, 8);
}

#[test]
fn bad_films_are_refused_before_the_run() {
    let dir = scratch("animate-bad");
    let gif = dir.join("x.gif");
    let g = gif.to_str().unwrap();
    let base = ["animate", "--table", "stadium:a=1", "--alpha", "0.5"];
    fn with<'a>(base: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
        [base, extra].concat()
    }
    let missing = dir.join("no/such/dir/x.gif");
    refused(
        &with(&base, &["-o", missing.to_str().unwrap()]),
        &["--output", "does not exist"],
    );
    refused(
        &with(&base, &["-o", dir.join("x.png").to_str().unwrap()]),
        &[".gif or .mp4"],
    );
    refused(
        &with(&base, &["--fps", "60", "-o", g]),
        &["at most 50 fps", ".mp4"],
    );
    refused(&with(&base, &["--fps", "0", "-o", g]), &["fps"]);
    refused(&with(&base, &["--duration", "-1", "-o", g]), &["duration"]);
    refused(&with(&base, &["--radius", "0", "-o", g]), &["radius"]);
    refused(&with(&base, &["--balls", "0", "-o", g]), &["balls"]);
    refused(&with(&base, &["--start", "5,0,1,0", "-o", g]), &["outside"]);
    refused(&with(&base, &["--start", "0,0,1", "-o", g]), &["x,y,vx,vy"]);
    refused(&with(&base, &["--size", "20x20", "-o", g]), &["too small"]);
    refused(&with(&base, &["--size", "big", "-o", g]), &["WIDTHxHEIGHT"]);
    refused(
        &["animate", "--table", "stadium:a=1", "--alpha", "2", "-o", g],
        &["--alpha"],
    );
    assert!(!gif.exists(), "nothing written");
    // An MP4 needs ffmpeg: without it, the message says what to do.
    let mp4 = dir.join("x.mp4");
    let ffmpeg = std::process::Command::new("ffmpeg")
        .arg("-version")
        .output();
    if ffmpeg.is_ok_and(|o| o.status.success()) {
        ok(&with(
            &base,
            &["--duration", "0.5", "-o", mp4.to_str().unwrap()],
        ));
        assert!(std::fs::metadata(&mp4).unwrap().len() > 500);
    } else {
        refused(
            &with(&base, &["-o", mp4.to_str().unwrap()]),
            &["install ffmpeg", ".gif"],
        );
        // Straight to stderr, past the test harness's capture.
        let _ = writeln!(
            std::io::stderr(),
            "bad_films_are_refused_before_the_run: MP4 part skipped, ffmpeg is not on PATH"
        );
    }
}
