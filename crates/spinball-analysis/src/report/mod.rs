//! Reports: the one result schema. Estimates as flat records (CSV rows,
//! terminal tables) and as versioned JSON documents, and the one way to
//! merge the pieces of a run.
//!
//! A [`SweepRow`] holds one estimate with the derived quantities the paper's
//! figures plot (chaotic-fraction band, DHF product, collision rate), so it
//! reads from [`run`](crate::run), [`precision`](crate::precision) and
//! [`diagnostics`](crate::diagnostics) and is the top layer of the crate. A
//! [`BudgetRow`] holds one estimate's
//! [`ErrorBudget`](crate::precision::ErrorBudget); a [`TrajectoryRow`] one
//! initial condition. Every front (the command line, the examples, the
//! figures, the Python package) writes results through these types.
//!
//! # Rows
//!
//! Records are typed: the method is a [`MethodName`], the initial
//! conditions' origin an [`IcSource`], the stop reason a
//! [`StopReason`](crate::run::StopReason), the bias law a
//! [`BiasRegime`](crate::precision::BiasRegime); each is written as a stable
//! lowercase name (`fd`, `paper`, `target_reached`, `inverse_t`).
//!
//! # CSV
//!
//! With the `serde` feature, CSV goes through serde ([`write_csv`],
//! [`read_csv`]): the columns are the record's serde field names in
//! declaration order ([`csv_columns`]), so the header, the rows and reading
//! them back share one definition. Numbers are written in their shortest
//! round-trip form, an absent value (a conditional mean without chaotic
//! trajectories) as an empty field, a field with a comma (the spec
//! `rectangle:L=1,H=1`) quoted. Two tables:
//!
//! - one [`SweepRow`] per α ([`csv_string`]): `spinball lyapunov --csv`,
//!   the figures' `<stem>.csv`;
//! - one [`TrajectoryRow`] per initial condition ([`trajectories_csv`]):
//!   `alpha,index,exponent,per_collision,time,collisions`, written by
//!   `spinball ftle --per-ic` and the figures alike.
//!
//! # Documents
//!
//! Every JSON result is a [`Document`] (feature `serde`): one object with
//! `schema` (the layout version, [`SCHEMA`]), `kind` (which result) and the
//! fields of that kind:
//!
//! | `kind` | type | written by |
//! |---|---|---|
//! | `spinball.lyapunov` | [`LyapunovDocument`] | `lyapunov`, `ftle`, `merge` |
//! | `spinball.lyapunov.partial` | [`PartialDocument`] | a shard, a checkpoint |
//! | `spinball.spectrum` | [`SpectrumDocument`] | `spectrum`, `merge` |
//! | `spinball.spectrum.partial` | [`SpectrumDocument`] | a spectrum shard |
//! | `spinball.sweep` | [`SweepDocument`] | `sweep` |
//! | `spinball.multilevel` | [`MultilevelDocument`] | `lyapunov`, `sweep` with `--estimator multilevel` |
//! | `spinball.multilevel.partial` | [`MultilevelPartialDocument`] | a shard of `slurm --estimator multilevel` |
//! | `spinball.orbits` | [`OrbitsDocument`] | `orbits` |
//! | `spinball.section` | [`SectionDocument`] | `section`, `merge` |
//! | `spinball.section.partial` | [`SectionPartialDocument`] | a section shard |
//! | `spinball.kac` | [`KacDocument`] | `kac`, `merge` |
//! | `spinball.kac.partial` | [`KacPartialDocument`] | a Kac shard |
//! | `spinball.ftle_map` | [`FtleMapDocument`] | `ftle-map`, `merge` |
//! | `spinball.ftle_map.partial` | [`FtleMapPartialDocument`] | an FTLE map shard |
//! | `spinball.escape` | [`EscapeDocument`] | `escape`, `merge` |
//! | `spinball.escape.partial` | [`EscapePartialDocument`] | an escape shard |
//! | `spinball.diffusion` | [`DiffusionDocument`] | `diffuse`, `merge` |
//! | `spinball.diffusion.partial` | [`DiffusionPartialDocument`] | a diffusion shard |
//! | `spinball.figure` | [`FigureDocument`] | a figure example's `<stem>.json` |
//!
//! [`Document::from_json`] reads the header first: a file of another
//! schema is refused with [`DocumentError::Version`], naming the schema
//! found, the spinball version that wrote it and the schema expected.
//! Files of spinball 0.1 have no `schema` (schema 1); their finished
//! Lyapunov results have today's fields and are read, the rest (partial
//! runs without checksums, sweeps without a kind) are refused.
//!
//! # Merging
//!
//! A sharded or interrupted run is joined in one place:
//! [`PartialDocument::merge`], [`SpectrumDocument::merge`],
//! [`SectionPartialDocument::merge`], [`KacPartialDocument::merge`],
//! [`EscapePartialDocument::merge`] and [`DiffusionPartialDocument::merge`]
//! (FTLE maps: [`FtleMapPart::merge`](crate::phase_space::FtleMapPart::merge)), after
//! `same_run` has compared the pieces field by field. Every refusal is a
//! [`MergeError`](crate::run::MergeError), the error of
//! [`merge_partials`](crate::run::merge_partials) too; a front adds the
//! file names.

#[cfg(feature = "serde")]
mod diffusion;
#[cfg(feature = "serde")]
mod document;
#[cfg(feature = "serde")]
mod escape;
#[cfg(feature = "serde")]
mod figure;
mod lyapunov;
#[cfg(feature = "serde")]
mod multilevel;
mod names;
#[cfg(feature = "serde")]
mod open_run;
#[cfg(feature = "serde")]
mod orbits;
mod partial;
#[cfg(feature = "serde")]
mod phase_space;
mod rows;
mod spectrum;
mod sweep;
#[cfg(feature = "serde")]
mod table;
mod trajectories;

#[cfg(feature = "serde")]
pub use diffusion::{DIFFUSION_CSV_COLUMNS, DiffusionDocument, DiffusionPartialDocument};
#[cfg(feature = "serde")]
pub use document::{Document, DocumentError, SCHEMA, SCHEMA_0_1};
#[cfg(feature = "serde")]
pub use escape::{BudgetRecord, ESCAPE_CSV_COLUMNS, EscapeDocument, EscapePartialDocument};
#[cfg(feature = "serde")]
pub use figure::FigureDocument;
pub use lyapunov::LyapunovDocument;
#[cfg(feature = "serde")]
pub use multilevel::{
    MultilevelDocument, MultilevelPartialDocument, MultilevelPoint, MultilevelShardPoint,
};
pub use names::{IcSource, MethodName};
#[cfg(feature = "serde")]
pub use open_run::{OpenRun, OpenRunHead};
#[cfg(feature = "serde")]
pub use orbits::OrbitsDocument;
pub use partial::PartialDocument;
#[cfg(feature = "serde")]
pub use phase_space::{
    FtleMapDocument, FtleMapPartialDocument, KacDocument, KacPartialDocument, PhaseHead,
    SectionDocument, SectionPartialDocument,
};
pub use rows::{BudgetRow, SweepRow, sweep_rows};
pub use spectrum::{SpectrumDocument, SpectrumRow};
pub use sweep::{SweepDocument, SweepPoint};
#[cfg(feature = "serde")]
pub use table::{
    CsvError, csv_columns, csv_string, csv_text, read_csv, trajectories_csv, write_csv,
};
pub use trajectories::{TrajectoryRow, trajectory_rows};
