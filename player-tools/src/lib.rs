//! What the workspace's programs share at their edge, apart from the protocol library: the
//! protocol crate stays free of command-line crates (clap, anyhow, tracing-subscriber).

pub mod exit;
pub mod logging;
