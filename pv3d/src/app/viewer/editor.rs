//! The run-time component editor (the paper's "future improvement"): add a component from the
//! registry to the world or to a robot's device, remove one, change the visiting order,
//! disable and enable, and edit parameters — which re-creates the plugin from its new
//! configuration. Everything is kept in the plugins' instances, so "Save" (`--save-to`)
//! writes it back; a disabled plugin is saved with `enabled="false"` and loaded disabled.

use framework::device::DeviceAccess;
use framework::registry::Metadata;
use std::sync::Arc;

use super::{Slot, Viewer};
use crate::composition::{Element, Node, PluginInstance, SourcePos, write_back};

/// The attribute a disabled plugin is saved with.
pub(crate) const ENABLED_ATTR: &str = "enabled";

/// A plugin switched off: not made, so it neither runs nor draws; made again when enabled.
pub(crate) struct DisabledPlugin {
    pub instance: PluginInstance,
    pub metadata: Metadata,
    pub device: Option<Arc<dyn DeviceAccess>>,
    /// Where it stood in the visiting order.
    pub at: usize,
}

/// Why an edit could not be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum EditError {
    #[error("no component {0}")]
    NoSuchComponent(usize),
    #[error("no component library {0:?}; known: {1}")]
    UnknownLibrary(String, String),
    #[error("{0}")]
    NotMade(String),
}

impl Viewer {
    /// The registry's component libraries, for the "Add" menu.
    pub fn component_libraries(&self) -> Vec<&'static str> {
        let mut libraries: Vec<&'static str> = self.registry.libraries().collect();
        libraries.sort_unstable();
        libraries
    }

    /// Adds a component of `library`, to the world or to the device of plugin `attach_to`
    /// (a robot), at the end of the visiting order; returns its index.
    pub fn add_component(
        &mut self,
        library: &str,
        attach_to: Option<usize>,
    ) -> Result<usize, EditError> {
        if self.registry.find(library).is_none() {
            return Err(EditError::UnknownLibrary(
                library.to_string(),
                self.component_libraries().join(", "),
            ));
        }
        let mut element = Element::new("plugin", SourcePos::generated());
        element.set_attr("library", library);
        element.set_attr("id", library.trim_start_matches("libpv3d_"));
        let (mut device, mut found) = (None, None);
        if let Some(host) = attach_to {
            let slot = self
                .slots
                .get(host)
                .ok_or(EditError::NoSuchComponent(host))?;
            // The host's device masks, so that the saved composition finds the device again.
            for mask in slot.instance.element.elements() {
                if mask.name == "playerDeviceMask" {
                    element.children.push(Node::Element(mask.clone()));
                }
            }
            device = slot.device.clone();
            found = slot.instance.device.clone();
        }
        let instance = PluginInstance {
            element,
            device: found,
        };
        self.make_plugin(instance, device, self.slots.len())
    }

    /// Removes component `index`: cleaned, gone from the scene and from what is saved.
    pub fn remove_component(&mut self, index: usize) -> Result<(), EditError> {
        if index >= self.slots.len() {
            return Err(EditError::NoSuchComponent(index));
        }
        self.remove_plugin(index);
        Ok(())
    }

    /// Moves component `index` one place earlier (`up`) or later in the visiting order.
    pub fn move_component(&mut self, index: usize, up: bool) -> Result<(), EditError> {
        let other = if up {
            index.checked_sub(1)
        } else {
            Some(index + 1)
        };
        let Some(other) = other.filter(|&o| o < self.slots.len() && index < self.slots.len())
        else {
            return Err(EditError::NoSuchComponent(index));
        };
        self.slots.swap(index, other);
        self.active = self.active.map(|a| match a {
            a if a == index => other,
            a if a == other => index,
            a => a,
        });
        self.popup = None;
        Ok(())
    }

    /// Disables component `index`: its state is kept, the plugin itself is cleaned away.
    pub fn disable_component(&mut self, index: usize) -> Result<(), EditError> {
        if index >= self.slots.len() {
            return Err(EditError::NoSuchComponent(index));
        }
        let saved = self.slots[index].plugin.save();
        let mut slot = self.remove_plugin(index);
        write_back(&mut slot.instance.element, &saved);
        self.disabled.push(DisabledPlugin {
            instance: slot.instance,
            metadata: slot.metadata,
            device: slot.device,
            at: index,
        });
        Ok(())
    }

    /// Enables disabled component `index` (of [`Viewer::disabled_titles`]) where it stood.
    pub fn enable_component(&mut self, index: usize) -> Result<usize, EditError> {
        if index >= self.disabled.len() {
            return Err(EditError::NoSuchComponent(index));
        }
        let off = self.disabled.remove(index);
        let at = off.at.min(self.slots.len());
        self.make_plugin(off.instance, off.device, at)
    }

    /// The disabled components, by library and id.
    pub fn disabled_titles(&self) -> Vec<String> {
        self.disabled
            .iter()
            .map(|d| format!("{} {}", d.instance.library(), d.instance.id()))
            .collect()
    }

    /// The parameters of component `index` as it would save them now: (name, text).
    pub fn component_params(&self, index: usize) -> Vec<(String, String)> {
        self.slots.get(index).map_or_else(Vec::new, |slot| {
            let config = slot.plugin.save();
            config
                .params
                .iter()
                .map(|p| (p.name.clone(), p.text.clone()))
                .collect()
        })
    }

    /// Sets parameter `name` of component `index` and re-creates the plugin with it. When the
    /// new value is refused, the plugin is made again as it was and the error returned.
    pub fn set_component_param(
        &mut self,
        index: usize,
        name: &str,
        text: &str,
    ) -> Result<(), EditError> {
        if index >= self.slots.len() {
            return Err(EditError::NoSuchComponent(index));
        }
        let mut config = self.slots[index].plugin.save();
        let was_active = self.active == Some(index);
        let before = {
            let mut element = self.slots[index].instance.element.clone();
            write_back(&mut element, &config);
            element
        };
        config.set(name, text);
        let slot = self.remove_plugin(index);
        let mut instance = slot.instance;
        write_back(&mut instance.element, &config);
        let outcome = self.make_plugin(instance.clone(), slot.device.clone(), index);
        if let Err(e) = outcome {
            instance.element = before;
            self.make_plugin(instance, slot.device, index)?;
            return Err(e);
        }
        if was_active {
            self.set_active(Some(index));
        }
        Ok(())
    }

    /// Makes the plugin of `instance` with `device` and puts it at `at`.
    fn make_plugin(
        &mut self,
        mut instance: PluginInstance,
        device: Option<Arc<dyn DeviceAccess>>,
        at: usize,
    ) -> Result<usize, EditError> {
        instance
            .element
            .attributes
            .retain(|a| a.name != ENABLED_ATTR);
        let errors = self.errors.len();
        let slots = self.slots.len();
        self.add_plugins(vec![instance], &|_| device.clone());
        if self.slots.len() == slots {
            let why = self.errors.drain(errors..).collect::<Vec<_>>().join("; ");
            return Err(EditError::NotMade(why));
        }
        let slot: Slot = self.slots.pop().expect("just made");
        let at = at.min(self.slots.len());
        self.slots.insert(at, slot);
        self.active = self.active.map(|a| if a >= at { a + 1 } else { a });
        tracing::info!("component {} added at {at}", self.slots[at].plugin.title());
        Ok(at)
    }
}
