//! The relay's face to its observers: a Player server per robot, serving the devices the robot
//! reported, through `player_proto::server` — so any Player client can connect — with the
//! relay's rules: newest data per device in every queue and a small kernel send buffer (a slow
//! observer gets fresh data, not a backlog, and never holds anyone else up), and commands only
//! from the commanders.

use std::net::IpAddr;
use std::sync::Arc;

use player_proto::client::Client;
use player_proto::server::{Commanders, ReplaceRule, Server, ServerConfig, ServerError};

use crate::relayed_device::RelayedDevice;
use crate::subscriptions::Subscriptions;

/// How the downstream servers are set up.
#[derive(Debug, Clone)]
pub struct DownstreamOptions {
    pub bind: IpAddr,
    pub commanders: Commanders,
    /// Kernel send buffer per observer, bytes.
    pub send_buffer: usize,
}

/// Starts serving one robot's devices on `port` (0: any free port).
pub(crate) fn serve_robot(
    upstream: &Arc<Client>,
    subscribed: &Arc<Subscriptions>,
    port: u16,
    options: &DownstreamOptions,
) -> Result<Server, ServerError> {
    let mut config = ServerConfig::default();
    config.bind = options.bind;
    config.commanders = options.commanders;
    config.queue_rules = vec![ReplaceRule::newest_data()];
    config.send_buffer = Some(options.send_buffer);
    config.thread_name = "relay-downstream".into();
    if let Some(banner) = upstream.banner() {
        config.version = banner.version;
    }
    let robot = config.robot(port);
    for device in upstream.devices() {
        config.device(
            robot,
            device.addr,
            RelayedDevice {
                upstream: upstream.clone(),
                addr: upstream.addr(device.addr.interf, device.addr.index),
                driver: device.driver,
                subscribed: subscribed.clone(),
            },
        );
    }
    Server::start(config)
}
