//! LaTeX math in the world: formulas typeset to transparent pictures ([`typeset`]), and
//! `libpv3d_formula`, a formula label that follows its robot ([`label`]). Each formula is
//! typeset once per process ([`cache`]).
pub mod cache;
pub mod error;
pub mod label;
pub mod resolution;
pub mod typeset;
