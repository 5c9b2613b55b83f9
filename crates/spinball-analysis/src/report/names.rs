//! The names a flat record carries instead of strings: how the exponent
//! was measured and where the initial conditions came from.
//!
//! A [`Method`] holds δ0 and a `None` sampler means explicit states; a CSV
//! column holds one word. These enums are that word, typed, serialised as
//! the stable lowercase names scripts read (`fd`, `tangent`; `paper`,
//! `microcanonical`, `states`).

use std::fmt;

use spinball_core::Sampler;

use crate::estimators::Method;

/// How the exponent was measured, without its parameter: `fd` or
/// `tangent`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
#[non_exhaustive]
pub enum MethodName {
    /// The paper's finite-difference Benettin method.
    Fd,
    /// Exact tangent dynamics.
    Tangent,
}

impl MethodName {
    /// `fd` or `tangent`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            MethodName::Fd => "fd",
            MethodName::Tangent => "tangent",
        }
    }
}

impl From<Method> for MethodName {
    fn from(method: Method) -> Self {
        match method {
            Method::FiniteDifference { .. } => MethodName::Fd,
            Method::Tangent => MethodName::Tangent,
        }
    }
}

/// Where the initial conditions came from: a [`Sampler`] or explicit
/// states.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
#[non_exhaustive]
pub enum IcSource {
    /// [`Sampler::Paper`].
    Paper,
    /// [`Sampler::Microcanonical`].
    Microcanonical,
    /// States given one by one (no sampler).
    States,
}

impl IcSource {
    /// `paper`, `microcanonical` or `states`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            IcSource::Paper => "paper",
            IcSource::Microcanonical => "microcanonical",
            IcSource::States => "states",
        }
    }
}

impl From<Option<Sampler>> for IcSource {
    fn from(sampler: Option<Sampler>) -> Self {
        match sampler {
            Some(Sampler::Paper) => IcSource::Paper,
            Some(Sampler::Microcanonical) => IcSource::Microcanonical,
            None => IcSource::States,
        }
    }
}

impl From<Sampler> for IcSource {
    fn from(sampler: Sampler) -> Self {
        IcSource::from(Some(sampler))
    }
}

impl fmt::Display for MethodName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for IcSource {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_follow_the_method_and_the_sampler() {
        assert_eq!(MethodName::from(Method::default()).name(), "fd");
        assert_eq!(MethodName::from(Method::Tangent).to_string(), "tangent");
        assert_eq!(IcSource::from(Sampler::Paper).name(), "paper");
        assert_eq!(
            IcSource::from(Some(Sampler::Microcanonical)).to_string(),
            "microcanonical"
        );
        assert_eq!(IcSource::from(None).name(), "states");
    }
}
