//! Files that were edited are refused (issue 39, item 4); messages name the
//! field that differs (item 5); a table is identified by its geometry,
//! never a type name (issue 33, deliverable 4); sizes that would exhaust
//! the machine are typed errors.

use glam::DVec2;
use serde_json::Value;
use spinball_analysis::estimators::{Histogram, Method, SpectrumOptions};
use spinball_analysis::run::{
    Ensemble, LyapunovEstimate, MergeError, PartialRun, Silent, SpectrumEstimate, StopReason,
    Threads, merge_partials, spectrum_ensemble,
};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::{Boundary, Hit, Stadium};

fn stadium() -> Stadium {
    Stadium::new(1.0).unwrap()
}

fn ensemble(indices: std::ops::Range<u64>) -> Ensemble<Stadium> {
    Ensemble::new(stadium(), SpinLaw::new(0.5).unwrap())
        .with_seed(7)
        .with_indices(indices)
        .with_collisions(300)
        .with_threads(Threads::Fixed(1))
}

fn shard(indices: std::ops::Range<u64>) -> PartialRun {
    ensemble(indices).run_partial(None, &mut Silent).unwrap()
}

/// A partial run as JSON, edited by `edit`, read back.
fn edited(part: &PartialRun, edit: impl FnOnce(&mut Value)) -> Result<PartialRun, String> {
    let mut v = serde_json::to_value(part).unwrap();
    edit(&mut v);
    serde_json::from_value(v).map_err(|e| e.to_string())
}

#[test]
fn a_partial_run_reads_back_bitwise_with_its_checksum() {
    let part = shard(0..6);
    let v = serde_json::to_value(&part).unwrap();
    let sum = v["checksum"].as_str().unwrap();
    assert!(sum.starts_with("fnv1a64:") && sum.len() == 8 + 16, "{sum}");
    assert_eq!(v["n_trajectories"], 6);
    let text = serde_json::to_string(&part).unwrap();
    let back: PartialRun = serde_json::from_str(&text).unwrap();
    assert_eq!(back, part);
    // The checksum is a function of the content: writing again gives it.
    assert_eq!(serde_json::to_string(&back).unwrap(), text);
}

#[test]
fn an_edited_exponent_is_refused() {
    let part = shard(0..6);
    // The tester's edits: one exponent times 10, one set to 1e308, one +100.
    for edit in [
        |x: f64| x * 10.0,
        |_: f64| 1e308,
        |x: f64| x + 100.0,
        |x: f64| x.next_up(),
    ] {
        let e = edited(&part, |v| {
            let x = v["trajectories"][3]["exponent"].as_f64().unwrap();
            v["trajectories"][3]["exponent"] = edit(x).into();
        })
        .unwrap_err();
        assert!(e.contains("checksum does not hold"), "{e}");
    }
    // Any other field too: α, the seed, the wall time, the range.
    for (field, value) in [
        ("/provenance/alpha", Value::from(0.25)),
        ("/provenance/seed", Value::from(8)),
        ("/wall_time_s", Value::from(0.0)),
        ("/indices/end", Value::from(7)),
    ] {
        let e = edited(&part, |v| *v.pointer_mut(field).unwrap() = value).unwrap_err();
        assert!(e.contains("checksum does not hold"), "{field}: {e}");
    }
}

#[test]
fn a_count_that_does_not_hold_and_a_missing_checksum_are_refused() {
    let part = shard(0..6);
    let e = edited(&part, |v| {
        let extra = v["trajectories"][5].clone();
        v["trajectories"].as_array_mut().unwrap().push(extra);
    })
    .unwrap_err();
    assert!(
        e.contains("holds 7") && e.contains("says it holds 6"),
        "{e}"
    );
    // A file of 0.1.0, which wrote no checksum.
    let e = edited(&part, |v| {
        v.as_object_mut().unwrap().remove("checksum");
        v["version"] = "0.1.0".into();
    })
    .unwrap_err();
    assert!(
        e.contains("no checksum") && e.contains("spinball 0.1.0"),
        "{e}"
    );
    let e = edited(&part, |v| v["checksum"] = "crc32:1234".into()).unwrap_err();
    assert!(e.contains("not a `fnv1a64:`"), "{e}");
    // A non-finite value cannot even be written (it would read back as
    // `null`).
    let mut bad = part.clone();
    bad.trajectories[2].exponent = f64::INFINITY;
    let e = serde_json::to_string(&bad).unwrap_err().to_string();
    assert!(
        e.contains("initial condition 2") && e.contains("inf"),
        "{e}"
    );
}

#[test]
fn merge_and_resume_refuse_a_piece_that_does_not_hold() {
    let (a, mut b) = (shard(0..4), shard(4..8));
    b.trajectories[1].exponent = f64::NAN;
    let e = merge_partials(vec![a.clone(), b.clone()], Some(0..8)).unwrap_err();
    assert!(matches!(e, MergeError::Invalid { .. }), "{e}");
    assert!(e.to_string().contains("initial condition 5"), "{e}");
    let e = ensemble(4..8)
        .run_partial(Some(b), &mut Silent)
        .unwrap_err();
    assert!(e.to_string().contains("the checkpoint is refused"), "{e}");
    // Statistics that overflow are refused, never written as `null`.
    let mut huge = a.clone();
    huge.trajectories[0].exponent = 1e308;
    huge.trajectories[1].exponent = -1e308;
    let e = merge_partials(vec![huge], None).unwrap_err().to_string();
    assert!(e.contains("of the per-trajectory values is"), "{e}");
}

#[test]
fn a_resume_of_another_run_says_which_field_differs() {
    let part = shard(0..6);
    let check = |other: Ensemble<Stadium>, want: &str| {
        let e = other
            .run_partial(Some(part.clone()), &mut Silent)
            .unwrap_err()
            .to_string();
        assert!(e.contains(want), "{want}: {e}");
    };
    check(
        ensemble(0..6).with_seed(8),
        "seed 7 in the checkpoint, 8 asked",
    );
    check(
        Ensemble::new(stadium(), SpinLaw::new(0.25).unwrap())
            .with_seed(7)
            .with_indices(0..6)
            .with_collisions(300),
        "alpha 0.5 in the checkpoint, 0.25 asked",
    );
    check(
        ensemble(0..6).with_method(Method::Tangent),
        "method fd (delta0 1e-7) in the checkpoint, tangent asked",
    );
    check(
        ensemble(0..6).with_collisions(301),
        "collisions per IC 300 in the checkpoint, 301 asked",
    );
    check(
        ensemble(0..7),
        "initial conditions 0..6 in the checkpoint, 0..7 asked",
    );
    check(
        Ensemble::new(Stadium::new(2.0).unwrap(), SpinLaw::new(0.5).unwrap())
            .with_seed(7)
            .with_indices(0..6)
            .with_collisions(300),
        "table stadium:a=1 in the checkpoint, stadium:a=2 asked",
    );
    // Shards of different runs name the field too.
    let other = ensemble(6..12)
        .with_seed(9)
        .run_partial(None, &mut Silent)
        .unwrap();
    let done = ensemble(0..6).run_partial(None, &mut Silent).unwrap();
    let e = merge_partials(vec![done, other], None)
        .unwrap_err()
        .to_string();
    assert!(e.contains("seed 7 in one, 9 in another"), "{e}");
}

#[test]
fn shards_made_through_a_table_and_a_borrowed_one_merge() {
    let table = stadium();
    let law = SpinLaw::new(0.5).unwrap();
    let borrowed = Ensemble::new(&table, law)
        .with_seed(7)
        .with_indices(0..5)
        .with_collisions(300)
        .with_threads(Threads::Fixed(1))
        .run_partial(None, &mut Silent)
        .unwrap();
    let owned = shard(5..10);
    assert_eq!(borrowed.provenance.table, owned.provenance.table);
    assert_eq!(
        borrowed.provenance.table.identity(),
        owned.provenance.table.identity()
    );
    // Through a file as well.
    let borrowed: PartialRun =
        serde_json::from_str(&serde_json::to_string(&borrowed).unwrap()).unwrap();
    let merged = merge_partials(vec![owned, borrowed], Some(0..10)).unwrap();
    let whole = ensemble(0..10).run().unwrap();
    assert_eq!(merged.mean().to_bits(), whole.mean().to_bits());
    assert_eq!(merged.sem().to_bits(), whole.sem().to_bits());
    assert_eq!(merged.trajectories(), whole.trajectories());
}

/// A table of one's own, without a shape.
struct Plain(Stadium);

impl Boundary for Plain {
    fn cast(&self, o: DVec2, v: DVec2) -> Option<Hit> {
        self.0.cast(o, v)
    }
    fn aabb(&self) -> spinball_geometry::Aabb {
        self.0.aabb()
    }
}

#[test]
fn a_table_without_a_shape_is_not_merged_by_its_type_name() {
    let run = |indices| {
        Ensemble::new(Plain(stadium()), SpinLaw::new(0.5).unwrap())
            .with_seed(7)
            .with_indices(indices)
            .with_collisions(100)
            .with_threads(Threads::Fixed(1))
            .run_partial(None, &mut Silent)
            .unwrap()
    };
    let (a, b) = (run(0..3), run(3..6));
    assert_eq!(a.provenance.table.identity(), None);
    let e = merge_partials(vec![a.clone(), b], None).unwrap_err();
    assert!(matches!(e, MergeError::Table(_)), "{e}");
    assert!(e.to_string().contains("has no shape"), "{e}");
    let e = Ensemble::new(Plain(stadium()), SpinLaw::new(0.5).unwrap())
        .with_seed(7)
        .with_indices(0..3)
        .with_collisions(100)
        .run_partial(Some(a), &mut Silent)
        .unwrap_err();
    assert!(e.to_string().contains("has no shape"), "{e}");
}

#[test]
fn estimates_merge_by_geometry() {
    let a = ensemble(0..4).run().unwrap();
    let b = Ensemble::new(&stadium(), SpinLaw::new(0.5).unwrap())
        .with_seed(7)
        .with_indices(4..8)
        .with_collisions(300)
        .run()
        .unwrap();
    assert_eq!(a.merge(&b).unwrap().n_ics(), 8);
    let c = Ensemble::new(
        Stadium::new(1.0f64.next_up()).unwrap(),
        SpinLaw::new(0.5).unwrap(),
    )
    .with_seed(7)
    .with_indices(4..8)
    .with_collisions(300)
    .run()
    .unwrap();
    let e = a.merge(&c).unwrap_err().to_string();
    assert!(e.contains("table stadium:a=1 in one"), "{e}");
    // Overflowing statistics are an error, not `null` in a file.
    let mut t = a.trajectories().to_vec();
    t[0].exponent = 1e308;
    t[1].exponent = -1e308;
    let prov = ensemble(0..4).provenance();
    assert!(LyapunovEstimate::from_trajectories(&prov, t, 0.0, StopReason::Completed).is_err());
}

fn spectra(indices: std::ops::Range<u64>) -> SpectrumEstimate {
    let billiard = Billiard::new(stadium(), SpinLaw::new(0.5).unwrap());
    let options = SpectrumOptions::new(200, Method::Tangent);
    spectrum_ensemble(
        &billiard,
        Sampler::Paper,
        3,
        indices,
        &options,
        Threads::Fixed(1),
    )
    .unwrap()
}

#[test]
fn an_edited_spectrum_is_refused() {
    let est = spectra(0..4);
    let text = serde_json::to_string(&est).unwrap();
    let back: SpectrumEstimate = serde_json::from_str(&text).unwrap();
    assert_eq!(back, est);
    let read = |edit: &dyn Fn(&mut Value)| {
        let mut v: Value = serde_json::from_str(&text).unwrap();
        edit(&mut v);
        serde_json::from_value::<SpectrumEstimate>(v)
            .unwrap_err()
            .to_string()
    };
    // The tester's edit: one more spectrum appended.
    let e = read(&|v| {
        let extra = v["spectra"][3].clone();
        v["spectra"].as_array_mut().unwrap().push(extra);
    });
    assert!(e.contains("holds 5"), "{e}");
    // ... with the count edited to match.
    let e = read(&|v| {
        let extra = v["spectra"][3].clone();
        v["spectra"].as_array_mut().unwrap().push(extra);
        v["n_spectra"] = 5.into();
        v["n_ics"] = 5.into();
    });
    assert!(e.contains("checksum does not hold"), "{e}");
    let e = read(&|v| v["spectra"][1]["exponents"][0] = 10.0.into());
    assert!(e.contains("checksum does not hold"), "{e}");
    let e = read(&|v| {
        v.as_object_mut().unwrap().remove("checksum");
    });
    assert!(e.contains("no checksum"), "{e}");
    // In memory: a spectrum appended is refused by the merge.
    let mut grown = est.clone();
    grown.spectra.push(grown.spectra[0]);
    let e = grown.merge(&spectra(4..6)).unwrap_err().to_string();
    assert!(e.contains("holds 5"), "{e}");
    assert_eq!(est.merge(&spectra(4..6)).unwrap().n_ics, 6);
}

#[test]
fn a_huge_histogram_is_a_typed_error() {
    for bins in [0, Histogram::MAX_BINS + 1, usize::MAX] {
        let e = Histogram::new(0.0, 1.0, bins).unwrap_err().to_string();
        assert!(e.contains("1..=1048576"), "{e}");
    }
    assert_eq!(
        Histogram::new(0.0, 1.0, Histogram::MAX_BINS)
            .unwrap()
            .bins(),
        Histogram::MAX_BINS
    );
    let est = ensemble(0..4).run().unwrap();
    let e = est.ftle().unwrap().auto_histogram(usize::MAX).unwrap_err();
    assert!(e.to_string().contains("histogram bins"), "{e}");
}
