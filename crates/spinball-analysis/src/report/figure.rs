//! The document of a figure example: who made it (figure, mode, seed,
//! threads, version) and the fields the figure computed, as one `kind` of
//! the result schema (`spinball.figure`), so a figure's `<stem>.json` is
//! read like every other result file.
//!
//! Documented in the group docs (`report/mod.rs`), section "Documents".

use serde::{Deserialize, Serialize};

/// What a figure example wrote to its `<stem>.json` (kind
/// `spinball.figure`): the header, then the figure's own fields at the top
/// level (its curves, its statistics), as they were before the figures
/// joined the schema.
///
/// ```
/// use spinball_analysis::report::{Document, FigureDocument};
///
/// let mut doc = FigureDocument::new("fig_demo", "quick", 1, 2);
/// doc.data.insert("lambda".into(), serde_json::json!(0.18));
/// let text = Document::Figure(doc.clone()).to_json()?;
/// assert!(text.starts_with(r#"{"schema":2,"kind":"spinball.figure","figure":"fig_demo""#));
/// assert_eq!(Document::from_json(&text)?.into_figure()?, doc);
/// # Ok::<(), spinball_analysis::report::DocumentError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FigureDocument {
    /// The example that wrote it.
    pub figure: String,
    /// `quick`, `default` or `paper`.
    pub mode: String,
    /// Seed of the initial conditions.
    pub seed: u64,
    /// Worker threads used (results do not depend on it).
    pub threads: usize,
    /// Version of the crates that computed it.
    pub version: String,
    /// The figure's own fields.
    #[serde(flatten)]
    pub data: serde_json::Map<String, serde_json::Value>,
}

impl FigureDocument {
    /// The header of a figure run by this build, without fields yet.
    #[must_use]
    pub fn new(figure: &str, mode: &str, seed: u64, threads: usize) -> Self {
        FigureDocument {
            figure: figure.into(),
            mode: mode.into(),
            seed,
            threads,
            version: env!("CARGO_PKG_VERSION").into(),
            data: serde_json::Map::new(),
        }
    }
}
