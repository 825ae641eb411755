//! # pv3d-bench: does one client thread per robot scale to hundreds of robots?
//!
//! The ERF paper chose one thread per robot because a single thread polling every client
//! "does not extend computationally to more than 3 robots". This crate measures both designs
//! on the same traffic in the same run (issue 7):
//!
//! * a `player_proto::server` serving N robots on N ports, each publishing `position2d` state
//!   and a laser scan (361 beams at 10 Hz, or 1081 at 40 Hz) with the send time in the
//!   header timestamp ([`traffic`]);
//! * design (a), ours: one `player_proto::client::Client` thread per robot ([`threaded`]);
//! * design (b), the paper's: one thread polling every connection in turn with non-blocking
//!   sockets, framing and decoding with player-proto's own decoders ([`polling`]).
//!
//! Per N and design: messages stored per second, client-side CPU seconds per wall second
//! (from /proc/self/task, client threads only, [`cpu`]), p50/p99/max latency from send to
//! store, and messages lost (replaced in the server's queue, or never read).
//!
//! ```sh
//! cargo run --release -p bench --bin scale -- --out bench/results
//! cargo run --release -p bench --bin scale -- --lidar --out bench/results
//! ```
//!
//! Results and their reading: `bench/RESULTS.md`.

pub mod clock;
pub mod cpu;
pub mod crowd;
pub mod foxglove_clients;
pub mod observers;
pub mod pages;
pub mod plot;
pub mod polling;
pub mod process_stats;
pub mod recorder;
pub mod report;
pub mod run;
pub mod threaded;
pub mod traffic;

pub use run::{Design, Measurement, PointConfig, run_point};
pub use traffic::TrafficConfig;

/// Why a benchmark run failed.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error("bad benchmark settings: {0}")]
    Config(String),
    #[error("cannot start the mock server: {0}")]
    Server(String),
    #[error("cannot start a thread: {0}")]
    Thread(String),
    #[error("cannot connect a client: {0}")]
    Connect(String),
    #[error("protocol failure: {0}")]
    Protocol(String),
    #[error("cannot read CPU times: {0}")]
    Cpu(String),
    #[error("cannot draw the plot {path}: {why}")]
    Plot { path: String, why: String },
}
