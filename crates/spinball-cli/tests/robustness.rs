//! The `spinball` binary never panics (exit code 101) on the inputs of
//! issue 39: durations beyond what the clock counts, a full or closed
//! stdout, and output paths that are devices, FIFOs, directories or links.

mod common;
use common::{BIN, scratch};

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

#[cfg(unix)]
use std::os::unix::fs::{FileTypeExt, MetadataExt};

use serde_json::Value;

fn run(args: &[&str], stdout: Stdio) -> Output {
    Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .stdout(stdout)
        .output()
        .expect("the binary runs")
}

fn spinball(args: &[&str]) -> Output {
    run(args, Stdio::piped())
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Run and check the exit code (never 101) and that stderr says `needle`.
fn expect(args: &[&str], code: i32, needle: &str) -> Output {
    let out = spinball(args);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(code), "spinball {args:?}: {err}");
    assert!(err.contains(needle), "spinball {args:?}: {err}");
    out
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&fs::read_to_string(path).unwrap()).unwrap()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A quick λ run.
const QUICK: [&str; 9] = [
    "lyapunov",
    "--table",
    "stadium:a=1",
    "--alpha",
    "0,0.5",
    "--ics",
    "4",
    "--collisions",
    "60",
];

fn quick(more: &[&str]) -> Vec<String> {
    QUICK.iter().chain(more).map(|s| (*s).to_string()).collect()
}

fn words(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

#[test]
fn a_time_limit_beyond_the_clock_is_no_limit() {
    // 1e300 s is beyond a Duration, 1e19 s beyond an Instant (both
    // panicked), inf was refused: none can be reached, so none stops the run.
    for limit in ["1e300", "1e19", "inf"] {
        let dir = scratch("limit");
        let json = dir.join("r.json");
        let args = quick(&["--quiet", "--json", s(&json), "--time-limit", limit]);
        let out = spinball(&words(&args));
        assert_eq!(out.status.code(), Some(0), "{limit}: {}", stderr(&out));
        let doc = read(&json);
        for p in doc["points"].as_array().unwrap() {
            assert_eq!(p["n_ics"], 4, "{limit}");
            assert_eq!(p["stop"], "completed", "{limit}");
        }
    }
}

#[test]
fn a_time_limit_out_of_range_is_a_usage_error() {
    for limit in ["0", "-1", "nan", "-inf", "soon"] {
        let args = quick(&["--quiet", &format!("--time-limit={limit}")]);
        let out = expect(&words(&args), 2, "--time-limit");
        let err = stderr(&out);
        assert!(err.contains("seconds > 0"), "{limit}: {err}");
    }
}

#[test]
fn a_checkpoint_interval_beyond_the_clock_saves_only_on_stop() {
    let dir = scratch("every");
    let json = dir.join("r.json");
    let partial = dir.join("r.json.partial");
    for every in ["1e300", "inf"] {
        let args = quick(&["--quiet", "--json", s(&json), "--checkpoint-every", every]);
        let out = spinball(&words(&args));
        assert_eq!(out.status.code(), Some(0), "{every}: {}", stderr(&out));
        assert_eq!(read(&json)["points"][0]["n_ics"], 4);
        assert!(!partial.exists());
    }
    // Stopped at once: the checkpoint is still saved when the run stops.
    let _ = fs::remove_file(&json);
    let args = quick(&[
        "--quiet",
        "--json",
        s(&json),
        "--checkpoint-every",
        "1e300",
        "--time-limit",
        "1e-9",
    ]);
    expect(&words(&args), 3, "--resume");
    assert_eq!(read(&partial)["kind"], "spinball.lyapunov.partial");
    assert!(!json.exists());
}

#[test]
fn a_checkpoint_interval_out_of_range_is_a_usage_error() {
    for every in ["-1", "nan", "-inf", "often"] {
        let args = quick(&["--quiet", &format!("--checkpoint-every={every}")]);
        let out = expect(&words(&args), 2, "--checkpoint-every");
        let err = stderr(&out);
        assert!(err.contains("seconds >= 0"), "{every}: {err}");
    }
}

/// `/dev/full` as stdout (opened for writing only: writes fail with
/// ENOSPC), or `None` with a printed reason.
fn dev_full() -> Option<Stdio> {
    match fs::OpenOptions::new().write(true).open("/dev/full") {
        Ok(f) => Some(Stdio::from(f)),
        Err(e) => {
            eprintln!(
                "SKIPPED: /dev/full cannot be opened ({e}); the full-stdout cases did not run"
            );
            None
        }
    }
}

/// Run with stdout on `/dev/full` and expect exit code 1 saying so.
fn full_stdout(args: &[&str]) -> bool {
    let Some(full) = dev_full() else {
        return false;
    };
    let out = run(args, full);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "spinball {args:?}: {err}");
    assert!(err.contains("cannot write to stdout"), "{args:?}: {err}");
    assert!(err.contains("No space left"), "{args:?}: {err}");
    true
}

#[test]
fn a_full_stdout_fails_every_command_with_exit_1() {
    let dir = scratch("full");
    let json = dir.join("r.json");
    let csv = dir.join("r.csv");
    if !full_stdout(&words(&quick(&["--json", s(&json), "--csv", s(&csv)]))) {
        return;
    }
    // The files are the result: written even though stdout was full.
    assert_eq!(read(&json)["points"][1]["n_ics"], 4);
    assert!(fs::read_to_string(&csv).unwrap().lines().count() == 3);

    let per_ic = dir.join("per_ic.csv");
    let mut ftle = quick(&["--per-ic", s(&per_ic)]);
    ftle[0] = "ftle".into();
    full_stdout(&words(&ftle));
    assert!(dir.join("per_ic.alpha-0.5.csv").exists());

    let mut spectrum = quick(&[]);
    spectrum[0] = "spectrum".into();
    full_stdout(&words(&spectrum));

    full_stdout(&[
        "trajectory",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--collisions",
        "20",
    ]);
    full_stdout(&["table", "sinai:L=2,R=1"]);

    // A shard's note, and merge's table.
    let parts: Vec<PathBuf> = (0..2).map(|k| dir.join(format!("p{k}.json"))).collect();
    for (k, p) in parts.iter().enumerate() {
        full_stdout(&words(&quick(&[
            "--shard",
            &format!("{k}/2"),
            "--json",
            s(p),
        ])));
        assert_eq!(read(p)["kind"], "spinball.lyapunov.partial");
    }
    full_stdout(&["merge", s(&parts[0]), s(&parts[1])]);

    full_stdout(&[
        "slurm",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--dir",
        s(&dir.join("campaign")),
    ]);
    assert!(dir.join("campaign/campaign.json").exists());

    // clap's own output.
    full_stdout(&["--help"]);
    full_stdout(&["lyapunov", "--help"]);
    full_stdout(&["--version"]);
}

/// Run with stdout a pipe whose reader is gone, as `| head` leaves it.
fn closed_stdout(args: &[&str]) {
    let mut child = Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "spinball {args:?}: {err}");
    assert!(err.is_empty(), "a closed pipe is not an error: {err}");
}

#[test]
fn a_closed_stdout_ends_quietly_with_success() {
    let dir = scratch("pipe");
    let json = dir.join("r.json");
    closed_stdout(&words(&quick(&["--json", s(&json)])));
    assert_eq!(read(&json)["points"][0]["n_ics"], 4);
    // 20 000 collisions are far more than a pipe's buffer holds.
    closed_stdout(&[
        "trajectory",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--collisions",
        "20000",
    ]);
    closed_stdout(&["table", "circle"]);
    closed_stdout(&["--help"]);
}

/// Make a character device `major:minor` at `path` with mknod(1), or say
/// why not (printed, so a skipped test is visible with --nocapture).
#[cfg(unix)]
fn mknod(path: &Path, major: u32, minor: u32) -> bool {
    let out = Command::new("mknod")
        .args([s(path), "c", &major.to_string(), &minor.to_string()])
        .output();
    match out {
        Ok(o) if o.status.success() => true,
        Ok(o) => {
            eprintln!(
                "SKIPPED: mknod {} c {major} {minor} failed ({}); the device cases did not run",
                path.display(),
                String::from_utf8_lossy(&o.stderr).trim()
            );
            false
        }
        Err(e) => {
            eprintln!("SKIPPED: mknod cannot run ({e}); the device cases did not run");
            false
        }
    }
}

/// `path` is still the character device `major:minor`.
#[cfg(unix)]
fn still_device(path: &Path, major: u64, minor: u64) {
    let m = fs::symlink_metadata(path).unwrap();
    assert!(
        m.file_type().is_char_device(),
        "{} was replaced",
        path.display()
    );
    assert_eq!(m.rdev(), (major << 8) | minor, "{}", path.display());
}

#[cfg(unix)]
#[test]
fn a_device_is_never_replaced() {
    let dir = scratch("device");
    // The numbers of the null device (reads end at once, writes vanish)
    // and of the full device (writes fail with ENOSPC), in our directory.
    let null = dir.join("null");
    let full = dir.join("full");
    let png = dir.join("null.png");
    if !(mknod(&null, 1, 3) && mknod(&full, 1, 7) && mknod(&png, 1, 3)) {
        return;
    }
    let ok_json = dir.join("ok.json");
    let cases: Vec<(Vec<String>, &str)> = vec![
        (quick(&["--quiet", "--json", s(&null)]), "--json"),
        (
            quick(&["--quiet", "--json", s(&ok_json), "--checkpoint", s(&null)]),
            "--checkpoint",
        ),
        (
            {
                let mut v = quick(&["--quiet", "--json", s(&null)]);
                v[0] = "spectrum".into();
                v
            },
            "--json",
        ),
        (
            {
                let mut v = quick(&["--quiet", "--json", s(&null)]);
                v[0] = "ftle".into();
                v
            },
            "--json",
        ),
        (
            ["table", "circle", "--json", s(&null)]
                .map(String::from)
                .to_vec(),
            "--json",
        ),
        (
            ["table", "circle", "--png", s(&png)]
                .map(String::from)
                .to_vec(),
            "--png",
        ),
        (
            ["merge", s(&ok_json), "--json", s(&null)]
                .map(String::from)
                .to_vec(),
            "--json",
        ),
    ];
    for (args, flag) in &cases {
        let out = expect(&words(args), 2, "character device");
        let err = stderr(&out);
        assert!(err.contains(flag), "{args:?}: {err}");
        assert!(err.contains("refusing to replace"), "{args:?}: {err}");
        still_device(&null, 1, 3);
        still_device(&png, 1, 3);
    }
    assert!(!ok_json.exists(), "refused before the run");
    assert!(!dir.join("null.tmp").exists());

    // --csv and --npy write into the path (as a shell redirect would): on a
    // full device they fail, exit 1, and leave it a device.
    for flag in ["--csv", "--npy"] {
        let args = quick(&["--quiet", flag, s(&full)]);
        let out = expect(&words(&args), 1, "No space left");
        assert!(stderr(&out).contains(s(&full)), "{}", stderr(&out));
        still_device(&full, 1, 7);
    }
    for flag in ["--csv", "--npy"] {
        expect(
            &[
                "trajectory",
                "--table",
                "circle",
                "--alpha",
                "0.5",
                flag,
                s(&full),
            ],
            1,
            "No space left",
        );
        still_device(&full, 1, 7);
    }
}

#[cfg(unix)]
#[test]
fn a_fifo_and_a_directory_are_never_replaced() {
    let dir = scratch("fifo");
    let fifo = dir.join("fifo.json");
    let made = Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo needs no privilege");
    let sub = dir.join("sub.json");
    fs::create_dir(&sub).unwrap();
    for (path, what) in [(&fifo, "is a FIFO"), (&sub, "is a directory")] {
        for args in [
            quick(&["--quiet", "--json", s(path)]),
            ["table", "circle", "--json", s(path)]
                .map(String::from)
                .to_vec(),
        ] {
            let out = expect(&words(&args), 2, what);
            assert!(stderr(&out).contains(s(path)), "{}", stderr(&out));
        }
    }
    assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    assert!(fs::symlink_metadata(&sub).unwrap().is_dir());
    assert_eq!(fs::read_dir(&sub).unwrap().count(), 0);
}

#[cfg(unix)]
#[test]
fn a_link_to_a_regular_file_writes_the_file_and_stays_a_link() {
    use std::os::unix::fs::symlink;
    let dir = scratch("link");
    let file = dir.join("results").join("r.json");
    fs::create_dir(dir.join("results")).unwrap();
    fs::write(&file, "old").unwrap();
    let link = dir.join("r.json");
    symlink("results/r.json", &link).unwrap();
    let out = spinball(&words(&quick(&["--quiet", "--json", s(&link)])));
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(fs::symlink_metadata(&link).unwrap().is_symlink());
    assert_eq!(fs::read_link(&link).unwrap(), Path::new("results/r.json"));
    assert_eq!(read(&file)["kind"], "spinball.lyapunov");
    assert!(!dir.join("r.json.partial").exists());
    assert!(!dir.join("results/r.json.tmp").exists());

    // A link to nothing yet: the file it names is created.
    let later = dir.join("later.json");
    let dangling = dir.join("d.json");
    symlink(&later, &dangling).unwrap();
    let out = spinball(&["table", "circle", "--quiet", "--json", s(&dangling)]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(fs::symlink_metadata(&dangling).unwrap().is_symlink());
    assert!(read(&later)["area"].as_f64().is_some());

    // A link to a directory is refused, naming both.
    let to_dir = dir.join("to-dir.json");
    symlink(dir.join("results"), &to_dir).unwrap();
    let out = expect(
        &["table", "circle", "--json", s(&to_dir)],
        2,
        "through a link to",
    );
    assert!(stderr(&out).contains("is a directory"), "{}", stderr(&out));
    assert!(fs::symlink_metadata(&to_dir).unwrap().is_symlink());
}

#[test]
fn an_output_in_a_missing_directory_is_refused_before_the_run() {
    let dir = scratch("missing-dir");
    let nowhere = dir.join("no-such-dir");
    // A billion ICs would take hours: the refusal comes first.
    let long = |command: &str, more: &[&str]| {
        let mut v = quick(more);
        v[0] = command.into();
        assert_eq!(v[5], "--ics");
        v[6] = "1000000000".into();
        v
    };
    for flag in ["--json", "--csv", "--npy"] {
        let path = nowhere.join("r.out");
        let out = expect(
            &words(&long("lyapunov", &["--quiet", flag, s(&path)])),
            2,
            "does not exist",
        );
        assert!(stderr(&out).contains(flag), "{}", stderr(&out));
    }
    let per_ic = nowhere.join("x.csv");
    expect(
        &words(&long("ftle", &["--quiet", "--per-ic", s(&per_ic)])),
        2,
        "--per-ic",
    );
    assert!(!nowhere.exists());
}
