//! The kernels on the portable lanes against one lane, and their operation
//! counts per collision step.

use spinball_core::{Sampler, SpinLaw};
use spinball_geometry::Stadium;

use super::*;
use crate::geom::LaneStadium;
use crate::isa::Baseline;
use crate::lanes::Wide;
use crate::paused::Partner;

/// The portable lane type (used off x86) gives the numbers of the
/// one-lane reference, tails included.
#[test]
fn portable_lanes_match_one_lane() {
    let table = Stadium::new(1.0).unwrap();
    let law = SpinLaw::new(0.4).unwrap();
    let g = LaneStadium::new(table.a());
    let l = Law::new(&law);
    let ins: Vec<(State, TangentVector)> = (0..11)
        .map(|i| {
            let s = Sampler::Paper.initial_state(&table, &law, 3, i);
            (s, TangentVector::from_array([0.6, -0.2, 0.1, 0.7, 0.3]))
        })
        .collect();
    let starts: Vec<State> = ins.iter().map(|x| x.0).collect();
    let unit = |j: usize| {
        let mut z = [0.0; 5];
        z[j] = 1.0;
        TangentVector::from_array(z)
    };
    let frames: Vec<(State, [TangentVector; 5])> = ins
        .iter()
        .map(|x| (x.0, std::array::from_fn(unit)))
        .collect();
    let plain = Plain { collisions: 500 };
    assert_eq!(
        run_chunks::<_, _, Wide<f64, 3>, _>(Baseline, &g, &l, &plain, &starts),
        run_chunks::<_, _, f64, _>(Baseline, &g, &l, &plain, &starts)
    );
    let fd = FiniteDifference {
        collisions: 500,
        delta0: 1e-7,
        inv_units: [1.0; 5],
    };
    let shadows: Vec<Paused> = ins
        .iter()
        .map(|(s, d)| {
            let (z, d) = (s.to_array(), d.to_array());
            let shadow = std::array::from_fn(|c| z[c] + d[c] * 1e-7);
            Paused::launched(*s, shadow, Partner::Shadow { delta0: 1e-7 })
        })
        .collect();
    assert_eq!(
        run_chunks::<_, _, Wide<f64, 4>, _>(Baseline, &g, &l, &fd, &shadows),
        run_chunks::<_, _, f64, _>(Baseline, &g, &l, &fd, &shadows)
    );
    let units = Units::new(&table, &ins[0].0, &law);
    let tangent = Tangent {
        collisions: 500,
        units,
    };
    let vectors: Vec<Paused> = ins
        .iter()
        .map(|(s, d)| {
            let from = units.measure(d);
            Paused::launched(*s, d.to_array(), Partner::Tangent { from })
        })
        .collect();
    assert_eq!(
        run_chunks::<_, _, Wide<f64, 4>, _>(Baseline, &g, &l, &tangent, &vectors),
        run_chunks::<_, _, f64, _>(Baseline, &g, &l, &tangent, &vectors)
    );
    let spectrum = Spectrum {
        collisions: 500,
        qr_interval: 3,
    };
    assert_eq!(
        run_chunks::<_, _, Wide<f64, 2>, _>(Baseline, &g, &l, &spectrum, &frames),
        run_chunks::<_, _, f64, _>(Baseline, &g, &l, &spectrum, &frames)
    );
}

/// Operations per collision step of each kernel, counted with a
/// one-lane counting type over 20 000 steps (α = 0.5): the stadium
/// `a = 1` and the Sinai table `L = 2, R = 1` built in, and the tables
/// built from segments of `lanes_speed` (stadium, mushroom, 20-gon). The
/// numbers behind the "floor" and the division tables of
/// docs/PERFORMANCE.md; run with `--nocapture` to see them.
#[test]
fn operation_counts_per_step() {
    use spinball_geometry::Sinai;

    use crate::geom::{LaneSegments, LaneSinai, segment_tables};

    let law = SpinLaw::new(0.5).unwrap();
    let l = Law::new(&law);
    // [plain, fd, tangent, spectrum] × [div, sqrt] per step.
    let stadium = Stadium::new(1.0).unwrap();
    let c = counts("stadium", &stadium, &LaneStadium::new(1.0), &l, &law);
    // One division per cast (the chosen fraction) and one square root
    // (the cap's discriminant); the fallback of the circle contact never
    // runs. Finite differences add the shadow's cast, its shell and
    // δ0/δ with δ's square root; the tangent map adds 1/(n·v); the
    // spectrum five 1/|v_i| and five |v_i| of Gram–Schmidt.
    assert_eq!(c, [[1.0, 1.0], [4.0, 3.0], [2.0, 1.0], [7.0, 6.0]]);
    let sinai = Sinai::new(2.0, 1.0).unwrap();
    let c = counts("sinai", &sinai, &LaneSinai::new(2.0, 1.0), &l, &law);
    assert_eq!(c, [[1.0, 1.0], [4.0, 3.0], [2.0, 1.0], [7.0, 6.0]]);

    let seg_stadium = segment_tables::stadium(1.0);
    let ls = LaneSegments::new(&seg_stadium);
    let c = counts("seg-stadium", &seg_stadium, &ls.view::<true>(), &l, &law);
    // With arcs too, one division per cast (the chosen wall's fraction:
    // every arc's denominator is |v|²) and a square root per arc; the
    // fallback of the winning arc's contact never runs.
    assert_eq!(c[0], [1.0, 2.0]);
    let mushroom = segment_tables::mushroom(1.0, 0.3, 1.0);
    let lm = LaneSegments::new(&mushroom);
    let c = counts("mushroom", &mushroom, &lm.view::<true>(), &l, &law);
    assert_eq!(c[0], [1.0, 1.0]);
    let gon = segment_tables::alternating_twenty_gon();
    let lg = LaneSegments::new(&gon);
    let c = counts("20-gon", &gon, &lg.view::<false>(), &l, &law);
    // Without arcs: one division per cast, however many walls.
    assert_eq!(c[0], [1.0, 0.0]);
}

/// Runs the four kernels on `table` with the counting lane type and
/// prints every operation per step; returns divisions and square roots
/// per step of each, to 0.01.
fn counts<B: spinball_geometry::Boundary, G: Geom>(
    name: &str,
    table: &B,
    g: &G,
    l: &Law,
    law: &SpinLaw,
) -> [[f64; 2]; 4] {
    use crate::lanes::counted::{Counted, take};
    const N: u64 = 20_000;
    let s = Sampler::Paper.initial_state(table, law, 1, 0);
    let d = TangentVector::from_array([0.6, -0.2, 0.1, 0.7, 0.3]);
    let unit = |j: usize| {
        let mut z = [0.0; 5];
        z[j] = 1.0;
        TangentVector::from_array(z)
    };
    let names = [
        "add/sub",
        "mul",
        "div",
        "sqrt",
        "cmp/max/abs",
        "select",
        "mask",
        "bits",
    ];
    // Per trajectory: a kernel of several streams runs that many copies
    // of the one state in a chunk.
    let report = |kernel: &str, streams: usize| {
        let c = take().map(|k| k / streams as u64);
        let per: Vec<String> = names
            .iter()
            .zip(c)
            .map(|(n, k)| format!("{n} {:.2}", k as f64 / N as f64))
            .collect();
        println!("{name:<12} {kernel:<9} per step: {}", per.join(", "));
        // To 0.01 per step: the launch's and the end's few operations
        // (1/|V|², the final norm) vanish.
        let per_step = |k: u64| (k as f64 / N as f64 * 100.0).round() / 100.0;
        [per_step(c[2]), per_step(c[3])]
    };
    take();
    run_chunks::<_, _, Counted, _>(Baseline, g, l, &Plain { collisions: N }, &[s]);
    let plain = report("plain", Plain::STREAMS);
    let fd = FiniteDifference {
        collisions: N,
        delta0: 1e-7,
        inv_units: [1.0; 5],
    };
    let (z, dz) = (s.to_array(), d.to_array());
    let shadow = std::array::from_fn(|c| z[c] + dz[c] * 1e-7);
    let launched = Paused::launched(s, shadow, Partner::Shadow { delta0: 1e-7 });
    run_chunks::<_, _, Counted, _>(Baseline, g, l, &fd, &[launched]);
    let fd = report("fd", 1);
    run_chunks::<_, _, Counted, _>(
        Baseline,
        g,
        l,
        &Tangent {
            collisions: N,
            units: Units::new(table, &s, law),
        },
        &[Paused::launched(
            s,
            d.to_array(),
            Partner::Tangent {
                from: Units::new(table, &s, law).measure(&d),
            },
        )],
    );
    let tangent = report("tangent", 1);
    let spectrum = Spectrum {
        collisions: N,
        qr_interval: 1,
    };
    run_chunks::<_, _, Counted, _>(Baseline, g, l, &spectrum, &[(s, std::array::from_fn(unit))]);
    let spectrum = report("spectrum", 1);
    [plain, fd, tangent, spectrum]
}

/// The escape kernel refills its lanes as balls end: which lane runs a
/// ball, and after which others, changes no record (one lane against
/// three, 37 starts, budgets in collisions and in time).
#[test]
fn escape_records_do_not_depend_on_the_lanes_a_ball_runs_in() {
    use spinball_geometry::SegmentTable;

    use crate::geom::LaneSegments;

    let table =
        SegmentTable::stadium_with_hole(1.0, 2.0 + 0.5 * std::f64::consts::PI, 0.3).unwrap();
    let law = SpinLaw::new(0.4).unwrap();
    let l = Law::new(&law);
    let ls = LaneSegments::new(&table);
    let g = ls.view::<true>();
    let holes: Vec<f64> = table
        .kinds()
        .iter()
        .enumerate()
        .filter(|(_, k)| k.is_hole())
        .map(|(i, _)| i as f64)
        .collect();
    assert_eq!(holes.len(), 1);
    let starts: Vec<State> = (0..37)
        .map(|i| Sampler::Paper.initial_state(&table, &law, 3, i))
        .collect();
    for (collisions, time) in [(200, f64::INFINITY), (u64::MAX, 30.0)] {
        let k = Escape {
            collisions,
            time,
            holes: &holes,
        };
        let one = run_chunks::<_, _, f64, _>(Baseline, &g, &l, &k, &starts);
        let three = run_chunks::<_, _, Wide<f64, 3>, _>(Baseline, &g, &l, &k, &starts);
        assert_eq!(three, one);
        assert_eq!(one.len(), starts.len());
        assert!(one.iter().any(|e| e.escaped) && one.iter().any(|e| !e.escaped));
    }
}
