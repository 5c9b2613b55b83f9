//! `--estimator multilevel --target-error` on `spinball lyapunov` and
//! `spinball sweep`: the estimate, its JSON document, and the usage errors.

mod common;

use common::{scratch, spinball};
use serde_json::Value;

fn json(path: &std::path::Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn lyapunov_and_sweep_run_multilevel() {
    let dir = scratch("multilevel");
    let out = dir.join("ml.json");
    let run = spinball(&[
        "lyapunov",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--collisions",
        "2000",
        "--method",
        "tangent",
        "--seed",
        "3",
        "--estimator",
        "multilevel",
        "--target-error",
        "0.02",
        "--json",
        out.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let text = String::from_utf8_lossy(&run.stdout);
    assert!(
        text.contains("λ_∞") && text.contains("chaotic fraction"),
        "{text}"
    );
    let doc = json(&out);
    assert_eq!(doc["estimator"], "multilevel");
    let point = &doc["points"][0];
    assert_eq!(point["alpha"], 0.5);
    let levels = point["estimate"]["levels"].as_array().unwrap();
    assert_eq!(levels.len(), 4);
    // A plain ensemble of the same T (stadium α = 0.5, 2000 collisions,
    // tangent) gives 0.1889 ± 0.0015 (seed 12, 1500 ICs, the library's
    // test); the multilevel estimate is within 3 combined SE of it.
    let mean = point["estimate"]["means"][3]["value"].as_f64().unwrap();
    let sem = point["estimate"]["means"][3]["sem"].as_f64().unwrap();
    assert!(
        (mean - 0.1889).abs() < 3.0 * sem.hypot(0.0015),
        "{mean} ± {sem}"
    );

    let sweep_out = dir.join("sweep.json");
    let run = spinball(&[
        "sweep",
        "--table",
        "sinai:L=2,R=1",
        "--alphas",
        "0.5,1",
        "--ics",
        "2",
        "--collisions",
        "2000",
        "--method",
        "tangent",
        "--seed",
        "1",
        "--json",
        sweep_out.to_str().unwrap(),
        "--estimator",
        "multilevel",
        "--target-error",
        "0.03",
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(json(&sweep_out)["points"].as_array().unwrap().len(), 2);
}

#[test]
fn multilevel_usage_errors_exit_2() {
    let base = ["lyapunov", "--table", "stadium:a=1", "--alpha", "0.5"];
    for (extra, says) in [
        (&["--estimator", "multilevel"][..], "--target-error"),
        (&["--target-error", "0.01"][..], "--estimator multilevel"),
        (
            &["--estimator", "multilevel", "--target-error", "2"][..],
            "(0, 1)",
        ),
        (
            &[
                "--estimator",
                "multilevel",
                "--target-error",
                "0.01",
                "--collisions",
                "1000",
            ][..],
            "at least 1600",
        ),
        (
            &[
                "--estimator",
                "multilevel",
                "--target-error",
                "0.01",
                "--shard",
                "0/2",
            ][..],
            "--shard",
        ),
    ] {
        let args: Vec<&str> = base.iter().chain(extra).copied().collect();
        let run = spinball(&args);
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
}
