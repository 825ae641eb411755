//! Player servers: the shared client per server and plugins' access to their devices.

mod device_link;
mod manager;
pub mod recording;

pub use device_link::ClientDevice;
pub use manager::RobotManager;
