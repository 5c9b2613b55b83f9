//! The criterion benchmarks of the `spinball` facade, in a package of their
//! own so that the examples and tests of `spinball` do not compile
//! criterion. Nothing here is a library; run them with
//!
//! ```sh
//! cargo bench -p spinball-bench --bench collision
//! cargo bench -p spinball-bench --bench analysis
//! ```
//!
//! The lane kernels' benchmark is `cargo bench -p spinball-lanes --bench
//! lanes`; how fast on which CPU is in docs/PERFORMANCE.md.
