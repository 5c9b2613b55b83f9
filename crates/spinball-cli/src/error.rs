//! How a command fails, and the exit code each failure gets.
//!
//! | code | meaning |
//! |---|---|
//! | 0 | done (also when stdout's reader closed it early, as `\| head` does: the rest is not printed, files are still written) |
//! | 1 | the run failed (a trajectory error, an unwritable output, a full stdout) |
//! | 2 | bad usage: an option, a table, a file that cannot work |
//! | 3 | interrupted (signal or `--time-limit`); the checkpoint is written, rerun with `--resume` |

use std::fmt;
use std::path::PathBuf;
use std::process::ExitCode;

/// A failed command.
#[derive(Debug)]
pub enum CliError {
    /// The command cannot work as given (exit code 2).
    Usage(String),
    /// The run failed (exit code 1).
    Failed(String),
    /// Stdout was closed by its reader (a broken pipe, as `| head`
    /// leaves): nothing more is printed and the command succeeds (exit
    /// code 0, no message), as Unix tools do.
    StdoutClosed,
    /// Stopped by a signal or the time limit (exit code 3).
    Interrupted {
        /// Where what was finished was saved.
        checkpoint: Option<PathBuf>,
    },
}

impl CliError {
    /// A usage error from anything that displays.
    pub fn usage(e: impl fmt::Display) -> Self {
        CliError::Usage(e.to_string())
    }

    /// A run failure from anything that displays.
    pub fn failed(e: impl fmt::Display) -> Self {
        CliError::Failed(e.to_string())
    }

    /// The process exit code.
    pub fn code(&self) -> ExitCode {
        ExitCode::from(match self {
            CliError::StdoutClosed => 0,
            CliError::Failed(_) => 1,
            CliError::Usage(_) => 2,
            CliError::Interrupted { .. } => 3,
        })
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Usage(m) | CliError::Failed(m) => f.write_str(m),
            CliError::StdoutClosed => f.write_str("stdout was closed by its reader"),
            CliError::Interrupted {
                checkpoint: Some(p),
            } => write!(
                f,
                "interrupted; finished work saved in {} (rerun the same command with --resume)",
                p.display()
            ),
            CliError::Interrupted { checkpoint: None } => write!(
                f,
                "interrupted; nothing saved (give --json or --checkpoint to keep finished work)"
            ),
        }
    }
}
