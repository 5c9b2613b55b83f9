//! The `spinball` binary end to end: shards merge bitwise into the
//! unsharded result, interrupted runs resume to the uninterrupted result,
//! bad input gets exit code 2 with a message, outputs are readable.

mod common;
use common::{BIN, ok, scratch, spinball};

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use serde_json::Value;

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The result's points with the wall times (the only field allowed to
/// differ between a merged and an unsharded run) removed, and the
/// checksums of spectrum results (which cover the wall time).
fn without_wall_time(doc: &Value) -> Value {
    let mut doc = doc.clone();
    for p in doc["points"].as_array_mut().unwrap() {
        let p = p.as_object_mut().unwrap();
        p.remove("wall_time_s");
        p.remove("checksum");
    }
    doc
}

fn table_file(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../docs/tables")
        .join(name)
        .display()
        .to_string()
}

const RUN: [&str; 8] = [
    "--alpha",
    "0,0.5",
    "--ics",
    "11",
    "--collisions",
    "400",
    "--seed",
    "3",
];

#[test]
fn shards_merge_bitwise_into_the_unsharded_run() {
    let dir = scratch("shards");
    let mushroom = table_file("mushroom.toml");
    for (table, method) in [("stadium:a=1", "fd"), (mushroom.as_str(), "tangent")] {
        let whole = dir.join("whole.json");
        let mut args = vec!["lyapunov", "--table", table, "--method", method, "--quiet"];
        args.extend(RUN);
        let w = whole.to_str().unwrap();
        ok(&[args.as_slice(), &["--json", w]].concat());
        // 4 shards of 11 ICs (2, 3, 3, 3), merged in a scrambled order.
        let mut parts = Vec::new();
        for k in [2, 0, 3, 1] {
            let part = dir.join(format!("part{k}.json"));
            let shard = format!("{k}/4");
            ok(&[
                args.as_slice(),
                &["--shard", &shard, "--json", part.to_str().unwrap()],
            ]
            .concat());
            parts.push(part.to_str().unwrap().to_string());
        }
        let merged = dir.join("merged.json");
        let mut margs = vec!["merge", "--quiet", "--json", merged.to_str().unwrap()];
        margs.extend(parts.iter().map(String::as_str));
        ok(&margs);
        let (a, b) = (read(&whole), read(&merged));
        assert_eq!(a["points"].as_array().unwrap().len(), 2);
        assert_eq!(a["points"][1]["n_ics"], 11);
        // serde_json reads back the shortest round-trip decimal, so equal
        // values are equal bits.
        assert_eq!(
            without_wall_time(&a),
            without_wall_time(&b),
            "{table} {method}"
        );

        // Missing and overlapping shards are refused.
        let out = spinball(&["merge", &parts[0], &parts[1], &parts[2]]);
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains("missing"));
        let out = spinball(&[
            "merge", &parts[0], &parts[0], &parts[1], &parts[2], &parts[3],
        ]);
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains("overlap"));
    }
}

#[test]
fn merge_refuses_shards_of_different_runs() {
    let dir = scratch("different");
    let p = |k: u32, seed: &str| {
        let path = dir.join(format!("s{seed}_{k}.json"));
        let shard = format!("{k}/2");
        ok(&[
            "lyapunov",
            "--table",
            "sinai:L=2,R=1",
            "--alpha",
            "0.5",
            "--ics",
            "6",
            "--collisions",
            "200",
            "--seed",
            seed,
            "--shard",
            &shard,
            "--quiet",
            "--json",
            path.to_str().unwrap(),
        ]);
        path.to_str().unwrap().to_string()
    };
    let (a, b) = (p(0, "1"), p(1, "2"));
    let out = spinball(&["merge", &a, &b]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("different runs"), "{err}");
    let out = spinball(&["merge", &a, "no-such-file.json"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn an_interrupted_run_resumes_to_the_uninterrupted_result() {
    let dir = scratch("resume");
    let json = dir.join("r.json");
    let j = json.to_str().unwrap();
    let checkpoint = dir.join("r.json.partial");
    // The scalar engine on one thread: 14 batches of 96 ICs, long enough
    // to be stopped after the first.
    let args = [
        "lyapunov",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--ics",
        "1280",
        "--collisions",
        "20000",
        "--engine",
        "scalar",
        "--threads",
        "1",
        "--checkpoint-every",
        "0",
        "--quiet",
        "--json",
        j,
    ];
    let mut child = Command::new(BIN).args(args).spawn().unwrap();
    let clock = Instant::now();
    while !checkpoint.exists() {
        assert!(
            clock.elapsed() < Duration::from_secs(120),
            "no checkpoint appeared"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(3), "a stopped run exits with 3");
    let saved = read(&checkpoint);
    let done = saved["points"][0]["trajectories"].as_array().unwrap().len();
    assert!(done > 0 && done < 1280, "stopped after {done} ICs");
    assert!(!json.exists(), "no result before the run is finished");

    ok(&[args.as_slice(), &["--resume"]].concat());
    assert!(
        !checkpoint.exists(),
        "the checkpoint is removed once the result is written"
    );
    let resumed = read(&json);
    let straight = dir.join("s.json");
    let mut args2 = args.to_vec();
    let n = args2.len();
    args2[n - 1] = straight.to_str().unwrap();
    ok(&args2);
    assert_eq!(
        without_wall_time(&resumed),
        without_wall_time(&read(&straight))
    );
}

#[test]
fn a_time_limit_stops_and_saves() {
    let dir = scratch("limit");
    let json = dir.join("t.json");
    let args = [
        "lyapunov",
        "--table",
        "sinai:L=2,R=1",
        "--alpha",
        "0.3",
        "--ics",
        "300",
        "--collisions",
        "2000",
        "--quiet",
        "--json",
        json.to_str().unwrap(),
    ];
    let out = spinball(&[args.as_slice(), &["--time-limit", "1e-9"]].concat());
    assert_eq!(out.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--resume"));
    ok(&[args.as_slice(), &["--resume"]].concat());
    let doc = read(&json);
    assert_eq!(doc["points"][0]["n_ics"], 300);
    assert_eq!(doc["points"][0]["stop"], "completed");
}

#[test]
fn bad_usage_exits_2_with_a_message() {
    let cases: [(&[&str], &str); 7] = [
        (
            &["lyapunov", "--table", "hexagon", "--alpha", "0.5"],
            "unknown table",
        ),
        (
            &["lyapunov", "--table", "stadium:a=1", "--alpha", "1.5"],
            "--extended",
        ),
        (
            &[
                "lyapunov",
                "--table",
                "stadium:a=1",
                "--alpha",
                "0.5",
                "--ics",
                "1",
            ],
            "at least 2",
        ),
        (
            &[
                "lyapunov",
                "--table",
                "stadium:a=1",
                "--alpha",
                "0.5",
                "--shard",
                "4/4",
                "--json",
                "x.json",
            ],
            "shard",
        ),
        (
            &[
                "lyapunov",
                "--table",
                "stadium:a=1",
                "--alpha",
                "0.5",
                "--shard",
                "1/4",
            ],
            "--json",
        ),
        (
            &["lyapunov", "--table", "missing.toml", "--alpha", "0.5"],
            "cannot read",
        ),
        (
            &[
                "trajectory",
                "--table",
                "circle",
                "--alpha",
                "0.5",
                "--position",
                "5,0",
                "--velocity",
                "1,0",
            ],
            "launch",
        ),
    ];
    for (args, needle) in cases {
        let out = spinball(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn trajectory_writes_csv_and_npy() {
    let dir = scratch("trajectory");
    let npy = dir.join("t.npy");
    let out = ok(&[
        "trajectory",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--collisions",
        "100",
        "--position",
        "0.1,0.2",
        "--velocity",
        "0.6,0.8",
        "--spin",
        "0.1",
        "--npy",
        npy.to_str().unwrap(),
    ]);
    assert!(
        out.stdout.is_empty(),
        "with --npy alone nothing goes to stdout"
    );
    let bytes = std::fs::read(&npy).unwrap();
    assert_eq!(&bytes[..6], b"\x93NUMPY");
    let header = String::from_utf8_lossy(&bytes[..128]);
    assert!(header.contains("'shape': (100, 10,"), "{header}");
    assert!(header.contains("<f8"), "{header}");
    // Header, then 100 rows of 10 float64.
    let header_len = 10 + u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    assert_eq!(bytes.len(), header_len + 100 * 10 * 8);
    let out = ok(&[
        "trajectory",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--collisions",
        "5",
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "time,x,y,vx,vy,u,wall,s,v_par,q");
    assert_eq!(lines.len(), 6);
}

#[test]
fn table_describes_validates_and_draws() {
    let dir = scratch("table");
    let png = dir.join("m.png");
    let out = ok(&[
        "table",
        &table_file("mushroom.toml"),
        "--png",
        png.to_str().unwrap(),
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    // Half disk of radius 1 plus a 0.6 × 1 stem.
    let area = std::f64::consts::FRAC_PI_2 + 0.6;
    let shown: f64 = text
        .lines()
        .find_map(|l| l.strip_prefix("area"))
        .and_then(|v| v.trim().parse().ok())
        .expect("an area line");
    assert!((shown - area).abs() < 1e-12, "{text}");
    assert!(text.contains("engine         lanes"), "{text}");
    assert!(std::fs::metadata(&png).unwrap().len() > 1000);
    for f in ["l-polygon.toml", "two-disk-cell.json"] {
        ok(&["table", "--quiet", &table_file(f)]);
    }
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "polygon = [[0,0],[1,0],[1,1],[0,1],[0.5,0.5],[0.5,2]]\noops = 1\n",
    )
    .unwrap();
    let out = spinball(&["table", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown field"));
}

#[test]
fn slurm_writes_an_array_and_a_merge_job() {
    let dir = scratch("slurm");
    let d = dir.join("campaign");
    ok(&[
        "slurm",
        "--table",
        "stadium:a=1",
        "--and-table",
        "sinai:L=2,R=1",
        "--alpha",
        "0,0.5,1",
        "--ics",
        "40",
        "--collisions",
        "100",
        "--shards",
        "4",
        "--time",
        "10:00",
        "--dir",
        d.to_str().unwrap(),
    ]);
    let array = std::fs::read_to_string(d.join("array.sbatch")).unwrap();
    // 2 tables × 3 α × 4 shards.
    assert!(array.contains("#SBATCH --array=0-23"), "{array}");
    assert!(array.contains("--time-limit 540"), "{array}");
    for script in ["array.sbatch", "merge.sbatch", "submit.sh"] {
        let status = Command::new("bash")
            .arg("-n")
            .arg(d.join(script))
            .status()
            .unwrap();
        assert!(status.success(), "{script} is not valid bash");
    }
    let again = [
        "slurm",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--ics",
        "4",
        "--shards",
        "2",
        "--dir",
        d.to_str().unwrap(),
    ];
    // A second campaign in the same directory is refused, and the first
    // is kept, unless --force.
    let out = spinball(&again);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("holds a campaign already") && err.contains("--force"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(d.join("array.sbatch")).unwrap(),
        array
    );
    ok(&[&again[..], &["--force"]].concat());
    let replaced = std::fs::read_to_string(d.join("array.sbatch")).unwrap();
    assert!(replaced.contains("#SBATCH --array=0-1"), "{replaced}");
    let out = spinball(&[
        "slurm",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--ics",
        "4",
        "--shards",
        "5",
        "--force",
        "--dir",
        d.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn spectrum_shards_merge_bitwise() {
    let dir = scratch("spectrum");
    let args = [
        "spectrum",
        "--table",
        "sinai:L=2,R=1",
        "--alpha",
        "0.5",
        "--ics",
        "9",
        "--collisions",
        "300",
        "--quiet",
    ];
    let whole = dir.join("whole.json");
    ok(&[args.as_slice(), &["--json", whole.to_str().unwrap()]].concat());
    let parts: Vec<String> = (0..3)
        .map(|k| {
            let p = dir.join(format!("s{k}.json"));
            let shard = format!("{k}/3");
            ok(&[
                args.as_slice(),
                &["--shard", &shard, "--json", p.to_str().unwrap()],
            ]
            .concat());
            p.to_str().unwrap().to_string()
        })
        .collect();
    let merged = dir.join("merged.json");
    ok(&[
        "merge",
        "--quiet",
        &parts[2],
        &parts[0],
        &parts[1],
        "--json",
        merged.to_str().unwrap(),
    ]);
    let (a, b) = (read(&whole), read(&merged));
    assert_eq!(a["points"][0]["n_ics"], 9);
    assert_eq!(without_wall_time(&a), without_wall_time(&b));
    let out = spinball(&["merge", &parts[0], &parts[2]]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("missing"));
}

#[test]
fn merge_help_says_what_its_json_is() {
    let out = ok(&["merge", "--help"]);
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(help.contains("Write the merged result as JSON"), "{help}");
    assert!(!help.contains("A sharded run writes its partial"), "{help}");
}
