//! How a simulation is served: bind address, speed, lockstep, recording and a step observer.
//! Its own module so that the server ([`crate::serve`]) and the step loop ([`crate::stepper`])
//! both read it without reading each other.

use std::net::IpAddr;
use std::sync::Arc;
use std::time::Duration;

use crate::sim::Simulation;
use crate::sim_record::SimRecording;

/// Lockstep serving ([`player_proto::server::Lockstep`]): a step is taken once every client
/// driving a robot has sent its command for it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LockstepOptions {
    /// How long a step waits for a driver's command (wall clock); `None`: for ever.
    pub patience: Option<Duration>,
}

/// How a simulation is served.
#[derive(Debug, Clone)]
pub struct ServeOptions {
    pub bind: IpAddr,
    /// Simulated seconds per real second; 0 runs as fast as the machine can.
    pub speedup: f64,
    /// Stop after this many steps (for tests and benchmarks).
    pub max_steps: Option<u64>,
    /// Serve on free ports chosen by the system instead of the configured ones.
    pub free_ports: bool,
    /// Step in lockstep with the clients that drive robots.
    pub lockstep: Option<LockstepOptions>,
    /// Record every device of every port each step, stamped with simulated time.
    pub record: Option<SimRecording>,
    /// Called after each step with the simulation (ground truth for a grader).
    pub observer: Option<StepObserver>,
}

impl Default for ServeOptions {
    fn default() -> Self {
        ServeOptions {
            bind: IpAddr::V4(std::net::Ipv4Addr::LOCALHOST),
            speedup: 1.0,
            max_steps: None,
            free_ports: false,
            lockstep: None,
            record: None,
            observer: None,
        }
    }
}

/// Called after each step with the simulation, under its lock: must be quick.
#[derive(Clone)]
pub struct StepObserver(pub Arc<dyn Fn(&Simulation) + Send + Sync>);

impl std::fmt::Debug for StepObserver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("StepObserver")
    }
}
