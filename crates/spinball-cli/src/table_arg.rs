//! The `--table` argument: a built-in table's spec or a table file.

use std::path::Path;

use spinball_geometry::{Built, TableFile};

use crate::error::CliError;

/// Read `arg`: a path ending in `.toml` or `.json` is a table file, anything
/// else a built-in spec (`stadium:a=1`, `sinai:L=2,R=1`, `circle`,
/// `rectangle:L=1,H=1`; with a hole `stadium:a=1,hole=0.2`; a Lorentz gas's
/// cell `lorentz:lattice=triangular,w=1,R=0.45`).
///
/// # Errors
/// [`CliError::Usage`] with the parser's or the table's message.
pub fn read_table(arg: &str) -> Result<Built, CliError> {
    let is_file = Path::new(arg)
        .extension()
        .is_some_and(|e| e == "toml" || e == "json");
    if is_file {
        TableFile::load(arg).map_err(CliError::usage)
    } else {
        arg.parse::<Built>().map_err(|e| {
            CliError::Usage(format!(
                "--table {arg}: {e} (or give a .toml/.json table file)"
            ))
        })
    }
}
