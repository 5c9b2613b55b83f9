//! The escape and diffusion documents the fronts write: shards merged in
//! any order are the whole run bit for bit (JSON, CSV and array), on any
//! number of threads; the summary is the library's blocks applied to the
//! records; the tables that cannot run are refused with typed errors.
#![cfg(feature = "serde")]

use spinball_analysis::AnalysisError;
use spinball_analysis::escape::{EscapeError, EscapeOptions, EscapeSummary, KacPrediction};
use spinball_analysis::open::Budget;
use spinball_analysis::report::{
    DiffusionDocument, DiffusionPartialDocument, Document, EscapeDocument, EscapePartialDocument,
    OpenRun,
};
use spinball_analysis::run::{MergeError, Shard, Threads};
use spinball_analysis::transport::{DiffusionSummary, Horizon, TransportError, horizon_of};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::Built;

fn open_run(spec: &str, alpha: f64, ics: u64, threads: usize) -> OpenRun<Built> {
    OpenRun {
        billiard: Billiard::new(spec.parse().unwrap(), SpinLaw::new(alpha).unwrap()),
        sampler: Sampler::Paper,
        seed: 11,
        ics: 0..ics,
        threads: Threads::Fixed(threads),
    }
}

fn quiet() -> impl FnMut(u64, u64) {
    |_, _| {}
}

/// The bytes of every output of an escape document.
fn escape_bytes(doc: &EscapeDocument) -> (String, String, Vec<u64>) {
    let (shape, values) = doc.array();
    let mut bits: Vec<u64> = shape;
    bits.extend(values.iter().map(|v| v.to_bits()));
    (
        Document::Escape(doc.clone()).to_json().unwrap(),
        doc.csv(),
        bits,
    )
}

fn diffusion_bytes(doc: &DiffusionDocument) -> (String, String, Vec<u64>) {
    let (shape, values) = doc.array();
    let mut bits: Vec<u64> = shape;
    bits.extend(values.iter().map(|v| v.to_bits()));
    (
        Document::Diffusion(doc.clone()).to_json().unwrap(),
        doc.csv(),
        bits,
    )
}

#[test]
fn escape_shards_merge_into_the_whole_run_bitwise_on_any_threads() {
    let budget = Budget::collisions(3_000);
    let options = EscapeOptions::default();
    let whole = |threads| {
        EscapeDocument::run(
            &open_run("stadium:a=1,hole=0.3", 0.4, 300, threads),
            budget,
            options,
            &mut quiet(),
        )
        .unwrap()
    };
    let one = whole(1);
    let reference = escape_bytes(&one);
    assert_eq!(escape_bytes(&whole(2)), reference);
    for count in [3, 4] {
        let mut parts: Vec<EscapePartialDocument> = (0..count)
            .map(|k| {
                let run = open_run("stadium:a=1,hole=0.3", 0.4, 300, 2);
                EscapePartialDocument::run(
                    &run,
                    Shard::new(k, count).unwrap(),
                    budget,
                    options,
                    &mut quiet(),
                )
                .unwrap()
            })
            .collect();
        parts.reverse();
        parts.swap(0, 1);
        // Through JSON, as `spinball merge` reads them.
        let read: Vec<EscapePartialDocument> = parts
            .iter()
            .map(|p| {
                let text = Document::EscapePartial(p.clone()).to_json().unwrap();
                match Document::from_json(&text).unwrap() {
                    Document::EscapePartial(p) => p,
                    other => panic!("read back a {}", other.kind()),
                }
            })
            .collect();
        let merged = EscapePartialDocument::merge(read).unwrap();
        assert_eq!(escape_bytes(&merged), reference, "{count} shards");
    }
    // The document reads back as itself.
    assert_eq!(
        Document::from_json(&reference.0).unwrap(),
        Document::Escape(one.clone())
    );
}

#[test]
fn the_escape_summary_is_the_blocks_on_the_records() {
    let run = open_run("stadium:a=1,hole=0.3", 0.0, 400, 2);
    let doc = EscapeDocument::run(
        &run,
        Budget::collisions(5_000),
        EscapeOptions::default(),
        &mut quiet(),
    )
    .unwrap();
    let kac = KacPrediction::for_table(run.billiard.table(), 0.3, 0.0).unwrap();
    let s = &doc.summary;
    let k = s.kac.unwrap();
    assert!((k.hole - 0.3).abs() < 1e-12 && k.perimeter == kac.perimeter);
    assert_eq!(
        **s,
        EscapeSummary::new(&doc.records, s.kac, EscapeOptions::default()).unwrap()
    );
    assert_eq!(s.n, 400);
    assert_eq!(s.escaped + s.censored, 400);
    assert_eq!(
        s.censored,
        doc.records.iter().filter(|r| r.censored).count() as u64
    );
    // Every escaped ball left through the hole with its exit recorded.
    assert!(
        doc.records
            .iter()
            .all(|r| r.censored == r.exit.is_none() && r.index < 400)
    );
}

#[test]
fn diffusion_shards_merge_into_the_whole_run_bitwise_on_any_threads() {
    let spec = "lorentz:lattice=triangular,w=1,R=0.45";
    let times: Vec<f64> = (1..=12).map(|k| 5.0 * f64::from(k)).collect();
    let whole = |threads| {
        DiffusionDocument::run(
            &open_run(spec, 0.4, 90, threads),
            &times,
            None,
            &mut quiet(),
        )
        .unwrap()
    };
    let one = whole(1);
    let reference = diffusion_bytes(&one);
    assert_eq!(diffusion_bytes(&whole(2)), reference);
    for count in [3, 4] {
        let mut parts: Vec<DiffusionPartialDocument> = (0..count)
            .map(|k| {
                DiffusionPartialDocument::run(
                    &open_run(spec, 0.4, 90, 2),
                    Shard::new(k, count).unwrap(),
                    &times,
                    None,
                    &mut quiet(),
                )
                .unwrap()
            })
            .collect();
        parts.rotate_left(1);
        let merged = DiffusionPartialDocument::merge(parts).unwrap();
        assert_eq!(diffusion_bytes(&merged), reference, "{count} shards");
    }
    assert_eq!(one.summary.horizon, Horizon::Finite);
    assert_eq!(
        one.summary,
        DiffusionSummary::new(&times, &one.records, Horizon::Finite, None).unwrap()
    );
    assert_eq!(
        Document::from_json(&reference.0).unwrap(),
        Document::Diffusion(one)
    );
}

#[test]
fn tables_that_cannot_run_are_refused_with_typed_errors() {
    let err = EscapeDocument::run(
        &open_run("stadium:a=1", 0.4, 10, 1),
        Budget::collisions(10),
        EscapeOptions::default(),
        &mut quiet(),
    )
    .unwrap_err();
    assert_eq!(err, AnalysisError::Escape(EscapeError::NoHole));
    assert!(err.to_string().contains("add one"), "{err}");
    let times = [1.0, 2.0, 3.0];
    let err = DiffusionDocument::run(
        &open_run("stadium:a=1", 0.4, 10, 1),
        &times,
        None,
        &mut quiet(),
    )
    .unwrap_err();
    assert_eq!(err, AnalysisError::Transport(TransportError::NotPeriodic));
    // A hole in a periodic table: the horizon is not known.
    let gas: Built = "lorentz:lattice=square,w=1,R=0.4".parse().unwrap();
    assert_eq!(horizon_of(&gas), Ok(Horizon::Infinite));
    // Shards of different runs name the field.
    let part = |seed| {
        let mut run = open_run("stadium:a=1,hole=0.3", 0.4, 20, 1);
        run.seed = seed;
        EscapePartialDocument::run(
            &run,
            Shard::new(0, 2).unwrap(),
            Budget::collisions(50),
            EscapeOptions::default(),
            &mut quiet(),
        )
        .unwrap()
    };
    let e = EscapePartialDocument::merge(vec![part(1), part(2)]).unwrap_err();
    assert!(
        matches!(e, MergeError::DifferentRuns { what: "seed", .. }),
        "{e}"
    );
    let e = EscapePartialDocument::merge(vec![part(1)]).unwrap_err();
    assert!(matches!(e, MergeError::Missing { .. }), "{e}");
}
