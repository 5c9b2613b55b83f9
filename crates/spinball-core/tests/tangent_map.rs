//! The exact tangent map ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#exact-tangent-dynamics), "Exact tangent dynamics") against
//! central finite differences of the full nonlinear flight–collision step, on
//! the four paper tables at α ∈ {0, 0.3, 1, 5}; its determinant (−1 for α > 0,
//! +1 at α = 0); and two identities every flow Jacobian must satisfy (the flow
//! direction is carried to the flow direction, energy is conserved to first
//! order).
//!
//! Finite differences use the *flow* version of the step, as the Jacobian
//! does: each perturbed ball takes its own step, then drifts (forwards or
//! backwards, with its post-collision velocity) to the reference collision
//! time, and the states are compared there.

mod common;

use common::{ALPHAS, law, paper_tables};
use spinball_core::{Ball, Billiard, Jacobian, Sampler, State, TangentVector};
use spinball_geometry::Table;

/// Step of the central differences; truncation error O(h²·|∂³|) ≈ 1e-14 and
/// rounding error O(ε·|z|/h) ≈ 1e-9 for O(1) states.
const H: f64 = 1e-7;

struct Outcome {
    compared: usize,
    skipped: usize,
    worst_relative: f64,
    errors: Vec<f64>,
}

fn max_abs(j: &[[f64; 5]; 5]) -> f64 {
    j.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// Finite-difference Jacobian of one step from `ball`, or `None` if one of
/// the ten perturbed balls hits a different wall than the reference (then
/// the step is not differentiable along that direction within ±h).
fn fd_jacobian(
    billiard: &Billiard<Table>,
    ball: &Ball,
    wall: u32,
    tau: f64,
) -> Option<[[f64; 5]; 5]> {
    let z = ball.state().to_array();
    let mut fd = [[0.0; 5]; 5];
    for col in 0..5 {
        let mut ends = [[0.0; 5]; 2];
        for (end, sign) in ends.iter_mut().zip([1.0, -1.0]) {
            let mut zp = z;
            zp[col] += sign * H;
            let mut shadow = Ball::new(State::from_array(zp), billiard.law()).ok()?;
            let c = billiard.step(&mut shadow).ok()?;
            if c.wall() != wall {
                return None;
            }
            shadow.drift(tau - c.time());
            *end = shadow.state().to_array();
        }
        for (row, line) in fd.iter_mut().enumerate() {
            line[col] = (ends[0][row] - ends[1][row]) / (2.0 * H);
        }
    }
    Some(fd)
}

fn compare(billiard: &Billiard<Table>, seeds: u64, steps: usize) -> Outcome {
    let mut out = Outcome {
        compared: 0,
        skipped: 0,
        worst_relative: 0.0,
        errors: Vec::new(),
    };
    let alpha = billiard.law().alpha();
    for index in 0..seeds {
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 77, index);
        let mut ball = billiard.launch(start).unwrap();
        // A few collisions in, so the state sits on a wall as in a run.
        for _ in 0..3 {
            billiard.step(&mut ball).unwrap();
        }
        for _ in 0..steps {
            let before = ball;
            let (c, Jacobian(j)) = billiard.step_jacobian(&mut ball).unwrap();

            // Determinant: −1 for α > 0 (the collision is a half-turn in
            // (v, √α u), orientation reversing), +1 at α = 0 (u untouched).
            // LU of entries O(10) loses a few ulps per entry: 1e-9 relative
            // is far above that and far below any real error.
            let det = Jacobian(j).determinant();
            let want = if alpha > 0.0 { -1.0 } else { 1.0 };
            assert!(
                (det - want).abs() <= 1e-9 * max_abs(&j).powi(2).max(1.0),
                "{} alpha {alpha}: det {det}",
                billiard.table()
            );

            // Identities of any flow Jacobian. The flow direction
            // F = (v, 0, 0) at the start goes to F at the end (a neighbour
            // shifted along the orbit stays shifted by the same time), and
            // the energy gradient ∇E = (0, v, αu) is carried back:
            // ∇E(end)·J = ∇E(start). Both exact: tolerance 1e-12 × |J|.
            let v0 = before.velocity();
            let v1 = ball.velocity();
            let tol = 1e-12 * max_abs(&j).max(1.0);
            for (row, line) in j.iter().enumerate() {
                let jf = line[0] * v0.x + line[1] * v0.y;
                let f_end = [v1.x, v1.y, 0.0, 0.0, 0.0][row];
                assert!(
                    (jf - f_end).abs() <= tol,
                    "flow direction, row {row}: {jf} vs {f_end}"
                );
            }
            let g0 = [0.0, 0.0, v0.x, v0.y, alpha * before.spin()];
            let g1 = [0.0, 0.0, v1.x, v1.y, alpha * ball.spin()];
            for (col, g) in g0.iter().enumerate() {
                let gj: f64 = (0..5).map(|row| g1[row] * j[row][col]).sum();
                assert!(
                    (gj - g).abs() <= tol,
                    "energy gradient, column {col}: {gj} vs {g}"
                );
            }
            if alpha == 0.0 {
                // Spin decoupled and left unchanged: the u row and column are e_u.
                assert_eq!(j[4], [0.0, 0.0, 0.0, 0.0, 1.0]);
                assert!(j.iter().take(4).all(|row| row[4] == 0.0));
            }

            let Some(fd) = fd_jacobian(billiard, &before, c.wall(), c.time()) else {
                out.skipped += 1;
                continue;
            };
            out.compared += 1;
            // Column by column, relative to the size of that column of the
            // Jacobian (at least 1): the rounding error of a central
            // difference scales with the derivative it estimates.
            for col in 0..5 {
                let scale = (0..5).fold(1.0f64, |m, r| m.max(j[r][col].abs()));
                for row in 0..5 {
                    let e = (fd[row][col] - j[row][col]).abs() / scale;
                    out.worst_relative = out.worst_relative.max(e);
                    out.errors.push(e);
                }
            }
        }
    }
    out
}

#[test]
fn tangent_map_equals_central_finite_differences() {
    for table in paper_tables() {
        for alpha in ALPHAS {
            let billiard = Billiard::new(table, law(alpha));
            let mut out = compare(&billiard, 3, 100);
            let label = format!("{table} alpha {alpha}");
            // Skipped steps (a perturbed ball hits another wall: corners,
            // junctions) must be a small minority: 5% of 300.
            assert!(
                out.skipped * 20 <= out.compared + out.skipped,
                "{label}: skipped {} of {}",
                out.skipped,
                out.compared + out.skipped
            );
            // Agreement: ≤ 1e-7 relative to the column size everywhere (the
            // measured worst case is ≈ 5e-9), and a median at the rounding
            // level of a central difference, ε|z|/h ≈ 1e-9 (checked ≤ 1e-8).
            assert!(
                out.worst_relative <= 1e-7,
                "{label}: worst {:e}",
                out.worst_relative
            );
            out.errors.sort_by(f64::total_cmp);
            let median = out.errors[out.errors.len() / 2];
            assert!(median <= 1e-8, "{label}: median {median:e}");
        }
    }
}

#[test]
fn step_tangent_applies_the_jacobian() {
    // Carrying tangent vectors with `step_tangent` is the same linear map as
    // the Jacobian of `step_jacobian`, applied with `Jacobian::apply`, and
    // the ball ends in the same state as with a plain `step`.
    for table in paper_tables() {
        let billiard = Billiard::new(table, law(0.4));
        let start = Sampler::Microcanonical.initial_state(&table, billiard.law(), 3, 0);
        let mut ball = billiard.launch(start).unwrap();
        let mut vecs = [
            TangentVector::from_array([1.0, -2.0, 0.5, 0.25, -1.0]),
            TangentVector::from_array([0.0, 0.0, 0.0, 0.0, 1.0]),
        ];
        for _ in 0..50 {
            let mut a = ball;
            let mut b = ball;
            let (ca, jac) = billiard.step_jacobian(&mut a).unwrap();
            let cb = billiard.step(&mut b).unwrap();
            let want: Vec<TangentVector> = vecs.iter().map(|v| jac.apply(v)).collect();
            let cc = billiard.step_tangent(&mut ball, &mut vecs).unwrap();
            assert_eq!(ca, cb);
            assert_eq!(ca, cc);
            assert_eq!(a.state(), ball.state());
            assert_eq!(b.state(), ball.state());
            for (got, want) in vecs.iter().zip(&want) {
                let d = (*got - *want).norm();
                assert!(d <= 1e-12 * want.norm().max(1.0), "{table}: {d:e}");
            }
            // Keep the vectors O(1) (they grow exponentially on chaotic tables).
            for v in vecs.iter_mut() {
                *v = *v * (1.0 / v.norm());
            }
        }
    }
}
