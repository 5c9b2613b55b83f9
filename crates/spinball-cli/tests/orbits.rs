//! `spinball orbits`: the period-2 orbits of the Sinai table and where the
//! axis orbit turns elliptic (α = ℓ/(ℓ + 4R) = 1/5, docs/PHASE_SPACE.md).

mod common;

use common::{scratch, spinball};

#[test]
fn orbits_finds_the_sinai_axis_orbit_turning_elliptic_at_one_fifth() {
    let dir = scratch("orbits");
    let json = dir.join("orbits.json");
    let csv = dir.join("orbits.csv");
    let out = spinball(&[
        "orbits",
        "--table",
        "sinai:L=2,R=1",
        "--period",
        "2",
        "--alpha-range",
        "0,1,12",
        "--precision",
        "1e-9",
        "--normal-samples",
        "512",
        "--json",
        json.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("(hyperbolic -> elliptic)"), "{stdout}");
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let branches = doc["diagram"]["branches"].as_array().unwrap();
    let change = branches
        .iter()
        .flat_map(|b| b["changes"].as_array().unwrap())
        // The bisected one (the flats' families are parabolic at α = 0 itself).
        .find(|c| c["crossing"] == 2.0 && c["error"].as_f64().unwrap() > 0.0)
        .unwrap();
    let (alpha, error) = (
        change["alpha"].as_f64().unwrap(),
        change["error"].as_f64().unwrap(),
    );
    assert!(
        error <= 1e-9 && (alpha - 0.2).abs() <= error + 1e-12,
        "{change}"
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert!(lines.next().unwrap().starts_with("orbit,alpha,period,s,"));
    // 13 α per orbit.
    assert_eq!(lines.count(), 13 * branches.len());
}

#[test]
fn orbits_refuses_a_bad_range() {
    let out = spinball(&["orbits", "--table", "stadium:a=1", "--alpha-range", "0,1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("FROM,TO,STEPS"));
}

#[test]
fn orbits_islands_adds_the_island_area() {
    // Sinai L = 2, R = 1 at α = 0.1 (axis orbit hyperbolic: area 0) and
    // α = 0.5 (elliptic: an island, 0.55 ± 0.10 at 41 cells,
    // docs/PHASE_SPACE.md).
    let dir = scratch("orbits-islands");
    let json = dir.join("orbits.json");
    let csv = dir.join("orbits.csv");
    let out = spinball(&[
        "orbits",
        "--table",
        "sinai:L=2,R=1",
        "--alpha-range",
        "0.1,0.5,1",
        "--normal-samples",
        "512",
        "--islands",
        "--island-cells",
        "21",
        "--json",
        json.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("island area"));
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .ends_with(",residual,island_area,island_error")
    );
    // The axis orbit through s = L = 2 (walls: bottom box wall, disk).
    let axis: Vec<Vec<&str>> = lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|r| (r[3].parse::<f64>().unwrap() - 2.0).abs() < 1e-9)
        .collect();
    assert_eq!(axis.len(), 2, "{text}");
    assert_eq!(
        (axis[0][7], axis[0][13], axis[0][14]),
        ("hyperbolic", "0", "0")
    );
    assert_eq!(axis[1][7], "elliptic");
    let (area, error): (f64, f64) = (axis[1][13].parse().unwrap(), axis[1][14].parse().unwrap());
    assert!(area > 0.2 && error < 0.5 * area, "{area} ± {error}");
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let islands = doc["islands"].as_array().unwrap();
    assert_eq!(
        islands.len(),
        doc["diagram"]["branches"].as_array().unwrap().len()
    );
}
