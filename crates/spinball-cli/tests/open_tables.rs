//! `spinball escape` and `diffuse` end to end: shards 3 and 4, merged out
//! of order, give the whole run's JSON, CSV and NPY byte for byte on 1 or 2
//! threads; the outputs have the shapes their help says; tables that cannot
//! run are exit code 2 with a message saying what to do.

mod common;
use common::{ok, scratch, spinball};

use std::path::{Path, PathBuf};

use serde_json::Value;

fn usage(args: &[&str], words: &str) {
    let out = spinball(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "spinball {args:?}: {err}");
    assert!(err.contains(words), "spinball {args:?}: {err}");
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// The bytes of the three outputs of a run of `base` (plus `extra`) into
/// `dir` with stem `stem`.
fn outputs(dir: &Path, stem: &str, base: &[&str], extra: &[&str]) -> Vec<Vec<u8>> {
    let files: Vec<PathBuf> = ["json", "csv", "npy"]
        .iter()
        .map(|e| dir.join(format!("{stem}.{e}")))
        .collect();
    let mut args = base.to_vec();
    args.extend(extra);
    args.extend([
        "--json",
        s(&files[0]),
        "--csv",
        s(&files[1]),
        "--npy",
        s(&files[2]),
        "--quiet",
    ]);
    ok(&args);
    files.iter().map(|f| std::fs::read(f).unwrap()).collect()
}

/// Whole runs on 1 and 2 threads and shards 3 and 4 merged out of order
/// give the same bytes.
fn shards_merge_bitwise(name: &str, base: &[&str]) -> Value {
    let dir = scratch(name);
    let whole = outputs(&dir, "whole1", base, &["--threads", "1"]);
    assert_eq!(outputs(&dir, "whole2", base, &["--threads", "2"]), whole);
    for count in [3, 4] {
        let mut parts: Vec<String> = (0..count)
            .map(|k| {
                let path = dir.join(format!("part{k}of{count}.json"));
                let shard = format!("{k}/{count}");
                let mut args = base.to_vec();
                args.extend(["--shard", &shard, "--json", s(&path), "--quiet"]);
                ok(&args);
                s(&path).to_string()
            })
            .collect();
        parts.reverse();
        let stem = format!("merged{count}");
        let files: Vec<PathBuf> = ["json", "csv", "npy"]
            .iter()
            .map(|e| dir.join(format!("{stem}.{e}")))
            .collect();
        let mut args: Vec<&str> = vec!["merge"];
        args.extend(parts.iter().map(String::as_str));
        args.extend([
            "--json",
            s(&files[0]),
            "--csv",
            s(&files[1]),
            "--npy",
            s(&files[2]),
            "--quiet",
        ]);
        ok(&args);
        let merged: Vec<Vec<u8>> = files.iter().map(|f| std::fs::read(f).unwrap()).collect();
        assert_eq!(merged, whole, "{name}: {count} shards");
    }
    serde_json::from_slice(&whole[0]).unwrap()
}

#[test]
fn escape_shards_merge_into_the_whole_run_bitwise() {
    let base = [
        "escape",
        "--table",
        "stadium:a=1,hole=0.3",
        "--alpha",
        "0.4",
        "--ics",
        "120",
        "--collisions",
        "2000",
        "--seed",
        "5",
    ];
    let doc = shards_merge_bitwise("escape", &base);
    assert_eq!(doc["kind"], "spinball.escape");
    assert_eq!(doc["records"].as_array().unwrap().len(), 120);
    let s = &doc["summary"];
    assert_eq!(
        s["escaped"].as_u64().unwrap() + s["censored"].as_u64().unwrap(),
        120
    );
    assert!(s["kac"]["hole"].as_f64().unwrap() > 0.29);
    assert_eq!(doc["budget"]["collisions"], 2000);
    assert!(doc["budget"]["time"].is_null());
    // The terminal table says what escaped and the rate.
    let mut args = base.to_vec();
    args.extend(["--time", "500"]);
    let out = ok(&args);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("120 balls:") && text.contains("rate"),
        "{text}"
    );
}

#[test]
fn diffusion_shards_merge_into_the_whole_run_bitwise() {
    let base = [
        "diffuse",
        "--table",
        "lorentz:lattice=triangular,w=1,R=0.45",
        "--alpha",
        "0.4",
        "--ics",
        "60",
        "--until",
        "40",
        "--checkpoints",
        "8",
    ];
    let doc = shards_merge_bitwise("diffuse", &base);
    assert_eq!(doc["kind"], "spinball.diffusion");
    assert_eq!(doc["summary"]["horizon"], "finite");
    assert!(
        doc["summary"]["estimate"]["fit"]["Normal"].is_object(),
        "{}",
        doc["summary"]["estimate"]
    );
    // An infinite horizon reports the marginal coefficient, no finite D.
    let out = ok(&[
        "diffuse",
        "--table",
        "lorentz:lattice=square,w=1,R=0.4",
        "--alpha",
        "0",
        "--ics",
        "20",
        "--times",
        "5,10,15,20",
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("infinite horizon") && text.contains("no finite D"),
        "{text}"
    );
}

#[test]
fn tables_that_cannot_run_say_what_to_do() {
    usage(
        &[
            "escape",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.4",
            "--ics",
            "10",
        ],
        "add one",
    );
    usage(
        &[
            "diffuse",
            "--table",
            "stadium:a=1,hole=0.2",
            "--alpha",
            "0.4",
            "--ics",
            "10",
        ],
        "no periodic walls",
    );
    usage(
        &[
            "diffuse",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0",
            "--ics",
            "10",
        ],
        "no periodic walls",
    );
    usage(
        &[
            "escape",
            "--table",
            "lorentz:lattice=hexagonal",
            "--alpha",
            "0",
        ],
        "square, triangular",
    );
    usage(
        &[
            "escape",
            "--table",
            "stadium:a=1,hole=0.2",
            "--alpha",
            "0",
            "--shard",
            "1/2",
        ],
        "--shard needs --json",
    );
    usage(
        &[
            "escape",
            "--table",
            "stadium:a=1,hole=0.2",
            "--alpha",
            "0",
            "--time=-1",
        ],
        "time budget",
    );
}
