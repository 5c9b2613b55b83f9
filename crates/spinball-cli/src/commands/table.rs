//! `spinball table`: read a table (spec or file), say what it is, check
//! it, and draw it.

use std::path::PathBuf;

use clap::Args;
use serde::Serialize;
use spinball_analysis::run::{Engine, Ensemble};
use spinball_core::SpinLaw;
use spinball_geometry::Boundary;
use spinball_plot::{Plot, TablePlot};

use crate::documents::write_json;
use crate::error::CliError;
use crate::files::check_writable;
use crate::stdout::print;
use crate::table_arg::read_table;

/// The arguments of `spinball table`.
#[derive(Debug, Clone, Args)]
pub struct TableArgs {
    /// The table: a built-in spec or a table file. Reading it validates it
    /// (exit code 2 with the reason if it is not a table).
    pub table: String,
    /// Draw the table to this PNG (a regular file or a new path: it is
    /// removed if drawing fails).
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write the description as JSON here (a regular file, a link to one
    /// or a new path: it is replaced through a temporary file).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// No description on stdout.
    #[arg(long, short)]
    pub quiet: bool,
}

/// What `spinball table` says of a table.
#[derive(Debug, Clone, Serialize)]
struct Description {
    table: String,
    walls: usize,
    area: f64,
    perimeter: f64,
    curved_length: f64,
    bounding_box: [f64; 4],
    engine: Engine,
}

/// `spinball table`.
///
/// # Errors
/// [`CliError::Usage`] for a table that cannot be read or an output path
/// that is not a regular file; [`CliError::Failed`] for an output
/// (stdout included) that cannot be written.
pub fn table(args: &TableArgs) -> Result<(), CliError> {
    let table = read_table(&args.table)?;
    if let Some(path) = &args.json {
        check_writable("json", path)?;
    }
    if let Some(path) = &args.png {
        check_writable("png", path)?;
    }
    let shape = table.shape();
    let bb = table.aabb();
    let engine = Ensemble::new(table.clone(), SpinLaw::specular()).engine_used();
    let d = Description {
        table: table.to_string(),
        walls: shape.as_ref().map_or(0, spinball_geometry::Shape::walls),
        area: table.area(),
        perimeter: table.perimeter(),
        curved_length: table.curved_length(),
        bounding_box: [bb.min.x, bb.min.y, bb.max.x, bb.max.y],
        engine,
    };
    let shown = if args.quiet {
        Ok(())
    } else {
        print(&format!(
            "table          {}\n\
             walls          {}\n\
             area           {}\n\
             perimeter      {}\n\
             curved length  {}\n\
             bounding box   [{}, {}] x [{}, {}]\n\
             engine         {} (what ensembles on it run)\n",
            d.table,
            d.walls,
            d.area,
            d.perimeter,
            d.curved_length,
            d.bounding_box[0],
            d.bounding_box[2],
            d.bounding_box[1],
            d.bounding_box[3],
            d.engine.name()
        ))
    };
    // The files are written even if stdout failed.
    if let Some(path) = &args.json {
        write_json(path, &d)?;
    }
    if let Some(path) = &args.png {
        TablePlot::new(&table)
            .title(d.table.clone())
            .axes(true)
            .save_png(path, 800, 800)
            .map_err(CliError::failed)?;
    }
    shown
}
