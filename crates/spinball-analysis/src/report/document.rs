//! One versioned JSON document for every result a front writes: finished
//! and partial Lyapunov runs, spectra, sweeps, multilevel runs, stability
//! diagrams, sections, Kac return times, FTLE maps, escape and diffusion
//! runs. Each file says what it is
//! (`kind`) and which layout it follows (`schema`), so a reader refuses a
//! file it cannot read with a message naming both versions instead of a
//! field error deep inside.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::diffusion::{DiffusionDocument, DiffusionPartialDocument};
use super::escape::{EscapeDocument, EscapePartialDocument};
use super::figure::FigureDocument;
use super::lyapunov::LyapunovDocument;
use super::multilevel::{MultilevelDocument, MultilevelPartialDocument};
use super::orbits::OrbitsDocument;
use super::partial::PartialDocument;
use super::phase_space::{
    FtleMapDocument, FtleMapPartialDocument, KacDocument, KacPartialDocument, SectionDocument,
    SectionPartialDocument,
};
use super::spectrum::SpectrumDocument;
use super::sweep::SweepDocument;

/// The layout version this build writes and reads. Files written by
/// spinball 0.1 carry no `schema`: they are schema 1.
pub const SCHEMA: u32 = 2;

/// The schema of files without a `schema` field (spinball 0.1).
pub const SCHEMA_0_1: u32 = 1;

/// Every result document, told apart by its `kind`. As JSON it is one
/// object: `schema` ([`SCHEMA`]), `kind`, then the fields of the kind.
///
/// ```
/// use spinball_analysis::report::{Document, LyapunovDocument, SCHEMA};
///
/// let doc = Document::Lyapunov(LyapunovDocument::new(Vec::new()));
/// let text = doc.to_json()?;
/// assert_eq!(text, r#"{"schema":2,"kind":"spinball.lyapunov","points":[]}"#);
/// assert_eq!(Document::from_json(&text)?, doc);
/// # Ok::<(), spinball_analysis::report::DocumentError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum Document {
    /// A finished Lyapunov run (`spinball lyapunov`, `ftle`, `merge`).
    #[serde(rename = "spinball.lyapunov")]
    Lyapunov(LyapunovDocument),
    /// A shard or a checkpoint of a Lyapunov run.
    #[serde(rename = "spinball.lyapunov.partial")]
    LyapunovPartial(PartialDocument),
    /// A finished spectrum run.
    #[serde(rename = "spinball.spectrum")]
    Spectrum(SpectrumDocument),
    /// A shard of a spectrum run.
    #[serde(rename = "spinball.spectrum.partial")]
    SpectrumPartial(SpectrumDocument),
    /// λ(α) on one table with each point's error budget (`spinball sweep`).
    #[serde(rename = "spinball.sweep")]
    Sweep(SweepDocument),
    /// λ by the multilevel estimator, one point per α (`spinball
    /// lyapunov` or `sweep` with `--estimator multilevel`).
    #[serde(rename = "spinball.multilevel")]
    Multilevel(MultilevelDocument),
    /// A shard of a multilevel campaign (`spinball slurm --estimator
    /// multilevel`).
    #[serde(rename = "spinball.multilevel.partial")]
    MultilevelPartial(MultilevelPartialDocument),
    /// The stability diagram of periodic orbits (`spinball orbits`).
    #[serde(rename = "spinball.orbits")]
    Orbits(OrbitsDocument),
    /// A Birkhoff section (`spinball section`, `merge`).
    #[serde(rename = "spinball.section")]
    Section(SectionDocument),
    /// One shard of a Birkhoff section.
    #[serde(rename = "spinball.section.partial")]
    SectionPartial(SectionPartialDocument),
    /// Return times against Kac's lemma (`spinball kac`, `merge`).
    #[serde(rename = "spinball.kac")]
    Kac(KacDocument),
    /// One shard of a comparison with Kac's lemma.
    #[serde(rename = "spinball.kac.partial")]
    KacPartial(KacPartialDocument),
    /// A finished FTLE map (`spinball ftle-map`, `merge`).
    #[serde(rename = "spinball.ftle_map")]
    FtleMap(FtleMapDocument),
    /// One shard of an FTLE map.
    #[serde(rename = "spinball.ftle_map.partial")]
    FtleMapPartial(FtleMapPartialDocument),
    /// Escape from an open table: per-ball records and their summary
    /// (`spinball escape`, `merge`).
    #[serde(rename = "spinball.escape")]
    Escape(EscapeDocument),
    /// One shard of an escape run.
    #[serde(rename = "spinball.escape.partial")]
    EscapePartial(EscapePartialDocument),
    /// Diffusion through a periodic table: per-IC displacements and their
    /// summary (`spinball diffuse`, `merge`).
    #[serde(rename = "spinball.diffusion")]
    Diffusion(DiffusionDocument),
    /// One shard of a diffusion run.
    #[serde(rename = "spinball.diffusion.partial")]
    DiffusionPartial(DiffusionPartialDocument),
    /// What a figure example computed (`<stem>.json` of `fig_*`).
    #[serde(rename = "spinball.figure")]
    Figure(FigureDocument),
}

/// Why a document could not be read or written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum DocumentError {
    /// Not JSON, or not the fields of its kind (an edited or damaged file
    /// included: the checks of partial runs and spectra report here).
    #[error("not a valid spinball result: {0}")]
    Json(#[from] serde_json::Error),
    /// Written with a layout this build does not read.
    #[error(
        "written {} with result schema {found}; this build (spinball {}) reads schema {expected}: rerun the command that made it{}",
        written_by.as_ref().map_or_else(|| "by another spinball".to_string(), |v| format!("by spinball {v}")),
        env!("CARGO_PKG_VERSION"),
        if *found < *expected { " with this version" } else { ", or read it with a newer spinball" }
    )]
    Version {
        /// The schema of the file (1 for a file without one).
        found: u32,
        /// The schema this build reads ([`SCHEMA`]).
        expected: u32,
        /// The crate version the file names, if it names one.
        written_by: Option<String>,
    },
    /// A document of another kind than the one asked for.
    #[error("a `{found}` document, not a `{expected}`")]
    Kind {
        /// The kind of the file.
        found: String,
        /// The kind asked for.
        expected: &'static str,
    },
}

/// What a reader looks at before the fields: kind, schema and the
/// version the file names (top-level, or that of its first point).
#[derive(Deserialize)]
struct Header {
    #[serde(default)]
    kind: Option<String>,
    #[serde(default)]
    schema: Option<u32>,
    #[serde(default)]
    version: Option<String>,
    #[serde(default)]
    points: Vec<PointHeader>,
}

#[derive(Deserialize)]
struct PointHeader {
    #[serde(default)]
    version: Option<String>,
}

/// A document as written: the schema, then the kind and its fields.
#[derive(Serialize)]
struct Versioned<'a> {
    schema: u32,
    #[serde(flatten)]
    document: &'a Document,
}

impl Document {
    /// The document's `kind`, e.g. `spinball.lyapunov`.
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            Document::Lyapunov(_) => "spinball.lyapunov",
            Document::LyapunovPartial(_) => "spinball.lyapunov.partial",
            Document::Spectrum(_) => "spinball.spectrum",
            Document::SpectrumPartial(_) => "spinball.spectrum.partial",
            Document::Sweep(_) => "spinball.sweep",
            Document::Multilevel(_) => "spinball.multilevel",
            Document::MultilevelPartial(_) => "spinball.multilevel.partial",
            Document::Orbits(_) => "spinball.orbits",
            Document::Section(_) => "spinball.section",
            Document::SectionPartial(_) => "spinball.section.partial",
            Document::Kac(_) => "spinball.kac",
            Document::KacPartial(_) => "spinball.kac.partial",
            Document::FtleMap(_) => "spinball.ftle_map",
            Document::FtleMapPartial(_) => "spinball.ftle_map.partial",
            Document::Escape(_) => "spinball.escape",
            Document::EscapePartial(_) => "spinball.escape.partial",
            Document::Diffusion(_) => "spinball.diffusion",
            Document::DiffusionPartial(_) => "spinball.diffusion.partial",
            Document::Figure(_) => "spinball.figure",
        }
    }

    /// Read a document. Files of this [`SCHEMA`] are read whole; a
    /// finished Lyapunov result of spinball 0.1 (no `schema`, same fields)
    /// is read too; every other layout is refused.
    ///
    /// # Errors
    /// [`DocumentError::Version`] for a schema this build does not read
    /// (naming it, the spinball version that wrote it and [`SCHEMA`]);
    /// [`DocumentError::Json`] for text that is not a document or a file
    /// that does not hold together.
    pub fn from_json(text: &str) -> Result<Document, DocumentError> {
        let header: Header = serde_json::from_str(text)?;
        let found = header.schema.unwrap_or(SCHEMA_0_1);
        let readable = found == SCHEMA
            || (found == SCHEMA_0_1
                && header.schema.is_none()
                && header.kind.as_deref() == Some("spinball.lyapunov"));
        if !readable {
            return Err(DocumentError::Version {
                found,
                expected: SCHEMA,
                written_by: header
                    .version
                    .or_else(|| header.points.into_iter().find_map(|p| p.version)),
            });
        }
        let mut doc: Document = serde_json::from_str(text)?;
        if let Document::Figure(f) = &mut doc {
            // The figure's own fields are open: the header's `schema` is not one.
            f.data.remove("schema");
        }
        Ok(doc)
    }

    /// The document as compact JSON (one line).
    ///
    /// # Errors
    /// [`DocumentError::Json`] if a value cannot be written (a partial run
    /// or a spectrum that does not hold together).
    pub fn to_json(&self) -> Result<String, DocumentError> {
        Ok(serde_json::to_string(&self.versioned())?)
    }

    /// The document as indented JSON (two spaces a level).
    ///
    /// # Errors
    /// As [`Document::to_json`].
    pub fn to_json_pretty(&self) -> Result<String, DocumentError> {
        self.to_json_indent(2)
    }

    /// The document as JSON indented by `indent` spaces a level.
    ///
    /// # Errors
    /// As [`Document::to_json`].
    pub fn to_json_indent(&self, indent: usize) -> Result<String, DocumentError> {
        use serde::Serialize;
        let pad = vec![b' '; indent];
        let mut out = Vec::new();
        let format = serde_json::ser::PrettyFormatter::with_indent(&pad);
        self.versioned()
            .serialize(&mut serde_json::Serializer::with_formatter(
                &mut out, format,
            ))?;
        Ok(String::from_utf8(out).expect("serde_json writes UTF-8"))
    }

    fn versioned(&self) -> Versioned<'_> {
        Versioned {
            schema: SCHEMA,
            document: self,
        }
    }

    /// The finished Lyapunov run this document is.
    ///
    /// # Errors
    /// [`DocumentError::Kind`] for any other kind.
    pub fn into_lyapunov(self) -> Result<LyapunovDocument, DocumentError> {
        match self {
            Document::Lyapunov(d) => Ok(d),
            other => Err(other.not("spinball.lyapunov")),
        }
    }

    /// The piece of a Lyapunov run this document is.
    ///
    /// # Errors
    /// [`DocumentError::Kind`] for any other kind.
    pub fn into_partial(self) -> Result<PartialDocument, DocumentError> {
        match self {
            Document::LyapunovPartial(d) => Ok(d),
            other => Err(other.not("spinball.lyapunov.partial")),
        }
    }

    /// The figure this document is.
    ///
    /// # Errors
    /// [`DocumentError::Kind`] for any other kind.
    pub fn into_figure(self) -> Result<FigureDocument, DocumentError> {
        match self {
            Document::Figure(d) => Ok(d),
            other => Err(other.not("spinball.figure")),
        }
    }

    /// The sweep this document is.
    ///
    /// # Errors
    /// [`DocumentError::Kind`] for any other kind.
    pub fn into_sweep(self) -> Result<SweepDocument, DocumentError> {
        match self {
            Document::Sweep(d) => Ok(d),
            other => Err(other.not("spinball.sweep")),
        }
    }

    /// The shard of an FTLE map this document is.
    ///
    /// # Errors
    /// [`DocumentError::Kind`] for any other kind.
    pub fn into_ftle_map_partial(self) -> Result<FtleMapPartialDocument, DocumentError> {
        match self {
            Document::FtleMapPartial(d) => Ok(d),
            other => Err(other.not("spinball.ftle_map.partial")),
        }
    }

    pub(super) fn not(&self, expected: &'static str) -> DocumentError {
        DocumentError::Kind {
            found: self.kind().to_string(),
            expected,
        }
    }
}

impl LyapunovDocument {
    /// Read Lyapunov results: a `spinball.lyapunov` document (what the
    /// command line and Python's `to_json` write), or one bare estimate (a
    /// `LyapunovResult.to_json()` of spinball 0.2) as a document of one
    /// point.
    ///
    /// # Errors
    /// As [`Document::from_json`]; [`DocumentError::Kind`] for a document
    /// of another kind.
    pub fn from_json(text: &str) -> Result<LyapunovDocument, DocumentError> {
        let header: Header = serde_json::from_str(text)?;
        if header.kind.is_none()
            && header.schema.is_none()
            && header.points.is_empty()
            && let Ok(estimate) = serde_json::from_str::<crate::run::LyapunovEstimate>(text)
        {
            return Ok(LyapunovDocument::new(vec![estimate]));
        }
        Document::from_json(text)?.into_lyapunov()
    }
}
