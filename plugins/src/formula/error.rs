//! Why a formula gave no picture, on its own so that the typesetter and the cache of its
//! outcomes ([`super::cache`]) both use it without using each other.

use super::resolution::MAX_DPI;

/// Why a formula gave no picture.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FormulaError {
    #[error("{text:?} is not math: write it between dollar signs, as $v = \\omega r$")]
    NotMath { text: String },
    #[error("the formula {latex:?} cannot be typeset: {reason}")]
    Typeset { latex: String, reason: String },
    #[error("the math font could not be loaded: {0}")]
    Font(String),
    #[error("the typeset formula could not be read back: {0}")]
    Decode(String),
    #[error("a resolution of {0} dpi is not between 1 and {MAX_DPI}")]
    BadResolution(u32),
}
