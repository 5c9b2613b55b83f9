//! One module per subcommand; each parses nothing itself beyond its
//! arguments and calls the library.

pub mod ftle;
pub mod lyapunov;
pub mod merge;
pub mod orbits;
pub mod slurm;
pub mod spectrum;
pub mod sweep;
pub mod table;
pub mod trajectory;
