//! Animation frames against the exact dynamics: inside the table, on the
//! chords between the exact collisions, every wall taken, the spin angle
//! integrated as `ω = u / r`.

use spinball_analysis::AnalysisError;
use spinball_analysis::animation::{BallTrack, FrameOptions, animation_frames, track_ball};
use spinball_analysis::run::Starts;
use spinball_core::{Billiard, Sampler, SpinLaw, State};
use spinball_geometry::{Boundary, DVec2, Sinai, Stadium, Table};
use spinball_test_support::tables::{mushroom, signed_distance};

/// The collision before frame `k` (or the start) and the first at or after
/// it: `(time, point)` of both ends of the chord the frame lies on, and the
/// spin of the flight.
fn chord(track: &BallTrack, k: usize) -> ((f64, DVec2), (f64, DVec2), f64) {
    let t = track.time(k);
    let j = track
        .collisions
        .iter()
        .position(|c| c.time >= t)
        .expect("every frame is bracketed by a collision after it");
    let (a, spin) = match j {
        0 => ((0.0, track.start.position), track.start.spin),
        _ => {
            let c = track.collisions[j - 1];
            ((c.time, c.point), c.spin)
        }
    };
    let b = track.collisions[j];
    (a, (b.time, b.point), spin)
}

fn check_on_chords(track: &BallTrack, scale: f64) {
    for k in 0..track.len() {
        let ((ta, a), (tb, b), _) = chord(track, k);
        let t = track.time(k);
        assert!(ta <= t && t <= tb, "frame {k} at {t} outside [{ta}, {tb}]");
        // Where the straight flight from a to b is at time t.
        let expected = a + (b - a) * ((t - ta) / (tb - ta));
        let miss = (track.positions[k] - expected).length();
        assert!(
            miss < 1e-12 * scale,
            "frame {k}: {:?} is {miss:.2e} off the chord {a:?} → {b:?}",
            track.positions[k]
        );
    }
}

#[test]
fn frames_lie_in_the_table_and_on_the_chords_between_collisions() {
    // Fast film (about one collision per frame, several between some) so
    // that many frames sit next to a collision.
    let options = FrameOptions::new(20.0, 10.0).with_speed(60.0);
    for alpha in [0.0, 0.5] {
        for table in [
            Table::Stadium(Stadium::new(1.0).unwrap()),
            Table::Sinai(Sinai::new(2.0, 1.0).unwrap()),
        ] {
            let billiard = Billiard::new(table, SpinLaw::new(alpha).unwrap());
            let frames =
                animation_frames(&billiard, &Starts::Sampled(Sampler::Paper), 3, 7, &options)
                    .unwrap();
            assert_eq!(frames.frame_count(), 200);
            for track in &frames.balls {
                assert!(track.collisions.len() > 200, "too few collisions to test");
                for (k, p) in track.positions.iter().enumerate() {
                    // Signed distance is exact inside: rounding only.
                    let d = signed_distance(&table, *p);
                    assert!(
                        d > -1e-12,
                        "{table} α={alpha} frame {k}: {p:?} is {d:.2e} inside"
                    );
                    assert!(table.contains(*p), "{table} frame {k}: {p:?}");
                }
                check_on_chords(track, table.length_scale());
            }
        }
    }
}

#[test]
fn no_wall_is_skipped_between_frames() {
    // The same start stepped by hand: every collision up to the last frame
    // is in the track, at the same time and point, though there are
    // several per frame.
    let billiard = Billiard::new(mushroom(), SpinLaw::new(0.4).unwrap());
    let start = State::new(DVec2::new(0.1, 0.5), DVec2::new(0.6, 0.8), 0.2);
    let options = FrameOptions::new(10.0, 3.0).with_speed(100.0);
    let track = track_ball(&billiard, start, &options).unwrap();
    let last = track.time(track.len() - 1);
    let mut ball = billiard.launch(start).unwrap();
    let mut t = 0.0;
    let mut n = 0;
    while t <= last {
        let c = billiard.step(&mut ball).unwrap();
        t += c.time();
        let mark = track.collisions[n];
        assert_eq!(
            (mark.time, mark.point, mark.spin),
            (t, c.point(), ball.spin())
        );
        n += 1;
    }
    // All up to the last frame, and the first one after it.
    assert_eq!(track.collisions.len(), n);
    assert!(
        n > 5 * track.len(),
        "{n} collisions for {} frames",
        track.len()
    );
    check_on_chords(&track, 1.0);
    for p in &track.positions {
        assert!(billiard.table().contains(*p));
    }
}

#[test]
fn spin_angle_advances_by_omega_dt() {
    // ω = u / r on each flight: the angle between two frames is the sum of
    // u τ / r over the flights between them (spin after each collision from
    // the marks, which the dynamics recorded, not the frames).
    let r = 0.05;
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
    let options = FrameOptions::new(25.0, 8.0).with_speed(5.0).with_radius(r);
    let frames =
        animation_frames(&billiard, &Starts::Sampled(Sampler::Paper), 4, 3, &options).unwrap();
    assert_eq!(frames.radius, r);
    for track in &frames.balls {
        assert_eq!(track.angles[0], 0.0);
        let mut turned_within = 0;
        for k in 1..track.len() {
            let (t0, t1) = (track.time(k - 1), track.time(k));
            // Flights overlapping [t0, t1]: from the start or a collision, with its spin.
            let mut edges = vec![(0.0, track.start.spin)];
            edges.extend(track.collisions.iter().map(|c| (c.time, c.spin)));
            let mut expected = 0.0;
            for (i, &(ts, u)) in edges.iter().enumerate() {
                let te = edges.get(i + 1).map_or(f64::INFINITY, |e| e.0);
                let overlap = te.min(t1) - ts.max(t0);
                if overlap > 0.0 {
                    expected += u * overlap / r;
                }
            }
            let got = track.angles[k] - track.angles[k - 1];
            // Rounding of angles that grow to |u| t / r ~ 1e3 rad.
            assert!(
                (got - expected).abs() < 1e-10 * (1.0 + track.angles[k].abs()),
                "frame {k}: turned {got}, expected {expected}"
            );
            // Within one flight: exactly ω Δt with the frame's spin.
            let (_, (tb, _), u) = chord(track, k);
            if chord(track, k - 1).1.0 == tb {
                turned_within += 1;
                assert_eq!(track.spins[k], u);
                assert!((got - u * (t1 - t0) / r).abs() < 1e-10 * (1.0 + track.angles[k].abs()));
            }
        }
        assert!(
            turned_within > 50,
            "only {turned_within} frame pairs within a flight"
        );
    }
}

#[test]
fn balls_start_where_an_ensemble_starts() {
    let table = Stadium::new(1.0).unwrap();
    let law = SpinLaw::new(0.4).unwrap();
    let billiard = Billiard::new(table, law);
    let starts = Starts::Sampled(Sampler::Microcanonical);
    let frames =
        animation_frames(&billiard, &starts, 2, 11, &FrameOptions::new(10.0, 1.0)).unwrap();
    for (i, track) in frames.balls.iter().enumerate() {
        let (state, _) = starts.draw(&table, &law, 11, i as u64).unwrap();
        assert_eq!(track.start, state);
        assert_eq!(track.positions[0], state.position);
    }
}

#[test]
fn bad_films_are_refused_with_the_reason() {
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.4).unwrap());
    let outside = State::new(DVec2::new(5.0, 0.0), DVec2::X, 0.0);
    let inside = State::new(DVec2::ZERO, DVec2::X, 0.0);
    let options = FrameOptions::new(10.0, 1.0);
    let e = animation_frames(
        &billiard,
        &Starts::States(vec![inside, outside]),
        2,
        1,
        &options,
    )
    .unwrap_err();
    assert!(matches!(e, AnalysisError::Launch { index: 1, .. }), "{e}");
    let e = animation_frames(&billiard, &Starts::States(vec![inside]), 2, 1, &options).unwrap_err();
    assert!(e.to_string().contains("only 1 states"), "{e}");
    for balls in [0, 1001] {
        let e = animation_frames(
            &billiard,
            &Starts::Sampled(Sampler::Paper),
            balls,
            1,
            &options,
        )
        .unwrap_err();
        assert!(
            matches!(e, AnalysisError::InvalidOption { name: "balls", .. }),
            "{e}"
        );
    }
    // A ball a million times faster than the energy shell would need
    // about 1e8 collisions: refused, not run for minutes.
    let fast = State::new(DVec2::ZERO, DVec2::new(3e5, 4e5), 0.0);
    let e = track_ball(
        &billiard,
        fast,
        &FrameOptions::new(10.0, 60.0).with_speed(10.0),
    )
    .unwrap_err();
    assert!(e.to_string().contains("collisions"), "{e}");
}
