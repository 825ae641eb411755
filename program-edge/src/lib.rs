//! What the workspace's programs (player-sim, pv3d, player-relay, the protocol tools, the
//! benchmarks) do alike at their edge: set up logging and end with an exit code. A crate of its
//! own so that no program imports another's for it, and the libraries stay free of
//! command-line crates (anyhow, tracing-subscriber).

pub mod exit;
pub mod logging;
