//! The spin collision law on its own (paper eqs. 1–3 and 7): the half-turn
//! form equals the paper's component formulas, conserves energy and
//! `Q = v∥ − αu` to a few ulps, is an involution, and its (v∥, u) block has
//! determinant −1 (+1 at α = 0, where u is left alone).

use proptest::prelude::*;
use spinball_core::{SpinLaw, SpinLawError};
use spinball_geometry::DVec2;

const EPS: f64 = f64::EPSILON;

/// Any α in [0, 10]: physical through `new`, beyond 1 through `extended`.
fn any_law(alpha: f64) -> SpinLaw {
    if alpha <= 1.0 {
        SpinLaw::new(alpha).unwrap()
    } else {
        SpinLaw::extended(alpha).unwrap()
    }
}

/// Paper eqs. (1)–(3), written out independently of the library.
fn paper_components(alpha: f64, v_par: f64, v_perp: f64, u: f64) -> (f64, f64, f64) {
    let beta = (1.0 - alpha) / (1.0 + alpha);
    let gamma = 2.0 * alpha / (1.0 + alpha);
    let delta = 2.0 / (1.0 + alpha);
    let u_new = if alpha > 0.0 {
        -beta * u - delta * v_par
    } else {
        u
    };
    (beta * v_par - gamma * u, -v_perp, u_new)
}

fn alpha_strategy() -> impl Strategy<Value = f64> {
    // Half the cases physical, some exactly 0 and 1, the rest up to 10.
    prop_oneof![Just(0.0), Just(1.0), 0.0f64..=1.0, 1.0f64..=10.0]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn one_collision_obeys_the_paper_law_and_conserves_e_and_q(
        alpha in alpha_strategy(),
        vx in -2.0f64..2.0,
        vy in -2.0f64..2.0,
        u in -2.0f64..2.0,
        wall_angle in 0.0f64..std::f64::consts::TAU,
    ) {
        let law = any_law(alpha);
        let n = DVec2::from_angle(wall_angle);
        let t = DVec2::new(n.y, -n.x);
        let v = DVec2::new(vx, vy);
        let (v2, u2) = law.collide(v, u, t);

        // Same as eqs. (1)–(3) in components. Tolerance: each side is a few
        // roundings of quantities bounded by |v| + (1 + α)|u|.
        let scale = v.length() + (1.0 + alpha) * u.abs() + f64::MIN_POSITIVE;
        let (vp, vn, up) = paper_components(alpha, v.dot(t), v.dot(n), u);
        prop_assert!((v2.dot(t) - vp).abs() <= 16.0 * EPS * scale);
        prop_assert!((v2.dot(n) - vn).abs() <= 16.0 * EPS * scale);
        prop_assert!((u2 - up).abs() <= 16.0 * EPS * scale);
        if alpha == 0.0 {
            // Specular, and u is left exactly as it was (reference convention).
            prop_assert_eq!(u2, u);
            prop_assert!((v2 - (v - 2.0 * v.dot(n) * n)).length() <= 8.0 * EPS * scale);
        }

        // Energy E = ½|v|² + ½αu², conserved by one raw collision (no shell
        // restore) to a few ulps of E: the map is orthogonal in (v, √α u).
        // Worst case seen over 2e7 random inputs: 9.5 ulps (the collision's
        // roundings plus those of two energy evaluations); bound 16.
        let e = law.energy(v, u);
        let e2 = law.energy(v2, u2);
        prop_assert!((e2 - e).abs() <= 16.0 * EPS * e, "dE/E = {}", (e2 - e) / e);

        // Q = v∥ − αu unchanged (paper eq. 12): few ulps of |v∥| + α|u|
        // (worst seen over 2e7 inputs: 4 ulps; components: 7 ulps).
        let q = law.q(v.dot(t), u);
        let q2 = law.q(v2.dot(t), u2);
        let q_scale = v.length() + alpha * u.abs() + f64::MIN_POSITIVE;
        prop_assert!((q2 - q).abs() <= 8.0 * EPS * q_scale, "dQ = {}", q2 - q);

        // A half-turn is an involution: colliding again at the same wall
        // restores the state.
        let (v3, u3) = law.collide(v2, u2, t);
        prop_assert!((v3 - v).length() <= 16.0 * EPS * scale);
        prop_assert!((u3 - u).abs() <= 16.0 * EPS * scale);
    }

    #[test]
    fn the_v_par_u_block_has_determinant_minus_one(alpha in alpha_strategy()) {
        let law = any_law(alpha);
        let m = law.matrix();
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        // Entries are at most 2 in size, so the determinant carries at most a
        // few ulps of 4.
        if alpha > 0.0 {
            prop_assert!((det + 1.0).abs() <= 16.0 * EPS, "det = {det}");
        } else {
            prop_assert_eq!(det, 1.0);
            prop_assert_eq!(m, [[1.0, 0.0], [0.0, 1.0]]);
        }
        prop_assert!((det.abs() - 1.0).abs() <= 16.0 * EPS);
        // M² = I (eq. 7: the (v∥, u) map is an involution).
        let [[a, b], [c, d]] = m;
        let square = [a * a + b * c, a * b + b * d, c * a + d * c, c * b + d * d];
        for (got, want) in square.into_iter().zip([1.0, 0.0, 0.0, 1.0]) {
            prop_assert!((got - want).abs() <= 16.0 * EPS, "M² = {square:?}");
        }
        // The matrix is the linear map collide_components applies.
        let (a, c) = law.collide_components(1.0, 0.0);
        let (b, d) = law.collide_components(0.0, 1.0);
        prop_assert!((a - m[0][0]).abs() <= 4.0 * EPS && (c - m[1][0]).abs() <= 4.0 * EPS);
        prop_assert!((b - m[0][1]).abs() <= 4.0 * EPS && (d - m[1][1]).abs() <= 4.0 * EPS);
        // Coefficients as in the paper, and β² + γδ = 1.
        prop_assert!((law.beta() - (1.0 - alpha) / (1.0 + alpha)).abs() <= 4.0 * EPS);
        prop_assert!((law.gamma() - 2.0 * alpha / (1.0 + alpha)).abs() <= 4.0 * EPS);
        prop_assert!((law.delta() - 2.0 / (1.0 + alpha)).abs() <= 4.0 * EPS);
        prop_assert!((law.beta().powi(2) + law.gamma() * law.delta() - 1.0).abs() <= 8.0 * EPS);
        prop_assert_eq!(law.alpha(), alpha);
        prop_assert_eq!(law.is_coupled(), alpha > 0.0);
    }
}

#[test]
fn named_balls_and_limits() {
    // The physical constructors and the law's special cases.
    assert_eq!(SpinLaw::specular(), SpinLaw::new(0.0).unwrap());
    assert!(!SpinLaw::specular().is_coupled());
    // -0.0 is accepted and normalised to +0.0.
    assert_eq!(
        SpinLaw::new(-0.0).unwrap().alpha().to_bits(),
        0.0f64.to_bits()
    );
    // α = 1 (thin ring): β = 0, the tangential velocity and spin swap roles.
    let ring = SpinLaw::new(1.0).unwrap();
    let (v, u) = ring.collide_components(0.6, 0.2);
    assert!((v - (-0.2)).abs() < 1e-16 && (u - (-0.6)).abs() < 1e-16);
    // Far towards the no-slip limit (α → ∞, β → −1): still exact energy and Q.
    let stiff = SpinLaw::extended(1e8).unwrap();
    assert!((stiff.beta() + 1.0).abs() < 1e-7);
    let (v, u) = (DVec2::new(0.3, -0.8), 1e-4);
    let (v2, u2) = stiff.collide(v, u, DVec2::X);
    let e = stiff.energy(v, u);
    assert!((stiff.energy(v2, u2) - e).abs() <= 16.0 * EPS * e);
    // α > 1 is only available by asking for it.
    assert_eq!(SpinLaw::new(5.0), Err(SpinLawError::Unphysical(5.0)));
    assert_eq!(SpinLaw::extended(5.0).unwrap().alpha(), 5.0);
}
