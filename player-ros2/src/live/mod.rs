//! The live front: each Player robot a ROS 2 node over DDS (RTPS), ROS 2's default middleware,
//! which any ROS 2 from Humble on discovers with no set-up. Its data goes out through the same
//! conversion as the files ([`crate::convert`]); `cmd_vel` (a `Twist`, or a `TwistStamped`
//! by choice: [`Commands`]) comes back as a velocity for the robot's base, refused when absurd
//! and stopped when its publisher goes quiet ([`commands`]); a simulation's time goes out on
//! `/clock` ([`clock`]).
//!
//! DDS discovers by multicast: run it where that is meant to happen (the tests run it inside a
//! network namespace of their own).

pub mod clock;
pub mod commands;
mod describe;
mod front;
mod inputs;
mod node;
mod publishers;
pub mod steer;

pub use clock::SimClock;
pub use describe::{Described, describe};
pub use front::Ros2Front;
pub use inputs::Commands;
pub use node::RobotNode;

use player_proto::RobotId;
use ros2_client::{Context, context::ContextOptions};

/// Why the ROS 2 side could not be set up.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LiveError {
    #[error("cannot join ROS 2 domain {domain}: {message}")]
    Domain { domain: u16, message: String },
    #[error("cannot make ROS 2 {what} for {robot}: {message}")]
    Create {
        robot: String,
        what: String,
        message: String,
    },
    #[error("ROS 2 domain {0} is out of range (0 to 232)")]
    DomainRange(u16),
    #[error("ROS_DOMAIN_ID must be a number from 0 to 232, got {0:?}")]
    DomainVariable(String),
}

/// The ROS 2 domain: the one given, else `ROS_DOMAIN_ID`, else 0 — as every ROS 2 program
/// picks it.
pub fn domain(given: Option<u16>) -> Result<u16, LiveError> {
    if let Some(domain) = given {
        return Ok(domain);
    }
    match std::env::var("ROS_DOMAIN_ID") {
        Ok(text) if !text.trim().is_empty() => text
            .trim()
            .parse()
            .map_err(|_| LiveError::DomainVariable(text)),
        _ => Ok(0),
    }
}

/// A process's way into one ROS 2 domain.
#[derive(Clone)]
pub struct Ros2 {
    context: Context,
}

impl Ros2 {
    /// Joins ROS 2 domain `domain` (`ROS_DOMAIN_ID`).
    pub fn join(domain: u16) -> Result<Ros2, LiveError> {
        if domain > 232 {
            return Err(LiveError::DomainRange(domain));
        }
        let context =
            Context::with_options(ContextOptions::new().domain_id(domain)).map_err(|e| {
                LiveError::Domain {
                    domain,
                    message: e.to_string(),
                }
            })?;
        Ok(Ros2 { context })
    }

    /// The node of `robot`: `/ns/player`, publishing its data, and (unless read-only)
    /// subscribed to its `cmd_vel`, `goal_pose` and `initialpose`.
    pub fn robot(&self, robot: &RobotId, commands: Commands) -> Result<RobotNode, LiveError> {
        RobotNode::new(&self.context, robot, commands)
    }

    /// Publishes `clock` on `/clock` until the returned thread is dropped.
    pub fn clock(&self, clock: SimClock) -> Result<clock::ClockThread, LiveError> {
        clock::ClockThread::start(&self.context, clock)
    }
}
