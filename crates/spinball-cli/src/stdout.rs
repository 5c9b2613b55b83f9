//! What the commands print on stdout, written so that a failed write is
//! an error and not a panic: a full device fails the command (exit code
//! 1), a reader that went away (`| head`) ends it quietly (exit code 0).

use std::io::{self, ErrorKind, Write};

use crate::error::CliError;

/// The error of a failed write to stdout.
pub fn stdout_error(e: &io::Error) -> CliError {
    if e.kind() == ErrorKind::BrokenPipe {
        CliError::StdoutClosed
    } else {
        CliError::Failed(format!("cannot write to stdout: {e}"))
    }
}

/// Print `text` on stdout, flushed.
///
/// # Errors
/// [`CliError::StdoutClosed`] on a broken pipe, [`CliError::Failed`] for
/// any other failed write (a full device).
pub fn print(text: &str) -> Result<(), CliError> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| stdout_error(&e))
}
