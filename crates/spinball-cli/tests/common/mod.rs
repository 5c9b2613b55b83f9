//! What every test of the `spinball` binary needs: the binary, a fresh
//! directory, a run.
#![allow(dead_code)] // each test file uses its own part

use std::path::PathBuf;
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The binary under test.
pub const BIN: &str = env!("CARGO_BIN_EXE_spinball");

/// A fresh empty directory for one test.
pub fn scratch(name: &str) -> PathBuf {
    static N: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "spinball-cli-{}-{name}-{}",
        std::process::id(),
        N.fetch_add(1, Ordering::SeqCst)
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Run the binary with `args`.
pub fn spinball(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Run and check that it succeeded (stderr in the message if not).
pub fn ok(args: &[&str]) -> Output {
    let out = spinball(args);
    assert!(
        out.status.success(),
        "spinball {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}
