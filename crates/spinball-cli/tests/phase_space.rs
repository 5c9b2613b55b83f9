//! `spinball section`, `ftle-map` and `kac` end to end: the outputs hold
//! what their help says, FTLE map shards merge into the unsharded map
//! bitwise, and bad input is exit code 2 before any computing.

mod common;
use common::{ok, scratch, spinball};

use std::path::Path;

use serde_json::Value;

/// Exit code 2 with `words` in the message.
fn usage(args: &[&str], words: &str) {
    let out = spinball(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "spinball {args:?}: {err}");
    assert!(err.contains(words), "spinball {args:?}: {err}");
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The shape in an NPY file's header, as written (`(3, 8)`).
fn npy_shape(path: &Path) -> String {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..6], b"\x93NUMPY");
    let header = String::from_utf8_lossy(&bytes[10..128.min(bytes.len())]).to_string();
    let start = header.find("'shape': ").unwrap() + 9;
    let end = header[start..].find(')').unwrap() + start + 1;
    header[start..end].replace(", )", ")")
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

#[test]
fn section_outputs_agree_and_invariant_starts_are_on_the_shell() {
    let dir = scratch("section");
    let (json, csv, npy) = (dir.join("s.json"), dir.join("s.csv"), dir.join("s.npy"));
    let base = [
        "section",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0.5",
        "--orbits",
        "3",
        "--collisions",
        "50",
    ];
    // Without a file, the CSV goes to stdout.
    let out = ok(&base);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("orbit,s,sin_theta,v_par,speed,u,wall,q\n"));
    assert_eq!(text.lines().count(), 1 + 3 * 50);
    let mut args = base.to_vec();
    args.extend([
        "--sampler",
        "invariant",
        "--json",
        s(&json),
        "--csv",
        s(&csv),
        "--npy",
        s(&npy),
    ]);
    ok(&args);
    let doc = read(&json);
    assert_eq!(doc["kind"], "spinball.section");
    assert_eq!(doc["version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(doc["table"]["name"], "stadium:a=1");
    assert_eq!(doc["sampler"], "invariant");
    let col = |name: &str| -> Vec<f64> {
        doc["columns"][name]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    let (speed, u) = (col("speed"), col("u"));
    assert_eq!(speed.len(), 150);
    // Starts from the invariant measure are on the shell |v|² + αu² = 1,
    // which the flow keeps (energy conservation, to rounding).
    for (v, u) in speed.iter().zip(&u) {
        assert!((v * v + 0.5 * u * u - 1.0).abs() < 1e-12);
    }
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 151);
    assert_eq!(npy_shape(&npy), "(150, 8)");
    // A spin slice keeps only the points with |√α u| < W.
    let mut sliced = args.clone();
    sliced.extend(["--spin-slice", "0.2"]);
    ok(&sliced);
    let kept = read(&json)["columns"]["u"].as_array().unwrap().len();
    let inside = u
        .iter()
        .filter(|u| (0.5f64.sqrt() * **u).abs() < 0.2)
        .count();
    assert_eq!(kept, inside);
    assert!(kept > 0 && kept < 150);
}

#[test]
fn section_refuses_bad_input_before_the_run() {
    let base = ["section", "--table", "stadium:a=1", "--alpha", "0.5"];
    let with = |extra: &[&'static str]| [&base[..], extra].concat();
    usage(&with(&["--spin-slice", "0"]), "half-width");
    usage(&with(&["--orbits", "0"]), "orbits");
    usage(&with(&["--sampler", "nope"]), "sampler");
    usage(
        &["section", "--table", "stadium:a=1", "--alpha", "1.5"],
        "--extended",
    );
    usage(
        &with(&["--csv", "/nonexistent-dir/x.csv"]),
        "does not exist",
    );
}

const MAP: [&str; 14] = [
    "ftle-map",
    "--table",
    "stadium:a=1",
    "--alpha",
    "0.5",
    "--columns",
    "32",
    "--rows",
    "16",
    "--collisions",
    "1000",
    "--seed",
    "5",
    "--quiet",
];

#[test]
fn ftle_map_shards_merge_bitwise_and_the_island_is_predicted() {
    let dir = scratch("ftle-map");
    let whole = dir.join("whole.json");
    let npy = dir.join("map.npy");
    let mut args = MAP.to_vec();
    args.extend(["--json", s(&whole), "--npy", s(&npy)]);
    ok(&args);
    let doc = read(&whole);
    assert_eq!(doc["kind"], "spinball.ftle_map");
    assert_eq!(doc["version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(npy_shape(&npy), "(16, 32)");
    // The bouncing-ball island of the spinning stadium: the cells the
    // rotation 4·arctan √α traps between the flats are regular (as in the
    // library's island-map test: all of them at 32 × 32, 1000 collisions).
    let cells = doc["predicted_cells"].as_u64().unwrap();
    assert!(cells > 0);
    assert_eq!(doc["predicted_regular"].as_u64().unwrap(), cells);
    assert_eq!(doc["predicted"].as_array().unwrap().len(), 32 * 16);
    // Three shards, merged in any order: the same map, bitwise.
    let mut parts = Vec::new();
    for k in 0..3 {
        let part = dir.join(format!("part{k}.json"));
        let shard = format!("{k}/3");
        let mut args = MAP.to_vec();
        args.extend(["--shard", &shard, "--json", s(&part)]);
        ok(&args);
        assert_eq!(read(&part)["kind"], "spinball.ftle_map.partial");
        parts.push(part);
    }
    let merged = dir.join("merged.json");
    ok(&[
        "merge",
        s(&parts[2]),
        s(&parts[0]),
        s(&parts[1]),
        "--json",
        s(&merged),
        "--quiet",
    ]);
    assert_eq!(read(&merged), doc);
    // A missing shard, or a shard of another map, is refused by name.
    usage(&["merge", s(&parts[0]), s(&parts[2])], "are missing");
    let other = dir.join("other.json");
    let mut args = MAP.to_vec();
    args[12] = "6";
    args.extend(["--shard", "1/3", "--json", s(&other)]);
    ok(&args);
    usage(
        &["merge", s(&parts[0]), s(&other), s(&parts[2])],
        "seed 5 in one, 6 in the other",
    );
}

#[test]
fn ftle_map_at_fixed_q_and_its_errors() {
    let dir = scratch("ftle-map-q");
    let csv = dir.join("q.csv");
    let base = [
        "ftle-map",
        "--table",
        "sinai:L=2,R=1",
        "--alpha",
        "0.5",
        "--columns",
        "8",
        "--rows",
        "8",
        "--collisions",
        "200",
    ];
    let with = |extra: &[&'static str]| [&base[..], extra].concat();
    let out = ok(&[&base[..], &["--q", "0.3", "--csv", s(&csv)]].concat());
    let line = String::from_utf8(out.stdout).unwrap();
    assert!(line.contains("cells regular"), "{line}");
    // No flats on the Sinai table: no prediction.
    assert!(!line.contains("bouncing-ball"), "{line}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("s,row,ftle\n"));
    // At fixed Q some cells are off the energy shell: fewer rows than cells.
    let rows = text.lines().count() - 1;
    assert!(rows > 2 && rows < 64, "{rows}");
    usage(
        &with(&["--q", "0.3", "--spin", "0.1"]),
        "cannot be used with",
    );
    usage(
        &[
            "ftle-map",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0",
            "--q",
            "0.1",
        ],
        "α > 0",
    );
    usage(&with(&["--spin", "2"]), "αu² < 1");
    usage(&with(&["--shard", "0/2"]), "--shard needs --json");
    usage(&with(&["--columns", "0"]), "columns");
    usage(
        &with(&["--json", "/nonexistent-dir/m.json"]),
        "does not exist",
    );
}

#[test]
fn kac_ratio_is_one_on_the_ergodic_stadium() {
    let dir = scratch("kac");
    let (json, csv, npy) = (dir.join("k.json"), dir.join("k.csv"), dir.join("k.npy"));
    // The specular stadium is ergodic: the mean return time to the bottom
    // flat at |v∥| < ½ is Kac's 1/μ(A) (the library's doc example, same
    // orbits, collisions and seed: ratio within 0.1 of 1).
    ok(&[
        "kac",
        "--table",
        "stadium:a=1",
        "--alpha",
        "0",
        "--s",
        "0,2",
        "--v-par",
        "-0.5,0.5",
        "--orbits",
        "8",
        "--collisions",
        "20000",
        "--json",
        s(&json),
        "--csv",
        s(&csv),
        "--npy",
        s(&npy),
        "--quiet",
    ]);
    let doc = read(&json);
    assert_eq!(doc["kind"], "spinball.kac");
    let expected = 2.0 * (4.0 + 2.0 * std::f64::consts::PI) / 2.0;
    let kac = &doc["comparison"];
    assert!((kac["expected"].as_f64().unwrap() - expected).abs() < 1e-12);
    let ratio = doc["ratio"]["value"].as_f64().unwrap();
    assert!((ratio - 1.0).abs() < 0.1, "{ratio}");
    assert_eq!(kac["orbits"].as_array().unwrap().len(), 8);
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("index,collisions,visits,mean_return,ratio\n"));
    assert_eq!(text.lines().count(), 9);
    assert_eq!(npy_shape(&npy), "(8, 4)");
}

#[test]
fn kac_refuses_bad_regions() {
    let base = ["kac", "--table", "stadium:a=1", "--alpha", "0"];
    let with = |extra: &[&'static str]| [&base[..], extra].concat();
    usage(&base, "--s");
    usage(&with(&["--s", "3,2"]), "not a range");
    // At α = 0 the spin is 0: a w range without 0 has zero measure.
    usage(
        &with(&["--s", "0,2", "--w", "0.2,0.4"]),
        "zero invariant measure",
    );
    usage(&with(&["--s", "0,2", "--orbits", "1"]), "orbits");
}

/// Run `base` whole and in three shards merged out of order: the merged
/// JSON, CSV and NPY are byte for byte those of the whole run; a missing
/// shard and a shard of another seed are refused.
fn shards_merge_bitwise(name: &str, base: &[&str], kind: &str) {
    let dir = scratch(name);
    let files = |stem: &str| ["json", "csv", "npy"].map(|ext| dir.join(format!("{stem}.{ext}")));
    let outputs = |f: &'_ [std::path::PathBuf; 3]| -> Vec<String> {
        let mut words = Vec::new();
        for (flag, path) in ["--json", "--csv", "--npy"].iter().zip(f) {
            words.extend([flag.to_string(), s(path).to_string()]);
        }
        words.push("--quiet".into());
        words
    };
    let whole = files("whole");
    let whole_outputs = outputs(&whole);
    let mut args = base.to_vec();
    args.extend(whole_outputs.iter().map(String::as_str));
    ok(&args);
    let mut parts = Vec::new();
    for k in 0..3 {
        let part = dir.join(format!("part{k}.json"));
        let shard = format!("{k}/3");
        let mut args = base.to_vec();
        args.extend(["--shard", &shard, "--json", s(&part), "--quiet"]);
        ok(&args);
        assert_eq!(read(&part)["kind"], format!("{kind}.partial"));
        parts.push(part);
    }
    let merged = files("merged");
    let merged_outputs = outputs(&merged);
    let mut args = vec!["merge", s(&parts[1]), s(&parts[2]), s(&parts[0])];
    args.extend(merged_outputs.iter().map(String::as_str));
    ok(&args);
    assert_eq!(read(&merged[0])["kind"], kind);
    for (a, b) in whole.iter().zip(&merged) {
        assert_eq!(
            std::fs::read(a).unwrap(),
            std::fs::read(b).unwrap(),
            "{b:?}"
        );
    }
    usage(&["merge", s(&parts[0]), s(&parts[2])], "missing");
    let other = dir.join("other.json");
    let mut args = base.to_vec();
    args.extend(["--seed", "9", "--shard", "1/3", "--json", s(&other)]);
    ok(&args);
    usage(
        &["merge", s(&parts[0]), s(&other), s(&parts[2])],
        "seed 0 in one, 9 in another",
    );
    usage(
        &["merge", s(&parts[0]), s(&dir.join("map-missing.json"))],
        "cannot read",
    );
    let mut args = base.to_vec();
    args.extend(["--shard", "0/2"]);
    usage(&args, "--shard needs --json");
}

#[test]
fn section_shards_merge_bitwise() {
    shards_merge_bitwise(
        "section-shards",
        &[
            "section",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--orbits",
            "7",
            "--collisions",
            "60",
            "--spin-slice",
            "0.6",
        ],
        "spinball.section",
    );
}

#[test]
fn kac_shards_merge_bitwise() {
    shards_merge_bitwise(
        "kac-shards",
        &[
            "kac",
            "--table",
            "stadium:a=1",
            "--alpha",
            "0.5",
            "--s",
            "0,2",
            "--orbits",
            "7",
            "--collisions",
            "500",
        ],
        "spinball.kac",
    );
}
