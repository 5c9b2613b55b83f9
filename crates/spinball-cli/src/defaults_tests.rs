//! The command line's defaults are the library's: every command parsed
//! with only its required options runs what the library's defaults run.

use clap::Parser;
use spinball_analysis::phase_space::FtleMapOptions;
use spinball_analysis::run::{
    Ensemble, FtleMapDefaults, KacDefaults, RunDefaults, SectionDefaults, SpectrumDefaults,
};
use spinball_core::SpinLaw;

use crate::run_args::{MethodArg, SamplerArg};
use crate::table_arg::read_table;
use crate::{Cli, Command};

fn parse(words: &[&str]) -> Command {
    let mut all = vec!["spinball"];
    all.extend_from_slice(words);
    Cli::try_parse_from(all).expect("the options parse").command
}

#[test]
fn an_ensemble_without_options_is_the_library_default_ensemble() {
    let table = read_table("stadium:a=1").unwrap();
    let law = SpinLaw::new(0.5).unwrap();
    let library = Ensemble::new(table, law);
    for command in ["lyapunov", "ftle"] {
        let run = match parse(&[command, "--table", "stadium:a=1", "--alpha", "0.5"]) {
            Command::Lyapunov(a) => a.run.clone(),
            Command::Ftle(a) => a.lyapunov.run.clone(),
            other => panic!("parsed {other:?}"),
        };
        let ensembles = run.ensembles().unwrap();
        assert_eq!(ensembles, vec![library.clone()], "{command}");
    }
}

#[test]
fn every_command_defaults_to_the_library_constants() {
    let Command::Spectrum(s) = parse(&["spectrum", "--table", "circle", "--alpha", "0"]) else {
        panic!("not spectrum");
    };
    assert_eq!(
        (s.run.ics, s.run.collisions, s.run.method, s.qr_interval),
        (
            SpectrumDefaults::ICS,
            SpectrumDefaults::COLLISIONS,
            MethodArg::from(SpectrumDefaults::METHOD),
            SpectrumDefaults::QR_INTERVAL
        )
    );
    assert_eq!(s.run.seed, RunDefaults::SEED);
    let Command::Section(s) = parse(&["section", "--table", "circle", "--alpha", "0"]) else {
        panic!("not section");
    };
    assert_eq!(
        (s.orbits, s.collisions, s.phase.seed),
        (
            SectionDefaults::ORBITS,
            SectionDefaults::COLLISIONS,
            RunDefaults::SEED
        )
    );
    let Command::Kac(k) = parse(&["kac", "--table", "circle", "--alpha", "0", "--s", "0,1"]) else {
        panic!("not kac");
    };
    assert_eq!(
        (k.orbits, k.collisions, k.phase.seed),
        (
            KacDefaults::ORBITS,
            KacDefaults::COLLISIONS,
            RunDefaults::SEED
        )
    );
    let Command::FtleMap(m) = parse(&["ftle-map", "--table", "circle", "--alpha", "0"]) else {
        panic!("not ftle-map");
    };
    let library = FtleMapOptions::new(
        FtleMapDefaults::COLUMNS as usize,
        FtleMapDefaults::ROWS as usize,
        spinball_analysis::phase_space::Slice::Spin(0.0),
    );
    assert_eq!(
        (m.columns, m.rows, m.collisions, m.phase.seed, m.threshold),
        (
            FtleMapDefaults::COLUMNS,
            FtleMapDefaults::ROWS,
            library.collisions,
            library.seed,
            library.threshold
        )
    );
    let Command::Trajectory(t) = parse(&["trajectory", "--table", "circle", "--alpha", "0"]) else {
        panic!("not trajectory");
    };
    assert_eq!(
        (t.seed, t.sampler),
        (RunDefaults::SEED, SamplerArg::from(RunDefaults::SAMPLER))
    );
}
