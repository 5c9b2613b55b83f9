//! The lane kernels against the scalar path, on every table, spin law and
//! instruction set this CPU has.
//!
//! - Plain trajectories are **bitwise** `Billiard::step` (end states by `==`,
//!   which leaves only the sign of a zero open; times by their bits), over
//!   long runs: the lanes perform the same floating-point operations.
//! - Finite differences: the reference and shadow trajectories are bitwise
//!   the scalar ones (`Billiard::step`, the shadow put back along the
//!   separation), so `Σ ln(δ/δ0)` differs only by how the product of the
//!   factors is rounded: a few ulps per factor.
//! - Exact tangent: the tangent map is bitwise `Billiard::step_tangent`;
//!   with the scalar vector rescaled by exact powers of two too, the lanes'
//!   vector is the scalar's times a power of two and `Σ ln` agrees to the
//!   rounding of the final `ln`, grazing starts included.
//! - Spectrum: the same tangent map and Gram–Schmidt as the scalar;
//!   differences from the product of `R_ii` only.
//!
//! The comparison with the exponents of `spinball-analysis`
//! (`largest_lyapunov`, `lyapunov_spectrum`, which normalise every step) is
//! in `crates/spinball-analysis/tests/lane_agreement.rs`: this crate cannot
//! depend on that one.
//!
//! Start sets include the paper's and the microcanonical samplers, balls
//! shot exactly into corners (rectangle, Sinai box) and junctions
//! (stadium), and near-grazing rays along flat walls and past the Sinai
//! disk; counts are not multiples of any lane count (tails).
//!
//! Tables built from segments (`SegmentTable`) are held to the same
//! standard: the stadium and the Sinai table written as segments, the
//! mushroom, an L-shaped polygon, a 12-gon and a 20-gon, with starts into their
//! corners, junctions and re-entrant corners and grazing their walls.

use spinball_core::{
    Ball, Billiard, Pcg64, Perturbation, SpinLaw, State, StepError, TangentVector, Units,
};
use spinball_geometry::{
    ArcSegment, Boundary, DVec2, LineSegment, Rectangle, Segment, SegmentTable, Sinai, Stadium,
    Table,
};
use spinball_lanes::{Isa, LaneBilliard, LanesError};
use spinball_test_support::lanes::{
    close, draw, frame_from, ics, lanes_for, laws, scalar_end, special, tables,
};

#[test]
fn special_starts_do_hit_corners_and_junctions() {
    // The special starts are what they claim: the scalar sees zero-time
    // (corner) collisions in the boxes and junction contacts in the stadium.
    let law = SpinLaw::new(0.4).unwrap();
    for table in [
        Table::from(Rectangle::square()),
        Sinai::new(2.0, 1.0).unwrap().into(),
    ] {
        let billiard = Billiard::new(table, law);
        let mut ball = billiard.launch(special(&table)[0]).unwrap();
        billiard.step(&mut ball).unwrap();
        assert_eq!(billiard.step(&mut ball).unwrap().time(), 0.0, "{table}");
    }
    let table = Table::from(Stadium::new(1.0).unwrap());
    let billiard = Billiard::new(table, law);
    let mut ball = billiard.launch(special(&table)[0]).unwrap();
    let c = billiard.step(&mut ball).unwrap();
    assert_eq!(c.point(), DVec2::new(1.0, 1.0));
}

/// The starts of `ics` that keep moving for `collisions` collisions on the
/// scalar path. A start that gets stuck there (a ball pinned at a
/// re-entrant corner or a junction, more than `MAX_ZERO_TIME_RUN`
/// zero-time collisions in a row: `StepError::Stuck`, issue 9) must fail on
/// every instruction set too (`LanesError::NonFinite`), and is left out of
/// the comparisons.
fn moving<B: Boundary + Clone>(
    table: &B,
    name: &str,
    law: &SpinLaw,
    ics: &[(State, TangentVector, Pcg64)],
    collisions: u64,
) -> Vec<(State, TangentVector, Pcg64)> {
    let billiard = Billiard::new(table, *law);
    let (keep, stuck): (Vec<_>, Vec<_>) = ics.iter().cloned().partition(|(s, _, _)| {
        let mut ball = billiard.launch(*s).unwrap();
        match billiard.run(&mut ball, collisions, &mut ()) {
            Ok(_) => true,
            Err(StepError::Stuck { .. }) => false,
            Err(e) => panic!("{name} α={}: {e}", law.alpha()),
        }
    });
    for (s, d, _) in &stuck {
        for lanes in lanes_for(table, law) {
            let what = format!("{name} α={} {} stuck start {s:?}", law.alpha(), lanes.isa());
            assert_eq!(
                lanes.trajectories(&[*s], collisions).unwrap_err(),
                LanesError::NonFinite { index: 0 },
                "{what}"
            );
            assert_eq!(
                lanes
                    .lyapunov_tangent(&[*s], &[*d], collisions)
                    .unwrap_err(),
                LanesError::NonFinite { index: 0 },
                "{what}"
            );
        }
    }
    keep
}

/// Plain trajectories of `ics` on every instruction set: end states and
/// times bitwise `Billiard::step`'s.
fn assert_plain<B: Boundary + Clone>(
    table: &B,
    name: &str,
    law: &SpinLaw,
    ics: &[(State, TangentVector, Pcg64)],
    collisions: u64,
) {
    let ics = &moving(table, name, law, ics, collisions);
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let want: Vec<(State, f64)> = starts
        .iter()
        .map(|s| scalar_end(table, law, *s, collisions))
        .collect();
    for lanes in lanes_for(table, law) {
        let got = lanes.trajectories(&starts, collisions).unwrap();
        assert_eq!(got.len(), starts.len());
        for (i, (g, (end, time))) in got.iter().zip(&want).enumerate() {
            let what = format!("{name} α={} {} ic {i}", law.alpha(), lanes.isa());
            assert_eq!(g.end, *end, "{what}");
            assert_eq!(g.time.to_bits(), time.to_bits(), "{what}");
            assert_eq!(g.collisions, collisions);
        }
    }
}

/// Finite differences of `ics` on every instruction set against the
/// scalar method written out with `spinball-core` (as `largest_lyapunov`
/// runs it): the shadow starts `Perturbation::offset` away, the reference
/// and the shadow take their own `Billiard::step`, the separation is
/// measured in units (`Perturbation::distance`) and the shadow put back
/// `δ0` from the reference along it. Times and end states bitwise, `Σ ln` to `1e-12`
/// (the lanes differ only by the rounding of the product of the factors).
fn assert_fd<B: Boundary + Clone>(
    table: &B,
    name: &str,
    law: &SpinLaw,
    ics: &[(State, TangentVector, Pcg64)],
    collisions: u64,
) {
    const DELTA0: f64 = 1e-7;
    let ics = &moving(table, name, law, ics, collisions);
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
    let billiard = Billiard::new(table, *law);
    let offset = |z: &State, d: TangentVector| {
        let (z, d) = (z.to_array(), d.to_array());
        State::from_array(std::array::from_fn(|i| z[i] + d[i]))
    };
    let want: Vec<(f64, f64, State)> = ics
        .iter()
        .map(|(s, dir, _)| {
            let mut ball = billiard.launch(*s).unwrap();
            // δ0 in units of the table and the speed (issue 9).
            let p = Perturbation::new(table, s, law, DELTA0).unwrap();
            let mut shadow = Ball::new(offset(s, p.offset(*dir)), law).unwrap();
            let (mut log, mut time) = (0.0, 0.0);
            for _ in 0..collisions {
                time += billiard.step(&mut ball).unwrap().time();
                billiard.step(&mut shadow).unwrap();
                let (a, b) = (ball.state().to_array(), shadow.state().to_array());
                let d = TangentVector::from_array(std::array::from_fn(|i| b[i] - a[i]));
                let dist = p.distance(&d);
                log += (dist / DELTA0).ln();
                shadow = Ball::new(offset(ball.state(), d * (DELTA0 / dist)), law).unwrap();
            }
            (log, time, *ball.state())
        })
        .collect();
    for lanes in lanes_for(table, law) {
        let got = lanes
            .lyapunov_fd(&starts, &dirs, DELTA0, collisions)
            .unwrap();
        assert_eq!(got.len(), starts.len());
        for (i, (g, (log, time, end))) in got.iter().zip(&want).enumerate() {
            let what = format!("{name} α={} {} ic {i}", law.alpha(), lanes.isa());
            assert_eq!(g.time.to_bits(), time.to_bits(), "time {what}");
            assert_eq!(g.end, *end, "{what}");
            close(g.log_stretch, *log, 1e-12, &what);
        }
    }
}

/// `v` scaled by the power of two that brings its largest component into
/// `[1, 2)` (exact), and the power taken off.
fn pow2_rescale(v: TangentVector) -> (TangentVector, i64) {
    let m = v.to_array().iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let e = (m.to_bits() >> 52) as i64 - 1023;
    (v * f64::from_bits(((1023 - e) as u64) << 52), e)
}

/// Exact tangent dynamics of `ics` on every instruction set against
/// `Billiard::step_tangent` with the vector rescaled by exact powers of two
/// rather than normalised: the tangent map is linear and a power of two
/// scales every rounding exactly, so the lanes' vector is the scalar's times
/// a power of two, bit for bit, and `Σ ln` differs only by the rounding of
/// the final `ln` — even for grazing starts, whose collisions amplify any
/// difference by `~1/(n·v)`. Times bitwise, `Σ ln` to `1e-12`.
fn assert_tangent<B: Boundary + Clone>(
    table: &B,
    name: &str,
    law: &SpinLaw,
    ics: &[(State, TangentVector, Pcg64)],
    collisions: u64,
) {
    let ics = &moving(table, name, law, ics, collisions);
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
    let billiard = Billiard::new(table, *law);
    let want: Vec<(f64, f64)> = ics
        .iter()
        .map(|(s, dir, _)| {
            let mut ball = billiard.launch(*s).unwrap();
            let mut v = [*dir];
            let (mut powers, mut time) = (0i64, 0.0);
            for _ in 0..collisions {
                time += billiard.step_tangent(&mut ball, &mut v).unwrap().time();
                let (w, e) = pow2_rescale(v[0]);
                v[0] = w;
                powers += e;
            }
            // Both lengths in units (the table's and the speed's).
            let units = Units::new(table, s, law);
            let log = (units.measure(&v[0]) / units.measure(dir)).ln()
                + powers as f64 * std::f64::consts::LN_2;
            (log, time)
        })
        .collect();
    for lanes in lanes_for(table, law) {
        let got = lanes.lyapunov_tangent(&starts, &dirs, collisions).unwrap();
        assert_eq!(got.len(), starts.len());
        for (i, (g, (log, time))) in got.iter().zip(&want).enumerate() {
            let what = format!("{name} α={} {} ic {i}", law.alpha(), lanes.isa());
            assert_eq!(g.time.to_bits(), time.to_bits(), "time {what}");
            close(g.log_stretch, *log, 1e-12, &what);
        }
    }
}

/// The spectrum of `ics` on every instruction set against five vectors
/// through `Billiard::step_tangent` with modified Gram–Schmidt every `qr`
/// collisions and after the last (as `lyapunov_spectrum`): times bitwise,
/// every `Σ ln R_ii` to `1e-10` (rounding of its products and sums).
fn assert_spectrum<B: Boundary + Clone>(
    table: &B,
    name: &str,
    law: &SpinLaw,
    ics: &[(State, TangentVector, Pcg64)],
    collisions: u64,
    qr: u32,
) {
    let ics = &moving(table, name, law, ics, collisions);
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let frames: Vec<[TangentVector; 5]> =
        ics.iter().map(|x| frame_from(&mut x.2.clone())).collect();
    let billiard = Billiard::new(table, *law);
    let want: Vec<([f64; 5], f64)> = starts
        .iter()
        .zip(&frames)
        .map(|(s, frame)| {
            let mut ball = billiard.launch(*s).unwrap();
            let mut v = *frame;
            let (mut logs, mut time) = ([0.0; 5], 0.0);
            for n in 1..=collisions {
                time += billiard.step_tangent(&mut ball, &mut v).unwrap().time();
                if n % u64::from(qr) == 0 || n == collisions {
                    for i in 0..5 {
                        for j in 0..i {
                            let p = v[i].dot(&v[j]);
                            v[i] = v[i] - v[j] * p;
                        }
                        let norm = v[i].norm();
                        v[i] = v[i] * (1.0 / norm);
                        logs[i] += norm.ln();
                    }
                }
            }
            (logs, time)
        })
        .collect();
    for lanes in lanes_for(table, law) {
        let got = lanes.spectrum(&starts, &frames, collisions, qr).unwrap();
        assert_eq!(got.len(), starts.len());
        for (i, (g, (logs, time))) in got.iter().zip(&want).enumerate() {
            let what = format!("{name} α={} qr {qr} {} ic {i}", law.alpha(), lanes.isa());
            assert_eq!(g.time.to_bits(), time.to_bits(), "time {what}");
            for (a, b) in g.log_stretch.iter().zip(logs) {
                close(*a, *b, 1e-10, &what);
            }
        }
    }
}

#[test]
fn plain_trajectories_are_bitwise_the_scalar_step() {
    for table in tables() {
        for law in laws() {
            let ics = ics(&table, &law, 17);
            assert_plain(&table, &table.to_string(), &law, &ics, 2_000);
        }
    }
}

#[test]
fn finite_differences_follow_the_scalar_shadow() {
    for table in tables() {
        for law in laws() {
            let ics = ics(&table, &law, 9);
            assert_fd(&table, &table.to_string(), &law, &ics, 600);
        }
    }
}

#[test]
fn exact_tangent_follows_the_scalar_tangent_map() {
    for table in tables() {
        for law in laws() {
            let ics = ics(&table, &law, 9);
            assert_tangent(&table, &table.to_string(), &law, &ics, 600);
        }
    }
}

#[test]
fn spectrum_follows_the_scalar_tangent_map_and_gram_schmidt() {
    for table in tables() {
        for law in laws() {
            for qr in [1u32, 5] {
                let ics = ics(&table, &law, 4);
                assert_spectrum(&table, &table.to_string(), &law, &ics, 400, qr);
            }
        }
    }
}

#[test]
fn instruction_sets_lane_counts_tails_and_threads_do_not_change_results() {
    let table = Table::from(Sinai::new(2.0, 1.0).unwrap());
    let law = SpinLaw::new(0.4).unwrap();
    let ics = ics(&table, &law, 20);
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
    let frames: Vec<[TangentVector; 5]> =
        ics.iter().map(|x| frame_from(&mut x.2.clone())).collect();
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let run = |lanes: &LaneBilliard, range: std::ops::Range<usize>| {
        let mut out = Vec::new();
        for f in lanes.trajectories(&starts[range.clone()], 300).unwrap() {
            out.extend([f.time, f.end.position.x, f.end.velocity.y, f.end.spin]);
        }
        for s in lanes
            .lyapunov_fd(&starts[range.clone()], &dirs[range.clone()], 1e-7, 300)
            .unwrap()
        {
            out.extend([s.log_stretch, s.time]);
        }
        for s in lanes
            .lyapunov_tangent(&starts[range.clone()], &dirs[range.clone()], 300)
            .unwrap()
        {
            out.extend([s.log_stretch, s.time]);
        }
        for s in lanes
            .spectrum(&starts[range.clone()], &frames[range], 300, 3)
            .unwrap()
        {
            out.extend(s.log_stretch);
        }
        bits(&out)
    };
    let reference = run(
        &LaneBilliard::new(table, law)
            .unwrap()
            .with_isa(Isa::Baseline)
            .unwrap(),
        0..starts.len(),
    );
    for isa in Isa::available() {
        for threads in [1, 2, 3] {
            let lanes = LaneBilliard::new(table, law)
                .unwrap()
                .with_isa(isa)
                .unwrap()
                .with_threads(threads)
                .unwrap();
            assert_eq!(
                run(&lanes, 0..starts.len()),
                reference,
                "{isa} on {threads} threads"
            );
        }
    }
    // One initial condition at a time (all tails) gives the same numbers.
    let lanes = LaneBilliard::new(table, law).unwrap();
    let one_by_one: Vec<_> = (0..starts.len()).map(|i| run(&lanes, i..i + 1)).collect();
    let n = starts.len();
    for (i, r) in one_by_one.iter().enumerate() {
        // Layout of `run`: 4 per trajectory, then 2, 2, 5 per IC.
        assert_eq!(r[..4], reference[4 * i..4 * i + 4]);
        assert_eq!(r[4..6], reference[4 * n + 2 * i..4 * n + 2 * i + 2]);
        assert_eq!(r[6..8], reference[6 * n + 2 * i..6 * n + 2 * i + 2]);
        assert_eq!(r[8..13], reference[8 * n + 5 * i..8 * n + 5 * i + 5]);
    }
}

#[test]
fn inputs_are_checked_like_the_scalar_path() {
    let table = Table::from(Stadium::new(1.0).unwrap());
    let law = SpinLaw::new(0.5).unwrap();
    let lanes = LaneBilliard::new(table, law).unwrap();
    let good = State::new(DVec2::new(0.1, 0.2), DVec2::new(0.6, 0.7), 0.3);
    let outside = State::new(DVec2::new(5.0, 0.0), DVec2::new(0.6, 0.7), 0.3);
    let dir = TangentVector::from_array([0.0, 0.0, 1.0, 0.0, 0.0]);
    assert!(matches!(
        lanes.trajectories(&[good, outside], 10),
        Err(LanesError::Launch { index: 1, .. })
    ));
    assert!(matches!(
        lanes.lyapunov_fd(&[good], &[dir, dir], 1e-7, 10),
        Err(LanesError::InvalidOption { .. })
    ));
    for delta0 in [0.0, -1e-7, f64::NAN, f64::INFINITY] {
        assert!(lanes.lyapunov_fd(&[good], &[dir], delta0, 10).is_err());
    }
    assert!(lanes.lyapunov_tangent(&[good], &[dir], 0).is_err());
    assert!(
        lanes
            .lyapunov_tangent(&[good], &[TangentVector::default()], 10)
            .is_err()
    );
    let frame = [dir; 5];
    assert!(lanes.spectrum(&[good], &[frame], 10, 0).is_err());
    assert!(lanes.spectrum(&[good], &[frame], 10, 33).is_err());
    assert!(lanes.clone().with_threads(0).is_err());
    assert!(lanes.trajectories(&[], 10).unwrap().is_empty());
    for isa in Isa::ALL {
        assert_eq!(
            LaneBilliard::new(table, law).unwrap().with_isa(isa).is_ok(),
            isa.is_available()
        );
    }
}

#[test]
fn a_shadow_that_lands_on_the_reference_fails_as_in_the_scalar_path() {
    // A shadow displaced along the flow hits the same wall point with the
    // same velocity: separation exactly 0 after one collision.
    let table = Table::from(Rectangle::square());
    let law = SpinLaw::new(0.5).unwrap();
    let start = State::new(DVec2::new(0.0, 0.0), DVec2::new(0.8, 0.0), 0.2);
    let dir = TangentVector::from_array([1.0, 0.0, 0.0, 0.0, 0.0]);
    let good = State::new(DVec2::new(0.1, 0.2), DVec2::new(0.6, 0.7), 0.3);
    let billiard = Billiard::new(table, law);
    // The scalar path refuses it (the direction it draws is not this one,
    // so check the separation directly).
    let mut a = billiard.launch(start).unwrap();
    let mut b = billiard
        .launch(State::new(
            DVec2::new(1e-7, 0.0),
            start.velocity,
            start.spin,
        ))
        .unwrap();
    billiard.step(&mut a).unwrap();
    billiard.step(&mut b).unwrap();
    assert_eq!(a.state(), b.state());
    for isa in Isa::available() {
        let lanes = LaneBilliard::new(table, law)
            .unwrap()
            .with_isa(isa)
            .unwrap();
        let r = lanes.lyapunov_fd(&[good, good, start], &[dir, dir, dir], 1e-7, 50);
        assert_eq!(r, Err(LanesError::NonFinite { index: 2 }), "{isa}");
    }
}

#[test]
fn launch_check_uses_the_table() {
    // The start must be inside the table as `Billiard::launch` decides.
    let table = Table::from(Sinai::new(2.0, 1.0).unwrap());
    let law = SpinLaw::new(0.5).unwrap();
    let in_disk = State::new(DVec2::new(0.1, 0.1), DVec2::new(0.6, 0.7), 0.3);
    assert!(!table.contains(in_disk.position));
    assert!(matches!(
        LaneBilliard::new(table, law)
            .unwrap()
            .trajectories(&[in_disk], 5),
        Err(LanesError::Launch { index: 0, .. })
    ));
}

// ------------------------------------------------------- tables of segments

fn line(a: DVec2, b: DVec2) -> Segment {
    Segment::Line(LineSegment::new(a, b).unwrap())
}

fn arc(c: DVec2, r: f64, start: f64, sweep: f64) -> Segment {
    Segment::Arc(ArcSegment::new(c, r, start, sweep).unwrap())
}

/// A table built from segments, with a name and its special starts.
struct Walled {
    name: &'static str,
    table: SegmentTable,
    special: Vec<State>,
}

/// The stadium (a = 1) and the Sinai table (L = 2, R = 1) written as
/// segments, the mushroom of the `SegmentTable` docs, an L-shaped polygon
/// and non-convex 12- and 20-gons, each with starts into its corners and junctions
/// and grazing its walls.
fn segment_tables() -> Vec<Walled> {
    use std::f64::consts::{FRAC_PI_2, PI, TAU};
    let p = DVec2::new;
    let st = |x: f64, y: f64, vx: f64, vy: f64| State::new(p(x, y), p(vx, vy), 0.3);
    let stadium = SegmentTable::new(vec![
        line(p(-1.0, -1.0), p(1.0, -1.0)),
        arc(p(1.0, 0.0), 1.0, -FRAC_PI_2, PI),
        line(p(1.0, 1.0), p(-1.0, 1.0)),
        arc(p(-1.0, 0.0), 1.0, FRAC_PI_2, PI),
    ])
    .unwrap();
    let sinai = SegmentTable::with_holes(
        vec![
            line(p(-2.0, -2.0), p(2.0, -2.0)),
            line(p(2.0, -2.0), p(2.0, 2.0)),
            line(p(2.0, 2.0), p(-2.0, 2.0)),
            line(p(-2.0, 2.0), p(-2.0, -2.0)),
        ],
        vec![vec![arc(DVec2::ZERO, 1.0, 0.0, -TAU)]],
    )
    .unwrap();
    let (r, w, h) = (1.0, 0.3, 1.0);
    let mushroom = SegmentTable::new(vec![
        line(p(-w, -h), p(w, -h)),
        line(p(w, -h), p(w, 0.0)),
        line(p(w, 0.0), p(r, 0.0)),
        arc(DVec2::ZERO, r, 0.0, PI),
        line(p(-r, 0.0), p(-w, 0.0)),
        line(p(-w, 0.0), p(-w, -h)),
    ])
    .unwrap();
    let l_shape = SegmentTable::polygon(&[
        p(0.0, 0.0),
        p(2.0, 0.0),
        p(2.0, 1.0),
        p(1.0, 1.0),
        p(1.0, 2.0),
        p(0.0, 2.0),
    ])
    .unwrap();
    let gon: Vec<DVec2> = (0..20)
        .map(|k| {
            let radius = if k % 2 == 0 {
                1.0
            } else {
                0.8 + 0.01 * k as f64
            };
            DVec2::from_angle(TAU * k as f64 / 20.0) * radius
        })
        .collect();
    let twenty = SegmentTable::polygon(&gon).unwrap();
    // A 12-gon, radii alternating 1 and 0.85: its walls' landing constants
    // fill 16-entry palettes (AVX-512 permutes two registers), where the
    // tables above fill 8 (one register) and the 20-gon 24 (a gather).
    let dozen: Vec<DVec2> = (0..12)
        .map(|k| DVec2::from_angle(TAU * k as f64 / 12.0) * if k % 2 == 0 { 1.0 } else { 0.85 })
        .collect();
    let twelve = SegmentTable::polygon(&dozen).unwrap();
    // Grazing along the 20-gon's wall 3 from just inside its middle.
    let (a, b) = (gon[3], gon[4]);
    let inward = (b - a).perp().normalize();
    let mid = 0.5 * (a + b) + inward * 1e-6;
    // Grazing starts lie 1e-6 inside the wall: the finite-difference
    // shadow, up to δ0 = 1e-7 away, must start inside the table too.
    vec![
        Walled {
            name: "stadium of segments",
            table: stadium,
            special: vec![
                // Into the junctions (1, 1) and (-1, -1), then grazing the
                // flat walls into the caps.
                st(0.0, 0.0, 0.5, 0.5),
                st(0.0, 0.0, -0.5, -0.5),
                st(0.0, 1.0 - 1e-6, 0.8, 1e-9),
                st(0.0, -1.0 + 1e-6, -0.8, 1e-12),
            ],
        },
        Walled {
            name: "sinai of segments",
            table: sinai,
            special: vec![
                // Box corners by exact ties, then grazing the hole.
                st(1.5, 1.5, 0.6, 0.6),
                st(-1.5, 1.5, -0.6, 0.6),
                st(-1.5, 1.0 - 1e-10, 0.8, 0.0),
                st(-1.5, 1.0 + 1e-10, 0.8, 0.0),
                st(1.0 - 1e-12, 1.5, 0.0, -0.8),
            ],
        },
        Walled {
            name: "mushroom",
            table: mushroom,
            special: vec![
                // Into the stem's top corners, along the cap's floor and
                // along the cap, and straight up the stem.
                st(0.0, -0.5, w, 0.5),
                st(0.0, -0.5, -w, 0.5),
                st(0.6, 1e-6, -0.8, -1e-13),
                st(0.0, 1.0 - 1e-6, 0.8, 0.0),
                st(0.0, -0.5, 0.0, 0.8),
            ],
        },
        Walled {
            name: "L-shape",
            table: l_shape,
            special: vec![
                // Into the re-entrant corner (1, 1), the corners (2, 0) and
                // (0, 0), and grazing the floor.
                st(0.5, 0.5, 0.5, 0.5),
                st(0.5, 0.5, 1.5, -0.5),
                st(0.5, 0.5, -0.5, -0.5),
                st(1.5, 1e-6, 0.8, 1e-13),
            ],
        },
        Walled {
            name: "12-gon",
            table: twelve,
            special: vec![
                // Into vertices 0, 7 (re-entrant) and 11.
                st(0.0, 0.0, dozen[0].x, dozen[0].y),
                st(0.0, 0.0, dozen[7].x, dozen[7].y),
                st(0.1, -0.1, dozen[11].x - 0.1, dozen[11].y + 0.1),
            ],
        },
        Walled {
            name: "20-gon",
            table: twenty,
            special: vec![
                st(0.0, 0.0, gon[0].x, gon[0].y),
                st(0.0, 0.0, gon[5].x, gon[5].y),
                st(0.0, 0.0, gon[13].x, gon[13].y),
                st(mid.x, mid.y, (b - a).x, (b - a).y),
            ],
        },
    ]
}

#[test]
fn segment_tables_special_starts_do_hit_corners_and_junctions() {
    let law = SpinLaw::new(0.4).unwrap();
    let tables = segment_tables();
    // (point, wall, time) of collision `n` from the first special start.
    let nth = |t: &Walled, n: usize| {
        let billiard = Billiard::new(&t.table, law);
        let mut ball = billiard.launch(t.special[0]).unwrap();
        let mut c = billiard.step(&mut ball).unwrap();
        for _ in 1..n {
            c = billiard.step(&mut ball).unwrap();
        }
        (c.point(), c.wall(), c.time())
    };
    let p = DVec2::new;
    // The stadium's junction (1, 1), the end of the right cap (wall 1).
    assert_eq!(nth(&tables[0], 1).0, p(1.0, 1.0));
    assert_eq!(nth(&tables[0], 1).1, 1);
    // The Sinai box's corner: the second collision takes no time.
    assert_eq!(nth(&tables[1], 2).2, 0.0);
    // The mushroom's stem corner (w, 0): the end of the stem's side.
    assert_eq!(nth(&tables[2], 1).0, p(0.3, 0.0));
    assert_eq!(nth(&tables[2], 1).1, 1);
    // The L's re-entrant corner: a tie of walls 2 and 3, to the lower id.
    assert_eq!(nth(&tables[3], 1).0, p(1.0, 1.0));
    assert_eq!(nth(&tables[3], 1).1, 2);
}

#[test]
fn segment_tables_plain_trajectories_are_bitwise_the_scalar_step() {
    for t in segment_tables() {
        for law in laws() {
            let ics = draw(&t.table, &law, 17, t.special.clone());
            assert_plain(&t.table, t.name, &law, &ics, 2_000);
        }
    }
}

#[test]
fn segment_tables_finite_differences_follow_the_scalar_shadow() {
    for t in segment_tables() {
        for law in laws() {
            let ics = draw(&t.table, &law, 9, t.special.clone());
            assert_fd(&t.table, t.name, &law, &ics, 600);
        }
    }
}

#[test]
fn segment_tables_exact_tangent_follows_the_scalar_tangent_map() {
    for t in segment_tables() {
        for law in laws() {
            let ics = draw(&t.table, &law, 9, t.special.clone());
            assert_tangent(&t.table, t.name, &law, &ics, 600);
        }
    }
}

#[test]
fn segment_tables_spectrum_follows_the_scalar_tangent_map() {
    for t in segment_tables() {
        for law in laws() {
            for qr in [1u32, 5] {
                let ics = draw(&t.table, &law, 4, t.special.clone());
                assert_spectrum(&t.table, t.name, &law, &ics, 400, qr);
            }
        }
    }
}

#[test]
fn segment_tables_by_reference_on_threads_and_one_by_one_give_the_same_bits() {
    // A borrowed table runs too; threads and one-by-one runs (all tails)
    // give the same bits.
    let t = &segment_tables()[2];
    let law = SpinLaw::new(0.4).unwrap();
    let ics = draw(&t.table, &law, 20, t.special.clone());
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
    let bits = |v: Vec<f64>| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let run = |lanes: &LaneBilliard<&SegmentTable>, r: std::ops::Range<usize>| {
        let mut out = Vec::new();
        for s in lanes
            .lyapunov_tangent(&starts[r.clone()], &dirs[r], 300)
            .unwrap()
        {
            out.extend([s.log_stretch, s.time, s.end.position.x, s.end.spin]);
        }
        bits(out)
    };
    let one = LaneBilliard::new(&t.table, law).unwrap();
    let reference = run(&one, 0..starts.len());
    for isa in Isa::available() {
        let lanes = LaneBilliard::new(&t.table, law)
            .unwrap()
            .with_isa(isa)
            .unwrap()
            .with_threads(3)
            .unwrap();
        assert_eq!(run(&lanes, 0..starts.len()), reference, "{isa}");
    }
    for i in 0..starts.len() {
        assert_eq!(run(&one, i..i + 1), reference[4 * i..4 * i + 4]);
    }
}
