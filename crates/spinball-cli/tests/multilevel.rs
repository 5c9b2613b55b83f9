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

/// The estimates of a multilevel document with the levels' wall times
/// taken out (the only numbers a sharded run may differ in).
fn untimed(mut doc: Value) -> Value {
    for p in doc["points"].as_array_mut().unwrap() {
        for l in p["estimate"]["levels"].as_array_mut().unwrap() {
            l["wall_time_s"] = Value::Null;
        }
    }
    doc.as_object_mut().unwrap().remove("version");
    doc
}

/// `spinball slurm --estimator multilevel` plans the allocation once; its
/// tasks (the array script itself, run by bash as SLURM would) each run
/// their shard of every level, the merge job joins them, and the result is
/// bitwise the allocation run whole in one process.
#[test]
fn slurm_multilevel_shards_merge_into_the_unsharded_run() {
    let dir = scratch("slurm-multilevel");
    let d = dir.join("campaign");
    let options = [
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--collisions",
        "1600",
        "--method",
        "fd",
        "--seed",
        "4",
        "--threads",
        "1",
        "--estimator",
        "multilevel",
        "--target-error",
        "0.05",
    ];
    let mut args = vec!["slurm"];
    args.extend(options);
    args.extend(["--shards", "3", "--dir", d.to_str().unwrap()]);
    let run = spinball(&args);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let plan = d.join("plans").join("t0_a0.json");
    let allocation = json(&plan);
    assert_eq!(
        allocation["levels"],
        serde_json::json!([200, 400, 800, 1600])
    );
    let array = std::fs::read_to_string(d.join("array.sbatch")).unwrap();
    assert!(array.contains("#SBATCH --array=0-2"), "{array}");
    assert!(array.contains("--allocation"), "{array}");
    for task in 0..3 {
        let status = std::process::Command::new("bash")
            .arg(d.join("array.sbatch"))
            .env("SLURM_ARRAY_TASK_ID", task.to_string())
            .env("SLURM_CPUS_PER_TASK", "1")
            .status()
            .unwrap();
        assert!(status.success(), "task {task}");
    }
    let status = std::process::Command::new("bash")
        .arg(d.join("merge.sbatch"))
        .status()
        .unwrap();
    assert!(status.success(), "merge job");
    let merged = json(&d.join("results").join("t0_a0.json"));
    assert_eq!(merged["kind"], "spinball.multilevel");

    let whole = dir.join("whole.json");
    let mut args = vec!["lyapunov"];
    args.extend(options);
    args.extend([
        "--allocation",
        plan.to_str().unwrap(),
        "--quiet",
        "--json",
        whole.to_str().unwrap(),
    ]);
    let run = spinball(&args);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(untimed(merged), untimed(json(&whole)));

    // A shard missing is refused by the merge.
    let parts = d.join("parts");
    let run = spinball(&[
        "merge",
        parts.join("t0_a0_s0.json").to_str().unwrap(),
        parts.join("t0_a0_s1.json").to_str().unwrap(),
        "--json",
        dir.join("two.json").to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(2));
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(err.contains("shard"), "{err}");
}
