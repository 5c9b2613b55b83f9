//! `spinball sweep`, the machine interface: the document's fields, bitwise
//! the same for any thread count, and bad usage refused with exit code 2
//! before any computing.

use std::path::PathBuf;
use std::process::{Command, Output};

use serde_json::Value;

const BIN: &str = env!("CARGO_BIN_EXE_spinball");

fn scratch(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("spinball-cli-sweep-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn sweep(args: &[&str]) -> Output {
    Command::new(BIN)
        .arg("sweep")
        .args(args)
        .output()
        .expect("the binary runs")
}

const SCENE: [&str; 12] = [
    "--table",
    "stadium:a=1",
    "--alphas",
    "0,0.5",
    "--ics",
    "8",
    "--collisions",
    "300",
    "--method",
    "fd",
    "--seed",
    "1",
];

/// The document with the wall times (the only field that differs between
/// two runs) removed.
fn without_wall_time(mut doc: Value) -> Value {
    for p in doc["points"].as_array_mut().unwrap() {
        p.as_object_mut().unwrap().remove("wall_time_s");
    }
    doc
}

#[test]
fn writes_the_document_bitwise_for_any_thread_count() {
    let dir = scratch("doc");
    let mut docs = Vec::new();
    for threads in ["1", "2"] {
        let json = dir.join(format!("t{threads}.json"));
        let json = json.to_str().unwrap();
        let mut args = SCENE.to_vec();
        args.extend(["--threads", threads, "--json", json]);
        let out = sweep(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = std::fs::read_to_string(json).unwrap();
        assert!(text.ends_with("}\n") && text.contains("\n  \"points\": ["));
        docs.push(serde_json::from_str::<Value>(&text).unwrap());
    }
    let doc = &docs[0];
    assert_eq!(
        (&doc["table"], &doc["method"], &doc["sampler"], &doc["seed"]),
        (
            &Value::from("stadium:a=1"),
            &Value::from("fd"),
            &Value::from("paper"),
            &Value::from(1)
        )
    );
    assert_eq!(doc["delta0"].as_f64(), Some(1e-7));
    assert_eq!(doc["version"], env!("CARGO_PKG_VERSION"));
    let points = doc["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    for (p, alpha) in points.iter().zip([0.0, 0.5]) {
        assert_eq!(p["alpha"].as_f64(), Some(alpha));
        assert_eq!(
            (p["n_ics"].as_u64(), p["n_collisions"].as_u64()),
            (Some(8), Some(300))
        );
        assert_eq!(p["stop"], "completed");
        assert!(p["mean"].as_f64().unwrap().is_finite());
    }
    assert_eq!(
        without_wall_time(docs[0].clone()),
        without_wall_time(docs[1].clone())
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_usage_exits_2() {
    let dir = scratch("bad");
    let json = dir.join("s.json");
    let json = json.to_str().unwrap();
    let with = |replace: (&str, &str), extra: &[&str]| {
        let mut args: Vec<&str> = SCENE
            .iter()
            .map(|&a| if a == replace.0 { replace.1 } else { a })
            .collect();
        args.extend(extra);
        sweep(&args)
    };
    let cases = [
        with(("0,0.5", "0,1.5"), &["--json", json]),
        with(("8", "1"), &["--json", json]),
        with(("fd", "rk4"), &["--json", json]),
        with(("stadium:a=1", "oval"), &["--json", json]),
        with(("1", "x"), &["--json", json]),
        with(("", ""), &[]),
        with(("", ""), &["--json", "/nonexistent/dir/s.json"]),
        with(("", ""), &["--json", json, "--threads", "0"]),
    ];
    for out in cases {
        assert_eq!(
            out.status.code(),
            Some(2),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(!out.stderr.is_empty());
    }
    let out = with(("0,0.5", "0,1.5"), &["--json", json]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("--extended"));
    // α > 1 with --extended runs.
    let out = with(("0,0.5", "1.5"), &["--json", json, "--extended"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
