//! The component lifecycle as the viewer drives it: a plugin is made, initialized once before
//! its first run (the viewer only runs inside a frame, so a window and its GL context exist
//! by then, offscreen ones included), run every iteration, and cleaned before it is removed —
//! when its device goes away, or when the viewer itself goes.

use std::time::Instant;

use framework::plugin::PluginContext;

use super::{DeviceLookup, Slot, Viewer};
use crate::composition::{PluginInstance, config_from_instance};

impl Viewer {
    /// Makes and adds a plugin for each instance; an id already in use gets a suffix. A
    /// plugin that fails is reported in [`Viewer::errors`] and the others carry on.
    pub fn add_plugins(&mut self, mut instances: Vec<PluginInstance>, devices: DeviceLookup<'_>) {
        let first_error = self.errors.len();
        self.take_reactions(&mut instances);
        for mut instance in instances {
            self.make_id_unique(&mut instance);
            let config = config_from_instance(&instance);
            let Some(component) = self.registry.find(&config.library) else {
                let known: Vec<&str> = self.registry.libraries().collect();
                self.errors.push(format!(
                    "{}: unknown plugin library {:?}; built in: {}",
                    config.origin,
                    config.library,
                    known.join(", ")
                ));
                continue;
            };
            let (create, metadata) = (component.constructor, component.metadata);
            let device = config.device.as_ref().and_then(devices);
            if instance.element.attr(super::editor::ENABLED_ATTR) == Some("false") {
                self.disabled.push(super::editor::DisabledPlugin {
                    instance,
                    metadata,
                    device,
                    at: self.slots.len(),
                });
                continue;
            }
            let mut ctx = PluginContext::new(&mut self.scene, &mut self.anchors, Instant::now())
                .with_device(device.as_deref());
            match create(config, &mut ctx) {
                Ok(plugin) => self.slots.push(Slot {
                    plugin,
                    device,
                    instance,
                    metadata,
                    initialized: false,
                }),
                Err(e) => self.errors.push(e.to_string()),
            }
        }
        for e in &self.errors[first_error..] {
            tracing::error!("{e}");
        }
    }

    fn make_id_unique(&self, instance: &mut PluginInstance) {
        let taken = |id: &str| {
            self.slots.iter().any(|s| s.instance.id() == id)
                || self.gone.iter().any(|g| g.instance.id() == id)
                || self.disabled.iter().any(|d| d.instance.id() == id)
        };
        let id = instance.id().to_string();
        if id.is_empty() || !taken(&id) {
            return;
        }
        let unique = (2..)
            .map(|n| format!("{id}-{n}"))
            .find(|candidate| !taken(candidate))
            .expect("some suffix is free");
        instance.element.set_attr("id", unique);
    }

    /// One iteration of the viewer: follows the servers (plugins for devices that appeared,
    /// plugins of devices that went away cleaned, returning ones resumed), then runs every
    /// plugin, initializing first the ones that never ran. Call it from a frame, before
    /// [`Viewer::ui`]: that is what makes "initialized after the window and GL exist" hold.
    pub fn update(&mut self, now: Instant) {
        self.follow_servers();
        self.follow_script(now);
        self.follow_speech(now);
        let mut sent = Vec::new();
        for i in 0..self.slots.len() {
            let first_run = !std::mem::replace(&mut self.slots[i].initialized, true);
            let mut outbox = Vec::new();
            let (plugin, ctx) = self.plugin_in_context(i, now);
            let mut ctx = ctx.with_outbox(&mut outbox);
            if first_run {
                plugin.initialize(&mut ctx);
            }
            plugin.run(&mut ctx);
            sent.extend(outbox.into_iter().map(|query| (i, query)));
        }
        self.deliver(sent, now);
        self.react();
    }

    /// Cleans plugin `index` and takes it out. The active handler keeps pointing at the plugin
    /// it meant; an open popup, which names plugins by position, is closed.
    pub(super) fn remove_plugin(&mut self, index: usize) -> Slot {
        let (plugin, mut ctx) = self.plugin_in_context(index, Instant::now());
        plugin.clean(&mut ctx);
        self.popup = None;
        self.active = match self.active {
            Some(a) if a == index => None,
            Some(a) if a > index => Some(a - 1),
            other => other,
        };
        self.slots.remove(index)
    }

    /// Cleans and removes every plugin, the last made first, as the viewer goes away.
    pub(super) fn remove_all_plugins(&mut self) {
        while !self.slots.is_empty() {
            self.remove_plugin(self.slots.len() - 1);
        }
    }
}
