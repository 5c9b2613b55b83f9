//! Phase space: the section observer, the bouncing-ball rotation and band,
//! the invariant measure and Kac's lemma, each checked against the
//! collision map itself (`Billiard::step`), and FTLE maps on tables whose
//! answer is known.

use std::f64::consts::PI;

use proptest::prelude::*;
use rand::Rng;
use spinball_analysis::diagnostics::collision_log;
use spinball_analysis::phase_space::{
    FacingFlats, FtleMapOptions, InvariantMeasure, SectionBox, SectionPoint, Slice, ftle_map,
    invariant_start, kac_comparison, pair_rotation, section_points, state_on_section,
};
use spinball_analysis::run::Threads;
use spinball_core::{Billiard, SpinLaw, State, ic_rng};
use spinball_geometry::{Boundary, Circle, DVec2, SegmentTable, Sinai, Stadium};

// ---------------------------------------------------------------------------
// Sections
// ---------------------------------------------------------------------------

fn agrees_with_log<B: Boundary>(billiard: &Billiard<B>, start: State) {
    let alpha = billiard.law().alpha();
    let points = section_points(billiard, start, 500).unwrap();
    let log = collision_log(billiard, start, 500).unwrap();
    assert_eq!(points.len(), log.rows.len());
    let mut spin_before = start.spin;
    for (p, row) in points.iter().zip(&log.rows) {
        // Columns: time, x, y, vx, vy, u (after), wall, s, v_par, q.
        assert_eq!(p.s, row[7]);
        assert_eq!(f64::from(p.wall), row[6]);
        assert_eq!(p.v_par, row[8]);
        assert_eq!(p.q, row[9]);
        assert_eq!(p.spin, spin_before);
        assert!((p.q - (p.v_par - alpha * p.spin)).abs() < 1e-14);
        // |v| before: energy with the spin before.
        let e = 0.5 * (p.speed * p.speed + alpha * p.spin * p.spin);
        assert!((e - start.energy(billiard.law())).abs() < 1e-14);
        spin_before = row[5];
    }
}

#[test]
fn section_points_agree_with_the_collision_log() {
    let start = State::new(DVec2::new(0.1, 0.2), DVec2::new(0.6, 0.7), 0.4);
    let law = SpinLaw::new(0.5).unwrap();
    agrees_with_log(&Billiard::new(Stadium::new(1.0).unwrap(), law), start);
    let start = State::new(DVec2::new(1.5, 0.2), DVec2::new(0.6, 0.7), 0.4);
    agrees_with_log(&Billiard::new(Sinai::new(2.0, 1.0).unwrap(), law), start);
    let p = DVec2::new;
    let room =
        SegmentTable::polygon(&[p(0.0, 0.0), p(2.0, 0.0), p(2.0, 1.0), p(0.0, 1.5)]).unwrap();
    agrees_with_log(
        &Billiard::new(room, law),
        State::new(p(0.5, 0.5), p(0.6, 0.7), 0.4),
    );
}

#[test]
fn a_ball_put_on_the_section_starts_there() {
    // After every collision of a run on the shell |V| = 1, the state put on
    // the section at that collision's (s, v∥ after, u after) is the ball's
    // state, to rounding.
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.4).unwrap());
    let start = State::new(DVec2::new(0.3, 0.1), DVec2::new(0.5, 0.6), 0.3);
    let scale = 1.0 / (2.0 * start.energy(billiard.law())).sqrt();
    let start = State::new(start.position, start.velocity * scale, start.spin * scale);
    let mut ball = billiard.launch(start).unwrap();
    for _ in 0..50 {
        let c = billiard.step(&mut ball).unwrap();
        let put = state_on_section(
            billiard.table(),
            billiard.law(),
            c.hit.s(),
            c.v_par_after,
            c.spin_after,
        )
        .unwrap();
        assert!((put.position - ball.position()).length() < 1e-12);
        assert!((put.velocity - ball.velocity()).length() < 1e-12);
        assert_eq!(put.spin, ball.spin());
    }
}

// ---------------------------------------------------------------------------
// The bouncing-ball rotation
// ---------------------------------------------------------------------------

/// `(v_x, √α u)` rotated by `angle`.
fn rotate(x: f64, y: f64, angle: f64) -> (f64, f64) {
    let (s, c) = angle.sin_cos();
    (c * x - s * y, s * x + c * y)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// A ball that has just hit the bottom flat (or the top one) of the
    /// stadium, with (v_x, √α u) small enough to hit the top and then the
    /// bottom flat: after that pair, (v_x, √α u) is rotated by −4·arctan √α
    /// (top then bottom; +4·arctan √α for bottom then top), to 1e-12.
    #[test]
    fn a_pair_of_flat_collisions_is_a_rotation_by_four_arctan_sqrt_alpha(
        alpha in 1e-4f64..4.0,
        r in 0.0f64..0.2,
        angle in 0.0f64..(2.0 * PI),
        x0 in -0.1f64..0.1,
        from_bottom in any::<bool>(),
    ) {
        let law = SpinLaw::extended(alpha).unwrap();
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law);
        let (vx, w) = (r * angle.cos(), r * angle.sin());
        let vy = (1.0 - r * r).sqrt();
        let (y0, vy) = if from_bottom { (-1.0, vy) } else { (1.0, -vy) };
        let start = State::new(DVec2::new(x0, y0), DVec2::new(vx, vy), w / alpha.sqrt());
        let mut ball = billiard.launch(start).unwrap();
        let first = billiard.step(&mut ball).unwrap();
        let second = billiard.step(&mut ball).unwrap();
        let walls = if from_bottom { (2, 0) } else { (0, 2) };
        prop_assert_eq!((first.wall(), second.wall()), walls);
        // From the bottom: top then bottom, a rotation by −Θ.
        let theta = if from_bottom { -pair_rotation(alpha) } else { pair_rotation(alpha) };
        let (ex, ey) = rotate(vx, w, theta);
        let got = (ball.velocity().x, alpha.sqrt() * ball.spin());
        prop_assert!((got.0 - ex).abs() < 1e-12 && (got.1 - ey).abs() < 1e-12,
            "α = {alpha}: got {got:?}, rotation predicts ({ex}, {ey})");
        prop_assert!((ball.velocity().y - vy).abs() < 1e-12);
    }

    /// The contacts on the flats follow x_n = c − A sin(θ₀ − nΔ) while the
    /// ball stays between them, and the ball leaves the flats exactly when
    /// the formula puts a contact past |x| = a.
    #[test]
    fn flat_contacts_follow_the_band(
        alpha in 0.01f64..1.0,
        r in 0.0f64..0.6,
        angle in 0.0f64..(2.0 * PI),
        x0 in -0.9f64..0.9,
    ) {
        let law = SpinLaw::new(alpha).unwrap();
        let stadium = Stadium::new(1.0).unwrap();
        let flats = FacingFlats::of(&stadium);
        let billiard = Billiard::new(stadium, law);
        let (vx, w) = (r * angle.cos(), r * angle.sin());
        let start = State::new(DVec2::new(x0, -1.0), DVec2::new(vx, (1.0 - r * r).sqrt()), w / alpha.sqrt());
        let band = flats.band(&law, &start).unwrap();
        let mut ball = billiard.launch(start).unwrap();
        for n in 0..300u64 {
            let predicted = band.contact(n);
            // Stay clear of the junctions, where rounding decides.
            if (predicted.abs() - 1.0).abs() < 1e-6 {
                break;
            }
            let c = billiard.step(&mut ball).unwrap();
            if predicted.abs() > 1.0 {
                prop_assert!(c.hit.is_curved(), "contact {n} predicted at x = {predicted} off the flats, hit wall {}", c.wall());
                break;
            }
            prop_assert!(!c.hit.is_curved());
            prop_assert!((c.point().x - predicted).abs() < 1e-9 * (1.0 + n as f64),
                "contact {n}: x = {} against {predicted}", c.point().x);
        }
    }
}

#[test]
fn predicted_bouncing_balls_never_reach_a_cap() {
    // Starts predicted trapped with a margin of 1e-3 stay on the flats for
    // 20 000 collisions; the share of such starts among the paper's
    // sampler is well above zero at α = 0.5 (the island has positive
    // measure) and exactly zero at α = 0.
    let stadium = Stadium::new(1.0).unwrap();
    let flats = FacingFlats::of(&stadium);
    for alpha in [0.0, 0.1, 0.5, 1.0] {
        let law = SpinLaw::new(alpha).unwrap();
        let billiard = Billiard::new(stadium, law);
        let mut trapped = 0;
        for i in 0..4000 {
            let start = spinball_core::Sampler::Paper.initial_state(&stadium, &law, 11, i);
            let Some(band) = flats.band(&law, &start) else {
                continue;
            };
            if band.margin(1.0) < 1e-3 {
                continue;
            }
            trapped += 1;
            let mut ball = billiard.launch(start).unwrap();
            for _ in 0..20_000 {
                assert!(
                    !billiard.step(&mut ball).unwrap().hit.is_curved(),
                    "α = {alpha}, start {i}"
                );
            }
        }
        if alpha == 0.0 {
            assert_eq!(trapped, 0);
        } else {
            assert!(
                trapped > 20,
                "α = {alpha}: only {trapped} of 4000 starts trapped"
            );
        }
    }
}

// ---------------------------------------------------------------------------
// The invariant measure
// ---------------------------------------------------------------------------

const S_BINS: usize = 8;
const V_BINS: usize = 4;

/// Bin of a section point in (s, v∥/|V|, w/|V|): `S_BINS` in s, `V_BINS`
/// in each of v and w over [−1, 1).
fn bin(perimeter: f64, s: f64, v: f64, w: f64, coupled: bool) -> usize {
    let b = |x: f64, n: usize| ((x * n as f64) as usize).min(n - 1);
    let (bs, bv) = (b(s / perimeter, S_BINS), b(0.5 * (v + 1.0), V_BINS));
    let bw = if coupled {
        b(0.5 * (w + 1.0), V_BINS)
    } else {
        0
    };
    (bs * V_BINS + bv) * V_BINS + bw
}

/// Histogram of `n` starts from `draw`, and of the next collision's section
/// point of each, in the bins of [`bin`].
fn push_forward<B: Boundary>(
    billiard: &Billiard<B>,
    n: u64,
    mut draw: impl FnMut(u64) -> (State, [f64; 3]),
) -> (Vec<f64>, Vec<f64>) {
    let alpha = billiard.law().alpha();
    let p = billiard.table().perimeter();
    let cells = S_BINS * V_BINS * V_BINS;
    let (mut before, mut after) = (vec![0.0; cells], vec![0.0; cells]);
    for i in 0..n {
        // The start and its own (outgoing) coordinates (s, v∥, w).
        let (start, [s0, v0, w0]) = draw(i);
        before[bin(p, s0, v0, w0, alpha > 0.0)] += 1.0;
        let mut ball = billiard.launch(start).unwrap();
        let mut next = None;
        billiard
            .run(
                &mut ball,
                1,
                &mut |c: &spinball_core::Collision, s: &State| {
                    next = Some(SectionPoint::of(c, s));
                },
            )
            .unwrap();
        let q = next.unwrap();
        let (v, w) = q.disk(alpha);
        after[bin(p, q.s, v, w, alpha > 0.0)] += 1.0;
    }
    (before, after)
}

/// The outgoing section coordinates `(s, v∥, w)` of a start put on the wall
/// (the wall found by casting back from just inside).
fn outgoing<B: Boundary>(table: &B, law: &SpinLaw, start: &State) -> [f64; 3] {
    let back = table
        .cast(start.position + start.velocity * 1e-9, -start.velocity)
        .unwrap();
    [
        back.s(),
        start.velocity.dot(back.tangent()),
        law.alpha().sqrt() * start.spin,
    ]
}

/// Pearson χ² of `counts` against `expected`, and of two samples of equal
/// size against each other.
fn chi2(counts: &[f64], expected: &[f64]) -> f64 {
    counts
        .iter()
        .zip(expected)
        .filter(|(_, e)| **e > 0.0)
        .map(|(c, e)| (c - e) * (c - e) / e)
        .sum()
}
fn chi2_two(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .filter(|(x, y)| **x + **y > 0.0)
        .map(|(x, y)| (x - y) * (x - y) / (x + y))
        .sum()
}

/// `power`: also check that a wrong measure (the hemisphere's area) is
/// moved by one collision (not on the circle, where rotation symmetry and
/// the (v∥, w) swap at α = 1 leave it invariant too).
fn check_invariance<B: Boundary + Copy>(name: &str, table: B, alpha: f64, power: bool) {
    let law = SpinLaw::new(alpha).unwrap();
    let billiard = Billiard::new(table, law);
    let measure = InvariantMeasure::new(&table, &law).unwrap();
    let n = 100_000;
    let (before, after) = push_forward(&billiard, n, |i| {
        let start = invariant_start(&table, &law, &measure, &mut ic_rng(7, i)).unwrap();
        (start, outgoing(&table, &law, &start))
    });
    // Expected counts from the measure of each bin.
    let p = table.perimeter();
    let coupled = alpha > 0.0;
    let mut expected = vec![0.0; after.len()];
    let edge = |k: usize, n: usize| -1.0 + 2.0 * k as f64 / n as f64;
    for bs in 0..S_BINS {
        for bv in 0..V_BINS {
            for bw in 0..(if coupled { V_BINS } else { 1 }) {
                let s = p * bs as f64 / S_BINS as f64..p * (bs + 1) as f64 / S_BINS as f64;
                let mut region = SectionBox::new(s, edge(bv, V_BINS)..edge(bv + 1, V_BINS));
                if coupled {
                    region = region.with_w(edge(bw, V_BINS)..edge(bw + 1, V_BINS));
                }
                expected[(bs * V_BINS + bv) * V_BINS + bw] =
                    n as f64 * measure.probability(&region).unwrap();
            }
        }
    }
    let dof = expected.iter().filter(|e| **e > 0.0).count() as f64 - 1.0;
    // χ² has mean dof and sd √(2 dof): allow 5 sd.
    let limit = dof + 5.0 * (2.0 * dof).sqrt();
    let (fit_before, fit_after, two) = (
        chi2(&before, &expected),
        chi2(&after, &expected),
        chi2_two(&before, &after),
    );
    assert!(
        fit_before < limit,
        "{name}: starts χ² {fit_before} > {limit}"
    );
    assert!(fit_after < limit, "{name}: pushed χ² {fit_after} > {limit}");
    assert!(two < limit, "{name}: before/after χ² {two} > {limit}");
    if !power {
        return;
    }

    // Power: the area measure of the hemisphere (density 1/v⊥ in the disk),
    // a natural wrong guess, is not invariant: one collision moves it.
    let mut rng = ic_rng(8, 0);
    let (wrong_before, wrong_after) = push_forward(&billiard, n, |_| {
        loop {
            let s = p * rng.random::<f64>();
            // Uniform on the hemisphere: v⊥ uniform in (0, 1) (Archimedes),
            // azimuth uniform; at α = 0 the great circle, v∥ = sin of a uniform angle.
            let (v, w) = if coupled {
                let z: f64 = rng.random();
                let phi = 2.0 * PI * rng.random::<f64>();
                let rho = (1.0 - z * z).sqrt();
                (rho * phi.cos(), rho * phi.sin())
            } else {
                ((PI * (rng.random::<f64>() - 0.5)).sin(), 0.0)
            };
            let u = if coupled { w / alpha.sqrt() } else { 0.0 };
            if let Ok(state) = state_on_section(&table, &law, s, v, u) {
                break (state, [s, v, w]);
            }
        }
    });
    let moved = chi2_two(&wrong_before, &wrong_after);
    assert!(
        moved > 4.0 * limit,
        "{name}: the wrong measure moved only χ² = {moved}"
    );
}

#[test]
fn the_invariant_measure_survives_a_collision() {
    check_invariance("stadium α = 0.5", Stadium::new(1.0).unwrap(), 0.5, true);
    check_invariance("stadium α = 0", Stadium::new(1.0).unwrap(), 0.0, true);
    check_invariance("sinai α = 0.3", Sinai::new(2.0, 1.0).unwrap(), 0.3, true);
    check_invariance("circle α = 1", Circle::unit(), 1.0, false);
}

// ---------------------------------------------------------------------------
// Kac's lemma
// ---------------------------------------------------------------------------

#[test]
fn kac_holds_on_ergodic_tables() {
    // Stadium and Sinai at α = 0 are ergodic: the mean return time to a box
    // is 1/μ(box) to within 4 SEM (across 16 orbits of 40 000 collisions).
    let stadium = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::specular());
    let sinai = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::specular());
    let cap = SectionBox::new(2.0..2.0 + PI, -0.3..0.6);
    let flat = SectionBox::new(0.5..1.5, -0.5..0.5);
    let disk = SectionBox::new(16.0..16.0 + PI, 0.0..0.8);
    for (name, kac) in [
        (
            "stadium cap",
            kac_comparison(&stadium, &cap, 16, 40_000, 3, Threads::All).unwrap(),
        ),
        (
            "stadium flat",
            kac_comparison(&stadium, &flat, 16, 40_000, 3, Threads::All).unwrap(),
        ),
        (
            "sinai disk",
            kac_comparison(&sinai, &disk, 16, 40_000, 3, Threads::All).unwrap(),
        ),
    ] {
        let r = kac.ratio().unwrap();
        assert_eq!(kac.never_returned, 0, "{name}");
        assert!(
            (r.value - 1.0).abs() < 4.0 * r.sem.max(1e-3),
            "{name}: ratio {} ± {}",
            r.value,
            r.sem
        );
        assert!(r.sem < 0.05, "{name}: ratio {} ± {}", r.value, r.sem);
    }
}

#[test]
fn bouncing_balls_never_return_to_the_caps() {
    // Stadium at α = 0.5, region: the right cap. The orbits (started from
    // the invariant measure) that the rotation predicts trapped between the
    // flats never visit it: the island splits the per-orbit return times
    // off; the rest return.
    let stadium = Stadium::new(1.0).unwrap();
    let law = SpinLaw::new(0.5).unwrap();
    let billiard = Billiard::new(stadium, law);
    let flats = FacingFlats::of(&stadium);
    let measure = InvariantMeasure::new(&stadium, &law).unwrap();
    let cap = SectionBox::new(2.0..2.0 + PI, -1.0..1.0);
    let kac = kac_comparison(&billiard, &cap, 300, 5_000, 9, Threads::All).unwrap();
    let mut trapped = 0;
    for orbit in &kac.orbits {
        let start = invariant_start(&stadium, &law, &measure, &mut ic_rng(9, orbit.index)).unwrap();
        if flats.trapped(&law, &start) {
            trapped += 1;
            assert_eq!(orbit.visits, 0, "orbit {}", orbit.index);
        }
    }
    assert!(trapped >= 3, "only {trapped} of 300 orbits trapped");
    assert!(kac.never_returned >= trapped);
    assert!(kac.never_returned < 300 / 4);
}

#[test]
fn kac_rejects_bad_inputs() {
    let stadium = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
    let nothing = SectionBox::new(0.0..1.0, 2.0..3.0);
    assert!(kac_comparison(&stadium, &nothing, 4, 100, 1, Threads::All).is_err());
    let ok = SectionBox::new(0.0..1.0, -0.5..0.5);
    assert!(kac_comparison(&stadium, &ok, 1, 100, 1, Threads::All).is_err());
    assert!(kac_comparison(&stadium, &ok, 4, 0, 1, Threads::All).is_err());
}

// ---------------------------------------------------------------------------
// FTLE maps
// ---------------------------------------------------------------------------

#[test]
fn ftle_maps_know_regular_from_chaotic() {
    let options = FtleMapOptions::new(32, 32, Slice::Spin(0.0)).with_collisions(2_000);
    // The circle is integrable at every α.
    for alpha in [0.0, 0.5, 1.0] {
        let map = ftle_map(Circle::unit(), SpinLaw::new(alpha).unwrap(), &options).unwrap();
        assert_eq!(map.regular_fraction(), 1.0, "circle α = {alpha}");
    }
    // The specular Sinai table is fully chaotic.
    let map = ftle_map(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::specular(), &options).unwrap();
    assert!(
        map.regular_fraction() < 0.02,
        "sinai: {}",
        map.regular_fraction()
    );
    assert_eq!(map.exponents.len(), 32 * 32);
}

#[test]
fn predicted_bouncing_balls_are_regular_on_the_map() {
    // Every cell of the stadium map at α = 0.5 the rotation predicts
    // trapped has FTLE ≤ 0.01, and spin makes the map's regular share grow.
    let stadium = Stadium::new(1.0).unwrap();
    let flats = FacingFlats::of(&stadium);
    let options = FtleMapOptions::new(64, 64, Slice::Spin(0.2)).with_collisions(2_000);
    let law = SpinLaw::new(0.5).unwrap();
    let map = ftle_map(stadium, law, &options).unwrap();
    let mask = flats.trapped_cells(&law, &map);
    let (trapped, trapped_regular) = map.regular_among(&mask);
    assert!(trapped > 20, "only {trapped} cells trapped");
    assert_eq!(trapped_regular, trapped);
    let specular = ftle_map(stadium, SpinLaw::specular(), &options.clone()).unwrap();
    assert!(map.regular_fraction() > specular.regular_fraction() + 0.02);
}

#[test]
fn ftle_maps_reject_bad_inputs() {
    let stadium = Stadium::new(1.0).unwrap();
    let law = SpinLaw::new(0.5).unwrap();
    let bad = |o: FtleMapOptions| ftle_map(stadium, law, &o).is_err();
    assert!(bad(FtleMapOptions::new(0, 8, Slice::Spin(0.0))));
    assert!(bad(FtleMapOptions::new(8, 8, Slice::Spin(2.0)))); // αu² = 2
    assert!(bad(FtleMapOptions::new(8, 8, Slice::Spin(f64::NAN))));
    assert!(bad(
        FtleMapOptions::new(8, 8, Slice::Spin(0.0)).with_collisions(0)
    ));
    assert!(bad(
        FtleMapOptions::new(8, 8, Slice::Spin(0.0)).with_threshold(f64::NAN)
    ));
    assert!(
        ftle_map(
            stadium,
            SpinLaw::specular(),
            &FtleMapOptions::new(8, 8, Slice::Q(0.1))
        )
        .is_err()
    );
    // Q slices mask the cells off the shell.
    let map = ftle_map(
        stadium,
        law,
        &FtleMapOptions::new(8, 8, Slice::Q(0.3)).with_collisions(200),
    )
    .unwrap();
    let off = map.exponents.iter().filter(|x| x.is_none()).count();
    assert!(off > 0 && off < 64);
    assert_eq!(map.to_array().iter().filter(|x| x.is_nan()).count(), off);
}
