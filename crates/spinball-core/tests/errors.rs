//! Every invalid input to the core returns its error variant: spin laws,
//! launches, steps that find no wall or produce non-finite values, and
//! unknown sampler names.

use spinball_core::{
    Ball, Billiard, LaunchError, Sampler, SpinLaw, SpinLawError, State, StepError, UnknownSampler,
};
use spinball_geometry::{Boundary, Circle, DVec2, Hit, SegmentTable, Sinai, Stadium};

#[test]
fn spin_law_rejects_bad_alpha() {
    assert!(matches!(SpinLaw::new(f64::NAN), Err(SpinLawError::NonFinite(a)) if a.is_nan()));
    assert_eq!(
        SpinLaw::new(f64::INFINITY),
        Err(SpinLawError::NonFinite(f64::INFINITY))
    );
    assert_eq!(
        SpinLaw::new(f64::NEG_INFINITY),
        Err(SpinLawError::NonFinite(f64::NEG_INFINITY))
    );
    assert_eq!(SpinLaw::new(-0.1), Err(SpinLawError::Negative(-0.1)));
    assert_eq!(
        SpinLaw::new(-f64::MIN_POSITIVE),
        Err(SpinLawError::Negative(-f64::MIN_POSITIVE))
    );
    assert_eq!(
        SpinLaw::new(1.0 + 1e-15),
        Err(SpinLawError::Unphysical(1.0 + 1e-15))
    );
    assert_eq!(SpinLaw::new(5.0), Err(SpinLawError::Unphysical(5.0)));
    // The extension takes any finite α >= 0, and nothing else.
    assert_eq!(SpinLaw::extended(5.0).unwrap().alpha(), 5.0);
    assert_eq!(SpinLaw::extended(1e12).unwrap().alpha(), 1e12);
    assert!(matches!(
        SpinLaw::extended(f64::NAN),
        Err(SpinLawError::NonFinite(_))
    ));
    assert_eq!(
        SpinLaw::extended(f64::INFINITY),
        Err(SpinLawError::NonFinite(f64::INFINITY))
    );
    assert_eq!(SpinLaw::extended(-1.0), Err(SpinLawError::Negative(-1.0)));
    // The physical end points are accepted.
    assert!(SpinLaw::new(0.0).is_ok() && SpinLaw::new(1.0).is_ok());
    // Messages say what is wrong and point at the way out.
    assert!(
        SpinLaw::new(5.0)
            .unwrap_err()
            .to_string()
            .contains("extended")
    );
}

#[test]
fn launch_rejects_bad_states() {
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
    let v = DVec2::new(0.6, 0.8);
    // Outside: beyond the cap, and just outside a flat wall.
    let out = DVec2::new(2.5, 0.0);
    assert_eq!(
        billiard.launch(State::new(out, v, 0.1)).unwrap_err(),
        LaunchError::Outside(out)
    );
    let out = DVec2::new(0.0, 1.0 + 1e-9);
    assert_eq!(
        billiard.launch(State::new(out, v, 0.1)).unwrap_err(),
        LaunchError::Outside(out)
    );
    // Non-finite components, each named.
    let p = DVec2::new(0.1, 0.2);
    let cases = [
        (State::new(DVec2::new(f64::NAN, 0.0), v, 0.0), "position.x"),
        (
            State::new(DVec2::new(0.0, f64::INFINITY), v, 0.0),
            "position.y",
        ),
        (State::new(p, DVec2::new(f64::NAN, 0.1), 0.0), "velocity.x"),
        (
            State::new(p, DVec2::new(0.1, f64::NEG_INFINITY), 0.0),
            "velocity.y",
        ),
        (State::new(p, v, f64::NAN), "spin"),
    ];
    for (s, name) in cases {
        assert_eq!(
            billiard.launch(s).unwrap_err(),
            LaunchError::NonFinite(name)
        );
        assert_eq!(
            Ball::new(s, billiard.law()).unwrap_err(),
            LaunchError::NonFinite(name)
        );
    }
    // At rest (even when spinning: it never reaches a wall).
    let rest = State::new(p, DVec2::ZERO, 1.0);
    assert_eq!(billiard.launch(rest).unwrap_err(), LaunchError::AtRest);
    assert_eq!(
        Ball::new(rest, billiard.law()).unwrap_err(),
        LaunchError::AtRest
    );
    // On the wall is inside (walls included), and so is the paper's example.
    assert!(
        billiard
            .launch(State::new(DVec2::new(0.0, 1.0), -v, 0.0))
            .is_ok()
    );
    assert!(billiard.launch(State::new(DVec2::ZERO, v, 0.3)).is_ok());
    // Sinai: inside the obstacle is outside the table.
    let sinai = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::new(0.5).unwrap());
    assert!(matches!(
        sinai.launch(State::new(DVec2::new(0.5, 0.0), v, 0.0)),
        Err(LaunchError::Outside(_))
    ));
    for e in [
        LaunchError::AtRest,
        LaunchError::Outside(out),
        LaunchError::NonFinite("spin"),
    ] {
        assert!(!e.to_string().is_empty());
    }
}

#[test]
fn a_step_with_no_wall_ahead_is_an_error() {
    // A triangle, and a ball (built unchecked, as a shadow trajectory may be)
    // far outside it moving away: no wall ahead is an error, not a flight to
    // infinity, and the ball is left where it was.
    let tri = SegmentTable::polygon(&[
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(0.0, 1.0),
    ])
    .unwrap();
    let billiard = Billiard::new(tri, SpinLaw::new(0.4).unwrap());
    let s = State::new(DVec2::new(5.0, 5.0), DVec2::new(1.0, 0.5), 0.2);
    let mut ball = Ball::new(s, billiard.law()).unwrap();
    let err = billiard.step(&mut ball).unwrap_err();
    assert_eq!(
        err,
        StepError::NoWall {
            position: s.position,
            velocity: s.velocity
        }
    );
    assert_eq!(*ball.state(), s);
    // `run` reports the same error and stops.
    let r = billiard.run(&mut ball, 10, &mut ());
    assert!(matches!(r, Err(StepError::NoWall { .. })));
    assert!(!err.to_string().is_empty());
}

/// A broken table whose cast returns a NaN flight time.
struct NanTable;

impl Boundary for NanTable {
    fn cast(&self, _origin: DVec2, _velocity: DVec2) -> Option<Hit> {
        Some(Hit::new(f64::NAN, DVec2::ZERO, DVec2::Y, 0.0, 0, 0.0))
    }
}

#[test]
fn a_non_finite_step_is_an_error() {
    let billiard = Billiard::new(NanTable, SpinLaw::new(0.4).unwrap());
    let s = State::new(DVec2::ZERO, DVec2::new(1.0, 0.0), 0.0);
    let mut ball = Ball::new(s, billiard.law()).unwrap();
    assert_eq!(
        billiard.step(&mut ball).unwrap_err(),
        StepError::NonFinite {
            position: s.position
        }
    );
    assert_eq!(*ball.state(), s);
    let mut tangent = [spinball_core::TangentVector::default()];
    assert!(billiard.step_tangent(&mut ball, &mut tangent).is_err());
    assert!(billiard.step_jacobian(&mut ball).is_err());
    assert_eq!(*ball.state(), s);
}

#[test]
fn unknown_sampler_names_are_rejected() {
    assert_eq!("paper".parse::<Sampler>(), Ok(Sampler::Paper));
    assert_eq!(
        " Microcanonical ".parse::<Sampler>(),
        Ok(Sampler::Microcanonical)
    );
    assert_eq!("liouville".parse::<Sampler>(), Ok(Sampler::Microcanonical));
    assert_eq!(
        "canonical".parse::<Sampler>(),
        Err(UnknownSampler("canonical".into()))
    );
    for s in [Sampler::Paper, Sampler::Microcanonical] {
        assert_eq!(s.to_string().parse::<Sampler>(), Ok(s));
    }
    // A circle built with a bad radius never gets this far.
    assert!(Circle::new(0.0).is_err());
}
