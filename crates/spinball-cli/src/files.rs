//! Output paths the command line replaces whole (JSON results, partial
//! results, checkpoints, pictures): written through a temporary file
//! renamed over the path, and refused when the path exists and is not a
//! regular file, so a device, a FIFO or a directory is never replaced.
//!
//! A symbolic link is followed: the file it names is written (atomically,
//! next to that file) and the link stays a link. A link that names nothing
//! yet creates the file it names.

use std::fs::{self, FileType, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use crate::error::CliError;

/// How many links are followed before giving up (as Linux's `ELOOP`).
const MAX_LINKS: usize = 40;

/// The path a write to `path` lands on: `path` itself, or the end of the
/// chain of symbolic links that starts there.
fn resolve(path: &Path) -> io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(io::Error::other(format!(
        "more than {MAX_LINKS} levels of symbolic links"
    )))
}

/// What a file type is, for messages ("a directory").
fn kind(t: FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

/// Why `path` (which leads to `target`) must not be replaced: it exists
/// and is not a regular file.
fn refusal(path: &Path, target: &Path, t: FileType) -> String {
    let what = kind(t);
    let what = if what == "not a regular file" {
        "something other than a regular file"
    } else {
        what
    };
    let via = if target == path {
        String::new()
    } else {
        format!(" (through a link to {})", target.display())
    };
    format!(
        "{}{via} is {what}, not a regular file: refusing to replace it (give the path of a regular file or a new one)",
        path.display()
    )
}

/// The file a whole-file write to `path` replaces or creates (through
/// links), or why it may not: it exists and is not a regular file.
/// Errors other than that one (a missing directory, a permission) are
/// left to the write, which reports them.
fn replaceable(path: &Path) -> Result<PathBuf, String> {
    let target = resolve(path).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    match fs::symlink_metadata(&target) {
        Ok(m) if !m.is_file() => Err(refusal(path, &target, m.file_type())),
        _ => Ok(target),
    }
}

/// Check, before a run, that the output `path` given as `--flag` can be
/// replaced whole (it is written through a temporary file renamed over
/// it): it does not exist, or it is a regular file (or a link to one); and
/// a new file can be made in its directory ([`check_creatable`]).
///
/// # Errors
/// [`CliError::Usage`] naming the flag, the path and what is wrong.
pub fn check_writable(flag: &str, path: &Path) -> Result<(), CliError> {
    replaceable(path).map_err(|m| CliError::Usage(format!("--{flag} {m}")))?;
    check_creatable(flag, path)
}

/// Check, before a run, every output of a command: `--json` (replaced
/// whole, [`check_writable`]) and the files written into (`--csv`,
/// `--npy`, ...: [`check_creatable`]), each given with its flag.
///
/// # Errors
/// [`CliError::Usage`] naming the first flag that cannot work and why.
pub fn check_outputs(
    json: Option<&Path>,
    written_into: &[(&str, Option<&Path>)],
) -> Result<(), CliError> {
    if let Some(path) = json {
        check_writable("json", path)?;
    }
    for (flag, path) in written_into {
        if let Some(path) = path {
            check_creatable(flag, path)?;
        }
    }
    Ok(())
}

/// Check, before a run, that the output `path` given as `--flag` can be
/// written into: it exists (a file, or a device such as `/dev/stdout`,
/// written as a shell redirect would), or its directory exists and takes a
/// new file (a scratch file is made there and removed). A typo in a
/// directory is found before the computation, not after it.
///
/// # Errors
/// [`CliError::Usage`] naming the flag, the path and what is wrong.
pub fn check_creatable(flag: &str, path: &Path) -> Result<(), CliError> {
    if fs::metadata(path).is_ok() {
        return Ok(());
    }
    let usage = |m: String| CliError::Usage(format!("--{flag} {}: {m}", path.display()));
    let target = resolve(path).map_err(|e| usage(e.to_string()))?;
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if !dir.is_dir() {
        return Err(usage(format!(
            "the directory {} does not exist (create it first)",
            dir.display()
        )));
    }
    let mut probe = dir.join(".spinball-write-check");
    probe
        .as_mut_os_string()
        .push(format!("-{}", std::process::id()));
    match OpenOptions::new().write(true).create_new(true).open(&probe) {
        Ok(_) => {
            let _ = fs::remove_file(&probe);
            Ok(())
        }
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => Ok(()),
        Err(e) => Err(usage(format!("cannot write in {}: {e}", dir.display()))),
    }
}

/// Replace the file at `path` (through links) by `bytes` atomically: a
/// temporary file beside it, renamed over it, so a kill while writing
/// never leaves a torn file.
///
/// # Errors
/// [`CliError::Failed`] if `path` exists and is not a regular file, or the
/// file cannot be written.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    let target = replaceable(path).map_err(CliError::Failed)?;
    let fail = |e: io::Error| CliError::Failed(format!("cannot write {}: {e}", path.display()));
    let mut tmp = target.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    // A temporary file left by a killed run is ours to clear; anything
    // else in its place is not.
    match fs::symlink_metadata(&tmp) {
        Ok(m) if m.is_file() || m.file_type().is_symlink() => {
            fs::remove_file(&tmp).map_err(fail)?
        }
        Ok(m) => {
            return Err(CliError::Failed(format!(
                "cannot write {}: its temporary file {}",
                path.display(),
                refusal(&tmp, &tmp, m.file_type())
            )));
        }
        Err(_) => {}
    }
    // `create_new` neither follows a link nor opens what appeared since.
    let written = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&tmp)
        .and_then(|mut f| f.write_all(bytes))
        .and_then(|()| fs::rename(&tmp, &target));
    if let Err(e) = written {
        let _ = fs::remove_file(&tmp);
        return Err(fail(e));
    }
    Ok(())
}

/// Remove the file at `path` if it is a regular file (or a link to one:
/// the link is removed, not the file it names); anything else is left
/// alone.
pub fn remove_regular(path: &Path) {
    if fs::metadata(path).is_ok_and(|m| m.is_file()) {
        let _ = fs::remove_file(path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("spinball-cli-files-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn a_new_file_and_a_regular_file_are_written() {
        let dir = scratch("regular");
        let p = dir.join("a.json");
        write_atomic(&p, b"one").unwrap();
        assert_eq!(fs::read(&p).unwrap(), b"one");
        write_atomic(&p, b"two").unwrap();
        assert_eq!(fs::read(&p).unwrap(), b"two");
        assert!(!dir.join("a.json.tmp").exists());
    }

    #[test]
    fn a_directory_is_refused_and_kept() {
        let dir = scratch("dir");
        let p = dir.join("d");
        fs::create_dir(&p).unwrap();
        let e = write_atomic(&p, b"x").unwrap_err().to_string();
        assert!(e.contains("is a directory"), "{e}");
        assert!(e.contains(&p.display().to_string()), "{e}");
        assert!(fs::metadata(&p).unwrap().is_dir());
        let e = check_writable("json", &p).unwrap_err();
        assert!(matches!(e, CliError::Usage(_)));
        assert!(e.to_string().starts_with("--json "), "{e}");
    }

    #[test]
    fn a_missing_directory_is_found_before_the_run() {
        let dir = scratch("missing");
        check_writable("csv", &dir.join("new.csv")).unwrap();
        // The scratch file of the check is gone.
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 0);
        let typo = dir.join("reslts").join("x.csv");
        let e = check_creatable("csv", &typo).unwrap_err().to_string();
        assert!(e.starts_with("--csv "), "{e}");
        assert!(e.contains("does not exist"), "{e}");
        assert!(e.contains("reslts"), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn links_are_followed_and_kept() {
        let dir = scratch("links");
        let file = dir.join("file.json");
        fs::write(&file, "old").unwrap();
        let link = dir.join("link.json");
        std::os::unix::fs::symlink("file.json", &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(fs::symlink_metadata(&link).unwrap().is_symlink());
        assert_eq!(fs::read(&file).unwrap(), b"new");
        // A link to a link to nothing yet creates the file at the end.
        let far = dir.join("far.json");
        std::os::unix::fs::symlink(&far, dir.join("mid")).unwrap();
        std::os::unix::fs::symlink("mid", dir.join("near")).unwrap();
        write_atomic(&dir.join("near"), b"far").unwrap();
        assert_eq!(fs::read(&far).unwrap(), b"far");
        // A loop is an error, not a hang.
        std::os::unix::fs::symlink("loop", dir.join("loop")).unwrap();
        let e = write_atomic(&dir.join("loop"), b"x")
            .unwrap_err()
            .to_string();
        assert!(e.contains("symbolic links"), "{e}");
    }

    #[test]
    fn a_stale_temporary_file_is_cleared() {
        let dir = scratch("stale");
        let p = dir.join("r.json");
        fs::write(dir.join("r.json.tmp"), "torn").unwrap();
        write_atomic(&p, b"whole").unwrap();
        assert_eq!(fs::read(&p).unwrap(), b"whole");
        assert!(!dir.join("r.json.tmp").exists());
        fs::create_dir(dir.join("r.json.tmp")).unwrap();
        let e = write_atomic(&p, b"again").unwrap_err().to_string();
        assert!(e.contains("temporary file"), "{e}");
        assert_eq!(fs::read(&p).unwrap(), b"whole");
    }
}
