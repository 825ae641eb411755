//! What a bridge out of Zenoh ([`crate::FromZenoh`]) is told: which site's robots, where to
//! serve them and who may command through them. Its own module, below both the bridge and
//! each robot it serves (`remote`), which read it.

use std::net::{IpAddr, Ipv4Addr};

use player_proto::server::Commanders;

/// Which robots to serve, where, and who may command through them.
#[derive(Debug, Clone)]
pub struct FromZenohConfig {
    /// The site whose robots are served; `*` for every site.
    pub site: String,
    /// Sent with every command and request: the robot's side executes those of its
    /// controller only (`--zenoh-controller` there).
    pub identity: String,
    pub bind: IpAddr,
    /// The n-th robot found is served on `base_port + n`; 0: any free port.
    pub base_port: u16,
    /// Which local clients may command (and so send commands on with `identity`).
    pub commanders: Commanders,
    pub send_buffer: Option<usize>,
}

impl FromZenohConfig {
    pub fn new(site: &str, identity: &str) -> FromZenohConfig {
        FromZenohConfig {
            site: site.into(),
            identity: identity.into(),
            bind: IpAddr::V4(Ipv4Addr::LOCALHOST),
            base_port: 0,
            commanders: Commanders::Everyone,
            send_buffer: None,
        }
    }
}
