//! The composer: turns the composition's handlers into plugin instances for the devices each
//! Player server reports — at start for the servers that answered, and later for each server
//! that answers only then. A robot that is still booting, or a simulation started after the
//! viewer, gets its plugins when it first answers instead of never.

use std::collections::HashSet;

use player_proto::client::ConnectionState;

use super::{Composition, FoundDevice, PluginInstance, instantiate};
use crate::robots::RobotManager;

/// Which servers' devices have been turned into plugins.
pub struct Composer {
    composition: Composition,
    composed: HashSet<(String, u16)>,
}

impl Composer {
    pub fn new(composition: Composition) -> Composer {
        Composer {
            composition,
            composed: HashSet::new(),
        }
    }

    pub fn composition(&self) -> &Composition {
        &self.composition
    }

    /// The instances for every server connected now, and the plugins named outright.
    pub fn initial(&mut self, robots: &RobotManager) -> Vec<PluginInstance> {
        let arrived = self.newly_connected(robots);
        instantiate(&self.composition, &devices_of(robots, &arrived))
    }

    /// The handlers' instances for the servers that connected since the last call; none (and
    /// almost no work) when nothing changed.
    pub fn arrivals(&mut self, robots: &RobotManager) -> Vec<PluginInstance> {
        let arrived = self.newly_connected(robots);
        if arrived.is_empty() {
            return Vec::new();
        }
        let devices = devices_of(robots, &arrived);
        instantiate(&self.composition, &devices)
            .into_iter()
            .filter(|instance| instance.device.is_some())
            .collect()
    }

    fn newly_connected(&mut self, robots: &RobotManager) -> HashSet<(String, u16)> {
        let mut arrived = HashSet::new();
        for (host, port, client) in robots.clients() {
            let key = (host.to_string(), port);
            if !self.composed.contains(&key) && client.state() == ConnectionState::Connected {
                arrived.insert(key.clone());
                self.composed.insert(key);
            }
        }
        arrived
    }
}

fn devices_of(robots: &RobotManager, servers: &HashSet<(String, u16)>) -> Vec<FoundDevice> {
    robots
        .devices()
        .into_iter()
        .filter(|d| servers.contains(&(d.host.clone(), d.port)))
        .collect()
}
