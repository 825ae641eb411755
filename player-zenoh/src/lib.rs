//! # player-zenoh: Player robots over Zenoh
//!
//! One `player-relay` serves a robot's data to many viewers on one network. Past one network
//! (several buildings, a public demo) copies of each stream must be made close to the
//! viewers; Zenoh's routers do that, once per link and not once per viewer, and discover,
//! route and reconnect by themselves. This crate puts Player robots into Zenoh and takes them
//! out again:
//!
//! * [`ZenohFront`] is a relay front (a client tap in `RelayConfig::fronts`): it publishes
//!   every message of every relayed robot, raw Player bytes (40-byte header + XDR body) so any
//!   Player decoder reads them, and answers for the robot's devices from what it saw;
//! * [`FromZenoh`] finds robots by their liveliness tokens and serves each as an ordinary
//!   Player server on a local port, subscribed in Zenoh to a device's data only while a
//!   local client is subscribed to it (so the robot's relay subscribes upstream to that alone).
//!
//! ## Key space
//!
//! `player/<site>/<host>_<port>/…`, the robot named after its Player server as the relay
//! reaches it:
//!
//! | key | kind | what |
//! |---|---|---|
//! | `…/alive` | liveliness token | while the relay is connected to the robot |
//! | `…/devices` | queryable | the DEVLIST reply, then each DRIVERINFO reply |
//! | `…/<interface>/<index>/data` | put, congestion *drop* | each DATA message |
//! | `…/<interface>/<index>/replies` | queryable | cached `GET_*` replies (attachment: the request body) |
//! | `…/<interface>/<index>/cmd` | put (commands), get (requests) | to the robot; attachment [`Stamp`] |
//!
//! ## Control
//!
//! One controller per robot: the front executes commands, and requests other than `GET_*`,
//! only when the attachment names its configured controller; others are logged and counted,
//! and their requests NACKed. Commands are never stored: plain puts, no Zenoh storage, and
//! any command more than [`MAX_COMMAND_AGE`] old on arrival is dropped, so nothing held up by
//! a broken link is replayed when it heals.

mod answers;
mod bridge_config;
pub mod cache;
pub mod commands;
mod error;
mod feeds;
mod from_zenoh;
mod front;
pub mod keys;
pub mod options;
mod publish;
pub mod queue;
mod remote;
mod shared;
pub mod stamp;

pub use bridge_config::FromZenohConfig;
pub use error::ZenohError;
pub use from_zenoh::FromZenoh;
pub use front::ZenohFront;
pub use keys::RobotKey;
pub use options::{Mode, UnknownMode, ZenohOptions};
pub use shared::{DEFAULT_QUEUE, FrontConfig};
pub use stamp::{MAX_COMMAND_AGE, Stamp};
/// The Zenoh crate this one is built on, for opening sessions.
pub use zenoh;
