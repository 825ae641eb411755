//! Player servers: the shared client per server and plugins' access to their devices.

mod device_links;
mod manager;
pub mod recording;

pub use device_links::{ClientDevice, LinkKey};
pub use manager::{RobotManager, RobotOptions};
