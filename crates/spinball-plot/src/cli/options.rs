//! The one command-line reader behind every example.
//!
//! An example declares its options as data ([`Opt`]: a long name, maybe a
//! short alias, maybe a value, a help line) and [`parse_options`] reads the
//! arguments against that list: `--seed 7` and `--seed=7`, flags such as
//! `--quick`, `-h`/`--help`. Anything it cannot read is an [`ArgError`]
//! that names the option, so every example rejects bad input the same way
//! (the message and the usage on stderr, exit code 2; see [`exit_on_error`]).
//! The figure arguments ([`FigureArgs`](super::FigureArgs)) and the `sweep`
//! machine interface ([`SweepArgs`](super::SweepArgs)) are two option lists
//! read by this same reader.

use std::fmt::{self, Display, Write as _};
use std::str::FromStr;

use thiserror::Error;

/// One option of a command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Opt {
    /// Long name without the dashes (`seed` for `--seed`).
    pub name: &'static str,
    /// One-letter alias (`o` for `-o`).
    pub short: Option<char>,
    /// Name of the value in the usage (`N` in `--seed N`); `None` for a flag.
    pub value: Option<&'static str>,
    /// The option must be given.
    pub required: bool,
    /// One line of help.
    pub help: &'static str,
}

impl Opt {
    /// A flag without a value (`--quick`).
    #[must_use]
    pub const fn flag(name: &'static str, help: &'static str) -> Opt {
        Opt {
            name,
            short: None,
            value: None,
            required: false,
            help,
        }
    }

    /// An option with a value (`--seed N`).
    #[must_use]
    pub const fn value(name: &'static str, metavar: &'static str, help: &'static str) -> Opt {
        Opt {
            value: Some(metavar),
            ..Opt::flag(name, help)
        }
    }

    /// The same option with a one-letter alias.
    #[must_use]
    pub const fn short(self, alias: char) -> Opt {
        Opt {
            short: Some(alias),
            ..self
        }
    }

    /// The same option, required.
    #[must_use]
    pub const fn required(self) -> Opt {
        Opt {
            required: true,
            ..self
        }
    }

    /// `--seed N` or `--quick`.
    fn spelled(&self) -> String {
        match self.value {
            Some(v) => format!("--{} {v}", self.name),
            None => format!("--{}", self.name),
        }
    }
}

/// What the command line asked for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Parsed<T> {
    /// Run with these arguments.
    Run(T),
    /// Print the usage and stop (`-h` or `--help` anywhere).
    Help,
}

/// A command line that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum ArgError {
    /// An argument that is not one of the options.
    #[error("unknown argument `{0}`")]
    Unknown(String),
    /// An option that needs a value came last or before another option.
    #[error("`--{0}` needs a value")]
    MissingValue(&'static str),
    /// A flag was given a value (`--quick=1`).
    #[error("`--{0}` takes no value")]
    UnexpectedValue(&'static str),
    /// An option was given twice.
    #[error("`--{0}` given twice")]
    Repeated(&'static str),
    /// A required option is missing.
    #[error("missing `--{0}`")]
    Missing(&'static str),
    /// Two options that exclude each other.
    #[error("`--{0}` and `--{1}` exclude each other")]
    Conflict(&'static str, &'static str),
    /// A value that cannot be used.
    #[error("`--{option} {value}`: {why}")]
    Invalid {
        /// The option.
        option: &'static str,
        /// The value given.
        value: String,
        /// What is wrong with it.
        why: String,
    },
}

impl ArgError {
    /// An [`ArgError::Invalid`].
    pub fn invalid(option: &'static str, value: impl Into<String>, why: impl Display) -> Self {
        ArgError::Invalid {
            option,
            value: value.into(),
            why: why.to_string(),
        }
    }
}

/// The options found on a command line, in the order given.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Matches {
    given: Vec<(&'static str, Option<String>)>,
}

impl Matches {
    /// Whether the flag or option `name` was given.
    pub fn flag(&self, name: &str) -> bool {
        self.given.iter().any(|(n, _)| *n == name)
    }

    /// The value of `name`, if given.
    pub fn value(&self, name: &str) -> Option<&str> {
        self.given
            .iter()
            .find(|(n, _)| *n == name)
            .and_then(|(_, v)| v.as_deref())
    }

    /// The value of `name` read as a `T`, if given.
    ///
    /// # Errors
    /// [`ArgError::Invalid`] with `T`'s parse error.
    pub fn get<T>(&self, name: &str) -> Result<Option<T>, ArgError>
    where
        T: FromStr,
        T::Err: Display,
    {
        let Some((option, Some(v))) = self.given.iter().find(|(n, _)| *n == name) else {
            return Ok(None);
        };
        v.trim()
            .parse()
            .map(Some)
            .map_err(|e| ArgError::invalid(option, v.clone(), e))
    }

    /// The value of `name` read as a `T`, or `default` if not given.
    ///
    /// # Errors
    /// As [`get`](Self::get).
    pub fn get_or<T>(&self, name: &str, default: T) -> Result<T, ArgError>
    where
        T: FromStr,
        T::Err: Display,
    {
        Ok(self.get(name)?.unwrap_or(default))
    }
}

/// Read `args` (without the program name) against `options`.
///
/// `-h` or `--help` anywhere gives [`Parsed::Help`]. A value may follow its
/// option (`--seed 7`) or be attached (`--seed=7`); a following argument
/// that starts with `--` is not taken as a value.
///
/// # Errors
/// The first [`ArgError`]: unknown arguments, missing or unexpected values,
/// repeated options, then missing required options.
pub fn parse_options<I, S>(options: &[Opt], args: I) -> Result<Parsed<Matches>, ArgError>
where
    I: IntoIterator<Item = S>,
    S: Into<String>,
{
    let args: Vec<String> = args.into_iter().map(Into::into).collect();
    if args.iter().any(|a| a == "-h" || a == "--help") {
        return Ok(Parsed::Help);
    }
    let mut matches = Matches::default();
    let mut it = args.into_iter();
    while let Some(arg) = it.next() {
        let (key, inline) = match arg.split_once('=') {
            Some((k, v)) if k.starts_with("--") => (k.to_string(), Some(v.to_string())),
            _ => (arg.clone(), None),
        };
        let opt = options.iter().find(|o| {
            key.strip_prefix("--") == Some(o.name)
                || o.short.is_some_and(|c| key == format!("-{c}"))
        });
        let Some(opt) = opt else {
            return Err(ArgError::Unknown(arg));
        };
        if matches.flag(opt.name) {
            return Err(ArgError::Repeated(opt.name));
        }
        let value = match (opt.value, inline) {
            (None, None) => None,
            (None, Some(_)) => return Err(ArgError::UnexpectedValue(opt.name)),
            (Some(_), Some(v)) => Some(v),
            (Some(_), None) => {
                let v = it.next().filter(|v| !v.starts_with("--"));
                Some(v.ok_or(ArgError::MissingValue(opt.name))?)
            }
        };
        matches.given.push((opt.name, value));
    }
    if let Some(missing) = options.iter().find(|o| o.required && !matches.flag(o.name)) {
        return Err(ArgError::Missing(missing.name));
    }
    Ok(Parsed::Run(matches))
}

/// The usage text: `about`, the synopsis `usage: {command} [options]` and
/// one line per option (and `-h, --help`).
pub fn usage_text(about: &str, command: &str, options: &[Opt]) -> String {
    let synopsis: Vec<String> = options
        .iter()
        .map(|o| {
            if o.required {
                o.spelled()
            } else {
                format!("[{}]", o.spelled())
            }
        })
        .collect();
    let spelled: Vec<String> = options
        .iter()
        .map(|o| match o.short {
            Some(c) => format!("-{c}, {}", o.spelled()),
            None => o.spelled(),
        })
        .collect();
    let width = spelled.iter().map(|s| s.chars().count()).max().unwrap_or(0);
    let mut s = String::new();
    if !about.is_empty() {
        let _ = write!(s, "{about}\n\n");
    }
    let _ = write!(s, "usage: {command} {}\n\noptions:", synopsis.join(" "));
    for (o, name) in options.iter().zip(&spelled) {
        let _ = write!(s, "\n  {name:<width$}  {}", o.help);
    }
    let _ = write!(s, "\n  {:<width$}  this text", "-h, --help");
    s
}

/// The arguments, or the end of the process: on [`Parsed::Help`] print
/// `usage` to stdout and exit 0; on an error print `name: error`, a blank
/// line and `usage` to stderr and exit 2.
pub fn exit_on_error<T>(name: &str, usage: &str, parsed: Result<Parsed<T>, ArgError>) -> T {
    match parsed {
        Ok(Parsed::Run(t)) => t,
        Ok(Parsed::Help) => {
            println!("{usage}");
            std::process::exit(0)
        }
        Err(e) => {
            eprintln!("{name}: {e}\n\n{usage}");
            std::process::exit(2)
        }
    }
}

impl fmt::Display for Opt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.spelled())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const OPTIONS: [Opt; 4] = [
        Opt::flag("quick", "small"),
        Opt::value("out", "DIR", "where").short('o'),
        Opt::value("seed", "N", "seed"),
        Opt::value("table", "SPEC", "table").required(),
    ];

    fn parse(args: &[&str]) -> Result<Matches, ArgError> {
        match parse_options(&OPTIONS, args.iter().copied())? {
            Parsed::Run(m) => Ok(m),
            Parsed::Help => panic!("help"),
        }
    }

    #[test]
    fn values_flags_and_aliases() {
        let m = parse(&["--table=stadium:a=1", "--quick", "-o", "d", "--seed", "7"]).unwrap();
        assert!(m.flag("quick"));
        assert_eq!(m.value("table"), Some("stadium:a=1"));
        assert_eq!(m.value("out"), Some("d"));
        assert_eq!(m.get::<u64>("seed"), Ok(Some(7)));
        assert_eq!(m.get_or::<u64>("missing", 3), Ok(3));
        assert_eq!(m.value("quick"), None);
        // Help wins over everything else.
        assert_eq!(parse_options(&OPTIONS, ["--bad", "-h"]), Ok(Parsed::Help));
    }

    #[test]
    fn errors_name_the_option() {
        assert_eq!(
            parse(&["--table", "x", "--fast"]),
            Err(ArgError::Unknown("--fast".into()))
        );
        assert_eq!(
            parse(&["--table", "x", "pos"]),
            Err(ArgError::Unknown("pos".into()))
        );
        assert_eq!(parse(&["--table"]), Err(ArgError::MissingValue("table")));
        assert_eq!(
            parse(&["--table", "--quick"]),
            Err(ArgError::MissingValue("table"))
        );
        assert_eq!(
            parse(&["--table", "x", "--quick=1"]),
            Err(ArgError::UnexpectedValue("quick"))
        );
        assert_eq!(
            parse(&["--table", "x", "--table", "y"]),
            Err(ArgError::Repeated("table"))
        );
        assert_eq!(parse(&["--quick"]), Err(ArgError::Missing("table")));
        let m = parse(&["--table", "x", "--seed", "-1"]).unwrap();
        let e = m.get::<u64>("seed").unwrap_err();
        assert!(matches!(&e, ArgError::Invalid { option: "seed", value, .. } if value == "-1"));
        assert!(e.to_string().starts_with("`--seed -1`: "), "{e}");
    }

    #[test]
    fn usage_lists_every_option() {
        let u = usage_text("About.", "prog", &OPTIONS);
        assert!(
            u.starts_with("About.\n\nusage: prog [--quick] [--out DIR] [--seed N] --table SPEC\n")
        );
        assert!(u.contains("\n  -o, --out DIR  where\n"), "{u}");
        assert!(u.ends_with("\n  -h, --help     this text"), "{u}");
    }
}
