//! The one result schema: every kind of document reads back as it was
//! written, bit for bit; files of spinball 0.1 (in `tests/data/0.1.0`,
//! written by the 0.1.0 command line: `spinball lyapunov --table
//! stadium:a=1 --alpha 0.5 --ics 4 --collisions 50 --seed 3`, the same with
//! `--shard 0/2`, and `spinball sweep` of that run by tangent) are read
//! when their layout is today's and refused naming both versions when it
//! is not.

#![cfg(feature = "serde")]

use spinball_analysis::estimators::{Method, SpectrumOptions};
use spinball_analysis::orbits::{SearchOptions, stability_diagram};
use spinball_analysis::phase_space::{
    FtleMapOptions, SectionBox, Slice, ftle_map, ftle_map_part, kac_comparison,
};
use spinball_analysis::precision::{EnsembleLevels, Multilevel};
use spinball_analysis::report::{
    Document, DocumentError, FtleMapDocument, FtleMapPartialDocument, KacDocument,
    LyapunovDocument, MultilevelDocument, MultilevelPoint, OrbitsDocument, PartialDocument,
    PhaseHead, SCHEMA, SectionDocument, SpectrumDocument, SpectrumRow, SweepDocument, csv_text,
    read_csv,
};
use spinball_analysis::run::{Ensemble, Shard, Silent, TableRecord, Threads, spectrum_ensemble};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::{Built, Stadium, Table};

const OLD_RESULT: &str = include_str!("data/0.1.0/result.json");
const OLD_PARTIAL: &str = include_str!("data/0.1.0/partial.json");
const OLD_SWEEP: &str = include_str!("data/0.1.0/sweep.json");

/// A small run: the settings of the 0.1.0 files.
fn old_run() -> Ensemble<Table> {
    Ensemble::new(
        Table::from(Stadium::new(1.0).unwrap()),
        SpinLaw::new(0.5).unwrap(),
    )
    .with_seed(3)
    .with_ics(4)
    .with_collisions(50)
    .with_method(Method::Tangent)
    .with_threads(Threads::Fixed(1))
}

/// `doc` written and read back.
fn round_trip(doc: &Document) -> Document {
    let text = doc.to_json().unwrap();
    let prefix = format!("{{\"schema\":{SCHEMA},\"kind\":\"{}\",", doc.kind());
    assert!(text.starts_with(&prefix), "{text}");
    let pretty = Document::from_json(&doc.to_json_pretty().unwrap()).unwrap();
    assert_eq!(&pretty, doc);
    Document::from_json(&text).unwrap()
}

#[test]
fn every_kind_reads_back_as_written() {
    let run = old_run();
    let estimate = run.run().unwrap();
    let lyapunov = Document::Lyapunov(LyapunovDocument::new(vec![estimate.clone()]));
    assert_eq!(round_trip(&lyapunov), lyapunov);
    let back = round_trip(&lyapunov).into_lyapunov().unwrap();
    assert_eq!(back.points[0].mean().to_bits(), estimate.mean().to_bits());

    let shard = Shard::new(1, 2).unwrap();
    let mut partial = PartialDocument::new(shard, 0..4);
    let piece = run.clone().with_indices(shard.range(0..4));
    partial
        .points
        .push(piece.run_partial(None, &mut Silent).unwrap());
    let partial = Document::LyapunovPartial(partial);
    assert_eq!(round_trip(&partial), partial);

    let mut sweep = SweepDocument::new(&run.table, run.method, Sampler::Paper, 3);
    sweep.push(&estimate);
    let sweep = Document::Sweep(sweep);
    assert_eq!(round_trip(&sweep), sweep);

    let billiard = Billiard::new(run.table, run.law);
    let options = SpectrumOptions::new(50, Method::Tangent);
    let spectra = spectrum_ensemble(
        &billiard,
        Sampler::Paper,
        3,
        0..4,
        &options,
        Threads::Fixed(1),
    )
    .unwrap();
    let spectrum = SpectrumDocument::new(
        TableRecord::of(&run.table),
        vec![0.5],
        None,
        0..4,
        vec![spectra],
    );
    // Its CSV: one row per α, through serde, reading back bit for bit.
    let csv = csv_text(&spectrum.rows()).unwrap();
    assert!(csv.starts_with("alpha,l1,l2,l3,l4,l5,sem1,sem2,sem3,sem4,sem5,n_ics\n"));
    assert_eq!(read_csv::<SpectrumRow>(&csv).unwrap(), spectrum.rows());
    let spectrum = Document::Spectrum(spectrum);
    assert_eq!(round_trip(&spectrum), spectrum);
}

/// The kinds of the other commands (multilevel runs, stability diagrams,
/// sections, Kac return times, FTLE maps and their shards) read back as
/// written too, `null` exponents off the shell and all.
#[test]
fn every_command_kind_reads_back_as_written() {
    let law = SpinLaw::new(0.5).unwrap();
    let stadium = Stadium::new(1.0).unwrap();

    let levels = EnsembleLevels::new(
        Ensemble::new(stadium, law)
            .with_method(Method::Tangent)
            .with_seed(5),
        vec![200, 400, 800, 1600],
    )
    .unwrap();
    let estimate = Multilevel::new(0.05)
        .with_pilot_ics(32)
        .run(&levels)
        .unwrap();
    let multilevel = Document::Multilevel(MultilevelDocument::new(vec![MultilevelPoint {
        alpha: 0.5,
        estimate,
    }]));
    assert_eq!(round_trip(&multilevel), multilevel);

    let diagram =
        stability_diagram(&stadium, 2, &[0.0, 0.5], 1e-3, &SearchOptions::default()).unwrap();
    assert!(!diagram.branches.is_empty());
    let orbits = Document::Orbits(OrbitsDocument {
        table: "stadium:a=1".into(),
        diagram,
        islands: None,
    });
    assert_eq!(round_trip(&orbits), orbits);

    let section = Document::Section(SectionDocument {
        head: PhaseHead::new(&stadium, &law),
        sampler: "invariant".into(),
        seed: 3,
        orbits: 1,
        collisions: 2,
        spin_slice: Some(0.2),
        columns: [("s", vec![0.25, 1.5]), ("u", vec![-0.1, 0.3])]
            .into_iter()
            .map(|(name, values)| (name.to_string(), values))
            .collect(),
    });
    assert_eq!(round_trip(&section), section);

    let cap = SectionBox::new(2.0..5.0, -1.0..1.0);
    let billiard = Billiard::new(stadium, law);
    let comparison = kac_comparison(&billiard, &cap, 4, 500, 3, Threads::Fixed(1)).unwrap();
    let kac = Document::Kac(KacDocument::new(&stadium, &law, 3, 500, comparison));
    assert_eq!(round_trip(&kac), kac);

    // Q = 0.9 at α = 0.5 leaves part of the grid off the shell.
    let options = FtleMapOptions::new(6, 5, Slice::Q(0.9)).with_collisions(100);
    let part = ftle_map_part(stadium, law, &options, Shard::new(0, 2).unwrap()).unwrap();
    let partial = Document::FtleMapPartial(FtleMapPartialDocument { part });
    assert_eq!(round_trip(&partial), partial);
    let map = ftle_map(stadium, law, &options).unwrap();
    assert!(map.exponents.iter().any(Option::is_none));
    let built = Built::Table(Table::from(stadium));
    let whole = FtleMapDocument::new(&built, &law, TableRecord::of(&stadium), map);
    assert!(whole.predicted.is_some());
    let whole = Document::FtleMap(whole);
    assert_eq!(round_trip(&whole), whole);
    let back = round_trip(&whole).into_ftle_map_partial().unwrap_err();
    assert!(back.to_string().contains("spinball.ftle_map"), "{back}");
}

#[test]
fn a_finished_result_of_0_1_still_loads_with_the_same_numbers() {
    let doc = Document::from_json(OLD_RESULT).unwrap();
    assert_eq!(doc.kind(), "spinball.lyapunov");
    let old = &doc.into_lyapunov().unwrap().points[0];
    assert_eq!(old.version(), "0.1.0");
    assert_eq!((old.n_ics(), old.alpha(), old.seed()), (4, 0.5, 3));
    // The numbers are the file's, bit for bit (the values in result.json).
    assert_eq!(old.mean(), 0.13510293006977941);
    assert_eq!(old.trajectories()[3].exponent, 0.17033083778763594);
    assert_eq!(old.trajectories()[3].time, 137.8877258286096);
}

#[test]
fn other_layouts_of_0_1_are_refused_naming_both_versions() {
    for (what, text) in [("partial", OLD_PARTIAL), ("sweep", OLD_SWEEP)] {
        let err = Document::from_json(text).unwrap_err();
        match &err {
            DocumentError::Version {
                found,
                expected,
                written_by,
            } => {
                assert_eq!((*found, *expected), (1, SCHEMA), "{what}");
                assert_eq!(written_by.as_deref(), Some("0.1.0"), "{what}");
            }
            other => panic!("{what}: {other}"),
        }
        let message = err.to_string();
        for needle in ["spinball 0.1.0", "schema 1", "reads schema 2"] {
            assert!(message.contains(needle), "{what}: {message}");
        }
    }
}

#[test]
fn a_newer_schema_is_refused_and_a_wrong_kind_is_named() {
    let doc = Document::Lyapunov(LyapunovDocument::new(vec![old_run().run().unwrap()]));
    let text = doc
        .to_json()
        .unwrap()
        .replacen("\"schema\":2", "\"schema\":3", 1);
    let err = Document::from_json(&text).unwrap_err();
    assert!(
        matches!(
            err,
            DocumentError::Version {
                found: 3,
                expected: 2,
                ..
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("newer spinball"), "{err}");
    let err = doc.into_partial().unwrap_err();
    assert_eq!(
        err.to_string(),
        "a `spinball.lyapunov` document, not a `spinball.lyapunov.partial`"
    );
    assert!(matches!(
        Document::from_json("[1, 2]"),
        Err(DocumentError::Json(_))
    ));
    assert!(matches!(
        Document::from_json(r#"{"schema":2,"kind":"spinball.unknown"}"#),
        Err(DocumentError::Json(_))
    ));
}
