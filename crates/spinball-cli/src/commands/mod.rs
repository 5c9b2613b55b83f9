//! One module per subcommand; each parses nothing itself beyond its
//! arguments and calls the library.

pub mod animate;
pub mod diffuse;
pub mod escape;
pub mod ftle;
pub mod ftle_map;
pub mod kac;
pub mod lyapunov;
pub mod merge;
pub mod orbits;
pub mod section;
pub mod slurm;
pub mod spectrum;
pub mod sweep;
pub mod table;
pub mod trajectory;
