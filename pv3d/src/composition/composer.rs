//! The composer: turns the composition into plugin instances for the devices each Player
//! server reports — at start for the servers that answered, and later whenever a server's
//! handshake brings a list that differs: a server that answers only then (a robot still
//! booting, a simulation started after the viewer), or one restarted with fewer devices or
//! more. New devices get their handlers' plugins, and the plugins named outright that wait for
//! them; devices that went away, and those that came back, are reported so that the viewer
//! cleans their plugins and resumes them.

use player_proto::client::ConnectionState;

use super::device_ledger::DeviceLedger;
use super::{
    Composition, FoundDevice, PluginInstance, bind_named, instantiate, instantiate_handlers,
};
use crate::robots::RobotManager;

/// Which devices every server has listed, and the plugins still waiting for their device.
pub struct Composer {
    composition: Composition,
    ledger: DeviceLedger,
    waiting: Vec<PluginInstance>,
}

/// How the servers' devices changed since the last look.
#[derive(Debug, Default)]
pub struct DeviceChanges {
    /// Plugins for devices listed for the first time.
    pub new_plugins: Vec<PluginInstance>,
    /// Devices a server listed before and no longer does: their plugins are gone.
    pub gone: Vec<FoundDevice>,
    /// Devices listed again after they went away: their plugins resume.
    pub back: Vec<FoundDevice>,
}

impl DeviceChanges {
    pub fn is_empty(&self) -> bool {
        self.new_plugins.is_empty() && self.gone.is_empty() && self.back.is_empty()
    }
}

impl Composer {
    pub fn new(composition: Composition) -> Composer {
        Composer {
            composition,
            ledger: DeviceLedger::default(),
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
        let mut devices = Vec::new();
        for (server, listed) in connected_lists(robots) {
            devices.extend(self.ledger.observe(server, listed).new);
        }
        let (waiting, ready): (Vec<_>, Vec<_>) = instantiate(&self.composition, &devices)
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

    /// How the connected servers' device lists changed since the last call: plugins for the
    /// new devices (the handlers', and the waiting plugins' whose device is now there), and
    /// the devices gone and back. Empty (and almost no work) when nothing changed.
    pub fn changes(&mut self, robots: &RobotManager) -> DeviceChanges {
        let mut new_devices = Vec::new();
        let mut changes = DeviceChanges::default();
        for (server, listed) in connected_lists(robots) {
            let change = self.ledger.observe(server, listed);
            new_devices.extend(change.new);
            changes.gone.extend(change.gone);
            changes.back.extend(change.back);
        }
        if new_devices.is_empty() {
            return changes;
        }
        changes.new_plugins = instantiate_handlers(&self.composition, &new_devices);
        let mut still_waiting = Vec::new();
        for instance in self.waiting.drain(..) {
            let bound = bind_named(&instance.element, &new_devices);
            if bound.device.is_some() {
                changes.new_plugins.push(bound);
            } else {
                still_waiting.push(instance);
            }
        }
        self.waiting = still_waiting;
        changes
    }
}

/// Every device the connected servers list now (what a component loaded at run time may
/// be bound to).
pub fn listed_devices(robots: &RobotManager) -> Vec<FoundDevice> {
    connected_lists(robots)
        .into_iter()
        .flat_map(|(_, listed)| listed)
        .collect()
}

/// Each connected server's devices, as of its last handshake.
fn connected_lists(robots: &RobotManager) -> Vec<((String, u16), Vec<FoundDevice>)> {
    robots
        .clients()
        .filter(|(_, _, client)| client.state() == ConnectionState::Connected)
        .map(|(host, port, client)| {
            let listed = client
                .devices()
                .into_iter()
                .map(|d| FoundDevice {
                    host: host.to_string(),
                    port,
                    addr: d.addr,
                    driver: d.driver,
                })
                .collect();
            ((host.to_string(), port), listed)
        })
        .collect()
}
