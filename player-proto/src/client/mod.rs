//! The Player client: one thread per robot connection (the design the ERF paper found to
//! scale where a single polling thread did not) — or, for hundreds of robots, one task each on
//! a few threads they share, which wait on all their sockets at once ([`SharedIo`]).
//!
//! The thread (or task) owns the socket and the session: it decodes, keeps the newest data of each
//! subscribed device with receive time, server timestamp and a sequence number, calls a
//! notifier when something new arrived, and reconnects with backoff — restoring the data mode,
//! the replace rules and the subscriptions — when the server goes away. The [`Client`] handle
//! sends it commands and reads what it publishes: blocking calls with timeouts, waits on state
//! changes, and non-blocking reads of the newest data, usable from a UI thread.
//!
//! ```no_run
//! use player_proto::client::{Client, ClientOptions};
//! let robot = Client::connect("localhost", 6665, ClientOptions::default()).unwrap();
//! for device in robot.devices() {
//!     println!("{} driven by {}", device.addr, device.driver);
//! }
//! let base = robot.position2d(0);
//! base.subscribe().unwrap();
//! base.set_velocity(0.3, 0.0, 0.1);
//! ```

mod commands;
pub mod describe;
mod handle;
mod handle_commands;
mod link;
mod liveness;
mod multi;
mod options;
mod proxies;
mod published;
mod requests;
mod responder;
mod robot_thread;
mod serve;
mod session_state;
mod shared_io;
mod store;
mod tap;
mod typed;

pub use crate::delivery::{DataMode, ReplaceAction, ReplaceRule};
pub use handle::Client;
pub use multi::MultiClient;
pub use options::{Backoff, ClientOptions, Notifier};
pub use proxies::{
    CameraProxy, FiducialProxy, LaserProxy, Position2dProxy, RangerProxy, SonarProxy,
};
pub use published::{ConnectionState, DeviceInfo};
pub use requests::{PendingReply, RequestError};
pub use responder::Responder;
pub use shared_io::SharedIo;
pub use store::{DeviceStats, Stamped};
pub use tap::{ConnectionTap, RobotTap, Tap, TapEvent, fan_out, unnamed};

/// Why a client could not connect.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConnectError {
    #[error("cannot reach the Player server at {host}:{port}: {why}")]
    Unreachable {
        host: String,
        port: u16,
        why: String,
    },
    #[error("cannot start the robot thread: {0}")]
    Thread(String),
}
