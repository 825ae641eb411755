//! The composer: turns the composition into plugin instances for the devices each Player
//! server reports — at start for the servers that answered, and later for each server that
//! answers only then. A robot that is still booting, or a simulation started after the
//! viewer, gets its plugins when it first answers instead of never; so does a plugin named
//! outright whose device is on such a server.

use std::collections::HashSet;

use player_proto::client::ConnectionState;

use super::{
    Composition, FoundDevice, PluginInstance, bind_named, instantiate, instantiate_handlers,
};
use crate::robots::RobotManager;

/// Which servers' devices have been turned into plugins, and the plugins still waiting for
/// their device.
pub struct Composer {
    composition: Composition,
    composed: HashSet<(String, u16)>,
    waiting: Vec<PluginInstance>,
}

impl Composer {
    pub fn new(composition: Composition) -> Composer {
        Composer {
            composition,
            composed: HashSet::new(),
            waiting: Vec::new(),
        }
    }

    pub fn composition(&self) -> &Composition {
        &self.composition
    }

    /// The plugins named outright whose device no server has reported yet, as written: a
    /// saved composition keeps them.
    pub fn waiting(&self) -> &[PluginInstance] {
        &self.waiting
    }

    /// The instances for every server connected now, and the plugins named outright that
    /// need no device or whose device is there.
    pub fn initial(&mut self, robots: &RobotManager) -> Vec<PluginInstance> {
        let arrived = self.newly_connected(robots);
        let (waiting, ready): (Vec<_>, Vec<_>) =
            instantiate(&self.composition, &devices_of(robots, &arrived))
                .into_iter()
                .partition(PluginInstance::waits_for_device);
        for instance in &waiting {
            tracing::info!(
                "{}: plugin {:?} waits for a device that fits its playerDeviceMask",
                instance.element.pos,
                instance.id()
            );
        }
        self.waiting = waiting;
        ready
    }

    /// The instances for the servers that connected since the last call: the handlers', and
    /// the waiting plugins' whose device is now there. None (and almost no work) when nothing
    /// changed.
    pub fn arrivals(&mut self, robots: &RobotManager) -> Vec<PluginInstance> {
        let arrived = self.newly_connected(robots);
        if arrived.is_empty() {
            return Vec::new();
        }
        let devices = devices_of(robots, &arrived);
        let mut made = instantiate_handlers(&self.composition, &devices);
        let mut still_waiting = Vec::new();
        for instance in self.waiting.drain(..) {
            let bound = bind_named(&instance.element, &devices);
            if bound.device.is_some() {
                made.push(bound);
            } else {
                still_waiting.push(instance);
            }
        }
        self.waiting = still_waiting;
        made
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
