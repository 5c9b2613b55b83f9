//! Edited files are refused by `merge` and `--resume`, naming the file
//! (issue 39, item 4); a resume of another run names the field that
//! differs (item 5); sizes that would exhaust the machine are refused at
//! parse time (exit 2), before any thread or bin is made.

mod common;
use common::{scratch, spinball};

use std::path::{Path, PathBuf};
use std::process::Output;

use serde_json::Value;

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Run and expect exit code `code` with `needles` in stderr.
fn expect(args: &[&str], code: i32, needles: &[&str]) -> String {
    let out = spinball(args);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: `{n}` not in {err}");
    }
    err
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn words(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// An edit of a result file.
type Edit = dyn Fn(&mut Value);

fn write(path: &Path, v: &Value) {
    std::fs::write(path, serde_json::to_string(v).unwrap()).unwrap();
}

/// A small λ run with `more` options; α 0.5 and seed 7 unless `more`
/// gives them.
fn lyapunov(more: &[&str]) -> Vec<String> {
    let mut words: Vec<String> = [
        "lyapunov",
        "--table",
        "stadium:a=1",
        "--ics",
        "8",
        "--collisions",
        "300",
    ]
    .iter()
    .chain(more)
    .map(|w| (*w).to_string())
    .collect();
    for (flag, value) in [("--alpha", "0.5"), ("--seed", "7")] {
        if !more.contains(&flag) {
            words.extend([flag.to_string(), value.to_string()]);
        }
    }
    words
}

/// The two shards of a small λ run, as files in `dir`.
fn shards(dir: &Path) -> [PathBuf; 2] {
    [0, 1].map(|k| {
        let path = dir.join(format!("s{k}.json"));
        let shard = format!("{k}/2");
        let args = lyapunov(&["--shard", &shard, "--quiet", "--json", s(&path)]);
        expect(&words(&args), 0, &[]);
        path
    })
}

#[test]
fn merge_refuses_an_edited_shard_naming_it() {
    let dir = scratch("merge");
    let [a, b] = shards(&dir);
    let merged = dir.join("merged.json");
    expect(
        &["merge", "--quiet", "--json", s(&merged), s(&a), s(&b)],
        0,
        &[],
    );
    let original = read(&b);
    let edited = dir.join("edited.json");
    // The tester's edits, and the count and checksum themselves.
    let edits: [(&str, &Edit, &str); 6] = [
        (
            "times 10",
            &|v| {
                let x = v["points"][0]["trajectories"][1]["exponent"]
                    .as_f64()
                    .unwrap();
                v["points"][0]["trajectories"][1]["exponent"] = (x * 10.0).into();
            },
            "checksum does not hold",
        ),
        (
            "1e308",
            &|v| v["points"][0]["trajectories"][1]["exponent"] = 1e308.into(),
            "checksum does not hold",
        ),
        (
            "null",
            &|v| v["points"][0]["trajectories"][1]["exponent"] = Value::Null,
            "invalid type: null",
        ),
        (
            "appended",
            &|v| {
                let t = v["points"][0]["trajectories"][3].clone();
                v["points"][0]["trajectories"]
                    .as_array_mut()
                    .unwrap()
                    .push(t);
            },
            "holds 5",
        ),
        (
            "no checksum",
            // A file of 0.1.0, which wrote no checksum.
            &|v| {
                v["points"][0].as_object_mut().unwrap().remove("checksum");
                v["points"][0]["version"] = "0.1.0".into();
            },
            "no checksum: it was written by spinball 0.1.0",
        ),
        (
            "other checksum",
            &|v| v["points"][0]["checksum"] = "fnv1a64:0000000000000000".into(),
            "checksum does not hold",
        ),
    ];
    for (name, edit, needle) in edits {
        let mut v = original.clone();
        edit(&mut v);
        write(&edited, &v);
        let err = expect(&["merge", s(&a), s(&edited)], 2, &[needle, s(&edited)]);
        assert!(!err.contains(s(&a)), "{name}: names the wrong file: {err}");
    }
}

#[test]
fn merge_names_the_field_and_the_files_of_different_runs() {
    let dir = scratch("different");
    let [a, _] = shards(&dir);
    let b = dir.join("other.json");
    let args = lyapunov(&["--seed", "8", "--shard", "1/2", "--quiet", "--json", s(&b)]);
    expect(&words(&args), 0, &[]);
    let want = format!("seed 7 in {}, 8 in {}", s(&a), s(&b));
    expect(&["merge", s(&a), s(&b)], 2, &[&want]);
}

#[test]
fn resume_refuses_an_edited_checkpoint_and_names_what_differs() {
    let dir = scratch("resume");
    let [a, _] = shards(&dir);
    // A finished shard is a checkpoint with nothing left to run.
    let json = dir.join("r.json");
    let checkpoint = dir.join("r.json.partial");
    let resume = |more: &[&str]| -> Vec<String> {
        let mut words = vec!["--shard", "0/2", "--quiet", "--json", s(&json), "--resume"];
        words.extend(more);
        lyapunov(&words)
    };
    let mut v = read(&a);
    std::fs::copy(&a, &checkpoint).unwrap();
    let args = resume(&["--seed", "8"]);
    expect(
        &words(&args),
        2,
        &[
            s(&checkpoint),
            "checkpoint of another run: seed 7 in the checkpoint, 8 asked",
        ],
    );
    let args = resume(&["--alpha", "0.25"]);
    expect(
        &words(&args),
        2,
        &["alpha 0.5 in the checkpoint, 0.25 asked"],
    );
    let args = resume(&["--method", "tangent"]);
    expect(
        &words(&args),
        2,
        &["method fd (delta0 1e-7) in the checkpoint, tangent asked"],
    );
    // The tester's edit: one exponent + 100.
    let x = v["points"][0]["trajectories"][0]["exponent"]
        .as_f64()
        .unwrap();
    v["points"][0]["trajectories"][0]["exponent"] = (x + 100.0).into();
    write(&checkpoint, &v);
    let args = resume(&[]);
    expect(
        &words(&args),
        2,
        &[s(&checkpoint), "checksum does not hold"],
    );
    assert!(!json.exists(), "nothing written from an edited checkpoint");
    // The unedited checkpoint resumes (nothing left: the shard is written).
    std::fs::copy(&a, &checkpoint).unwrap();
    expect(&words(&args), 0, &[]);
    // The same trajectories (the wall time, and with it the checksum,
    // grows by the resume's).
    let points = |v: Value| v["points"][0]["trajectories"].clone();
    assert_eq!(points(read(&json)), points(read(&a)));
}

#[test]
fn merge_refuses_an_edited_spectrum_shard() {
    let dir = scratch("spectrum");
    let parts = [0, 1].map(|k| {
        let path = dir.join(format!("s{k}.json"));
        let shard = format!("{k}/2");
        let args = [
            "spectrum",
            "--table",
            "sinai:L=2,R=1",
            "--alpha",
            "0.5",
            "--ics",
            "8",
            "--collisions",
            "200",
            "--shard",
            &shard,
            "--quiet",
            "--json",
            s(&path),
        ];
        expect(&args, 0, &[]);
        path
    });
    let merged = dir.join("merged.json");
    expect(
        &[
            "merge",
            "--quiet",
            "--json",
            s(&merged),
            s(&parts[0]),
            s(&parts[1]),
        ],
        0,
        &[],
    );
    assert_eq!(read(&merged)["points"][0]["n_ics"], 8);
    // The tester's edit: one more spectrum appended to a shard.
    let mut v = read(&parts[1]);
    let extra = v["points"][0]["spectra"][0].clone();
    v["points"][0]["spectra"]
        .as_array_mut()
        .unwrap()
        .push(extra);
    let edited = dir.join("edited.json");
    write(&edited, &v);
    expect(
        &["merge", s(&parts[0]), s(&edited)],
        2,
        &[s(&edited), "holds 5"],
    );
    // ... with the counts edited to match.
    v["points"][0]["n_spectra"] = 5.into();
    v["points"][0]["n_ics"] = 5.into();
    write(&edited, &v);
    expect(
        &["merge", s(&parts[0]), s(&edited)],
        2,
        &[s(&edited), "checksum does not hold"],
    );
}

#[test]
fn huge_thread_counts_and_bins_are_refused_before_anything_runs() {
    // Refused by the parser: no ensemble is built, no thread is made.
    for threads in ["100000", "0", "1025", "18446744073709551615", "x"] {
        let args = lyapunov(&["--threads", threads]);
        expect(&words(&args), 2, &["1..=1024"]);
        let args = [
            "spectrum",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--threads",
            threads,
        ];
        expect(&args, 2, &["1..=1024"]);
        let args = [
            "sweep",
            "--table",
            "stadium",
            "--alphas",
            "0.5",
            "--ics",
            "4",
            "--collisions",
            "50",
            "--method",
            "tangent",
            "--seed",
            "1",
            "--json",
            "never.json",
            "--threads",
            threads,
        ];
        expect(&args, 2, &["1..=1024"]);
    }
    let dir = scratch("bins");
    let hist = dir.join("h.csv");
    for bins in ["18446744073709551615", "0", "1048577"] {
        let args = [
            "ftle",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--ics",
            "4",
            "--collisions",
            "50",
            "--bins",
            bins,
            "--histogram",
            s(&hist),
        ];
        expect(&args, 2, &["1..=1048576"]);
    }
    assert!(!hist.exists());
}

/// A file of spinball 0.1.0 (written by its command line, kept with the
/// analysis crate's tests).
fn old_file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../spinball-analysis/tests/data/0.1.0/{name}"))
}

#[test]
fn files_of_0_1_are_refused_by_merge_and_resume_naming_the_versions() {
    let dir = scratch("old");
    let old = old_file("partial.json");
    let [a, _] = shards(&dir);
    // The results written now carry the schema and the kind.
    let v = read(&a);
    assert_eq!(
        (v["schema"].as_u64(), v["kind"].as_str()),
        (Some(2), Some("spinball.lyapunov.partial"))
    );
    let needles = [s(&old), "spinball 0.1.0", "schema 1", "reads schema 2"];
    expect(&["merge", s(&old), s(&a)], 2, &needles);
    expect(&["merge", s(&a), s(&old)], 2, &needles);
    // As a checkpoint to resume.
    let checkpoint = dir.join("old.partial");
    std::fs::copy(&old, &checkpoint).unwrap();
    let args = lyapunov(&["--quiet", "--resume", "--checkpoint", s(&checkpoint)]);
    expect(
        &words(&args),
        2,
        &[s(&checkpoint), "spinball 0.1.0", "schema 1"],
    );
    // A finished 0.1.0 result is no shard: merge says what it is.
    let result = old_file("result.json");
    expect(
        &["merge", s(&result)],
        2,
        &["its kind is `spinball.lyapunov`"],
    );
}
