//! Devices that come and go: when a server's handshake brings a different device list, the
//! plugins of devices no longer listed are cleaned and set aside as their saved configuration
//! — the item tree and the status panel say "device gone" — and made again, state kept, when
//! their device comes back; new devices get their handlers' plugins.

use framework::config::DeviceRef;
use framework::registry::Metadata;

use super::Viewer;
use crate::composition::{FoundDevice, PluginInstance, write_back};

/// A plugin whose device went away: cleaned and dropped, kept as the configuration it saved
/// so that it resumes where it was.
pub(super) struct GonePlugin {
    pub instance: PluginInstance,
    pub title: String,
    pub metadata: Metadata,
}

impl GonePlugin {
    /// The device it waits for.
    pub fn device(&self) -> Option<&FoundDevice> {
        self.instance.device.as_ref()
    }
}

/// Whether `instance` was made for `device` (same server, interface and index).
fn made_for(instance: &PluginInstance, device: &FoundDevice) -> bool {
    instance.device.as_ref().is_some_and(|d| {
        d.host == device.host
            && d.port == device.port
            && d.addr.interf == device.addr.interf
            && d.addr.index == device.addr.index
    })
}

impl Viewer {
    /// Follows the servers' device lists (see [`crate::composition::Composer::changes`]).
    pub(super) fn follow_servers(&mut self) {
        let (Some(composer), Some(robots)) = (self.composer.as_mut(), self.robots.clone()) else {
            return;
        };
        let changes = composer.changes(&robots);
        if changes.is_empty() {
            return;
        }
        let lookup = |device: &DeviceRef| robots.device(device);
        for device in &changes.gone {
            self.device_gone(device);
        }
        for device in &changes.back {
            self.device_back(device, &lookup);
        }
        if !changes.new_plugins.is_empty() {
            tracing::info!(
                "{} plugins for new devices (of a server that answered late, or came back with more)",
                changes.new_plugins.len()
            );
            self.add_plugins(changes.new_plugins, &lookup);
        }
    }

    /// Cleans the plugins of `device` and keeps what they saved.
    fn device_gone(&mut self, device: &FoundDevice) {
        while let Some(i) = self
            .slots
            .iter()
            .position(|s| made_for(&s.instance, device))
        {
            let slot = &self.slots[i];
            let title = slot.plugin.title();
            let mut instance = slot.instance.clone();
            write_back(&mut instance.element, &slot.plugin.save());
            let removed = self.remove_plugin(i);
            tracing::warn!(
                "{title}: its device {}:{} is no longer listed by {}:{}; it resumes if the device comes back",
                device.addr.interf,
                device.addr.index,
                device.host,
                device.port
            );
            self.gone.push(GonePlugin {
                instance,
                title,
                metadata: removed.metadata,
            });
        }
    }

    /// Makes the plugins of `device` again, from what they saved when it went.
    fn device_back(&mut self, device: &FoundDevice, lookup: super::DeviceLookup<'_>) {
        let (back, still_gone): (Vec<GonePlugin>, Vec<GonePlugin>) = std::mem::take(&mut self.gone)
            .into_iter()
            .partition(|g| made_for(&g.instance, device));
        self.gone = still_gone;
        for plugin in &back {
            tracing::info!("{}: its device is back; resuming", plugin.title);
        }
        self.add_plugins(back.into_iter().map(|g| g.instance).collect(), lookup);
    }

    /// The titles of the plugins whose device is gone, as they were when it went.
    pub fn gone_titles(&self) -> Vec<String> {
        self.gone.iter().map(|g| g.title.clone()).collect()
    }

    /// The devices whose plugins wait for them to come back.
    pub(super) fn gone_devices(&self) -> Vec<FoundDevice> {
        self.gone
            .iter()
            .filter_map(|g| g.device().cloned())
            .collect()
    }
}
