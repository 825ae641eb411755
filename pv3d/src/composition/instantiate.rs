//! Turning a composition into plugin instances for the devices the servers reported.
//!
//! Every device that fits a handler's mask gets a copy of the handler's templates, with the
//! template's `<playerDeviceMask>` replaced by the found device's address (the paper's Fig. 4
//! and 5). A plugin named outright with a `<playerDeviceMask>` is bound to the first device
//! that fits it, which is what makes an emitted composition (every plugin named outright, its
//! mask the full address of its device) run as the composition it came from.

use super::device_mask::FoundDevice;
use super::error::SourcePos;
use super::model::{Composition, read_mask};
use super::parent_node::bind_parent_node;
use super::parsers::extension_plugin;
use super::xml_tree::{Element, Node};

/// A plugin to create: its configuration element and the device it was made for, if any.
#[derive(Debug, Clone, PartialEq)]
pub struct PluginInstance {
    pub element: Element,
    pub device: Option<FoundDevice>,
}

impl PluginInstance {
    pub fn library(&self) -> &str {
        self.element.attr("library").unwrap_or_default()
    }

    pub fn id(&self) -> &str {
        self.element.attr("id").unwrap_or_default()
    }

    /// Whether this plugin names a device (it has a `<playerDeviceMask>`) that no server has
    /// reported yet: it is made once one that fits answers.
    pub fn waits_for_device(&self) -> bool {
        self.device.is_none() && self.element.child("playerDeviceMask").is_some()
    }
}

/// All plugin instances of a composition for the devices the servers reported: first the
/// handlers' (in handler, then device order), then the plugins named outright (bound to their
/// devices where they name one that was reported), then the extensions'. Ids are made unique
/// by numbering where a template is used more than once.
pub fn instantiate(composition: &Composition, devices: &[FoundDevice]) -> Vec<PluginInstance> {
    let mut instances = handler_instances(composition, devices);
    instances.extend(
        composition
            .plugins
            .iter()
            .map(|plugin| bind_named(plugin, devices)),
    );
    instances.extend(extension_plugins(composition));
    make_ids_unique(&mut instances);
    instances
}

/// The handlers' instances alone (as for a server that answers late), ids made unique.
pub fn instantiate_handlers(
    composition: &Composition,
    devices: &[FoundDevice],
) -> Vec<PluginInstance> {
    let mut instances = handler_instances(composition, devices);
    make_ids_unique(&mut instances);
    instances
}

fn handler_instances(composition: &Composition, devices: &[FoundDevice]) -> Vec<PluginInstance> {
    let mut instances = Vec::new();
    for handler in &composition.handlers {
        for device in devices.iter().filter(|d| handler.mask.matches(d)) {
            for template in &handler.templates {
                instances.push(PluginInstance {
                    element: bind_to_device(template, device),
                    device: Some(device.clone()),
                });
            }
        }
    }
    instances
}

/// A plugin named outright: bound to the first of `devices` that fits its
/// `<playerDeviceMask>` (unset parts of the mask, the server's included, fit any), or left
/// as it is written when it has no mask or nothing fits.
pub fn bind_named(plugin: &Element, devices: &[FoundDevice]) -> PluginInstance {
    let device = bound_mask(plugin).and_then(|mask| devices.iter().find(|d| mask.matches(d)));
    match device {
        Some(device) => PluginInstance {
            element: bind_to_device(plugin, device),
            device: Some(device.clone()),
        },
        None => PluginInstance {
            element: plugin.clone(),
            device: None,
        },
    }
}

/// One plugin per built-in extension in use, holding all of that extension's elements
/// (every `<zone>` goes to one `libpv3d_zones`).
fn extension_plugins(composition: &Composition) -> Vec<PluginInstance> {
    let mut plugins: Vec<PluginInstance> = Vec::new();
    for extension in &composition.extensions {
        let Some(library) = extension_plugin(&extension.parser) else {
            continue;
        };
        let existing = plugins.iter_mut().find(|p| p.library() == library);
        let plugin = match existing {
            Some(plugin) => plugin,
            None => {
                let mut element = Element::new("plugin", extension.element.pos.clone());
                element.set_attr("library", library);
                element.set_attr("id", library.trim_start_matches("libpv3d_"));
                plugins.push(PluginInstance {
                    element,
                    device: None,
                });
                plugins.last_mut().expect("just pushed")
            }
        };
        plugin
            .element
            .children
            .push(Node::Element(extension.element.clone()));
    }
    plugins
}

/// Whether an instance stands for extension elements (which are written back as they are).
pub fn is_extension_plugin(composition: &Composition, instance: &PluginInstance) -> bool {
    composition
        .extensions
        .iter()
        .any(|e| extension_plugin(&e.parser) == Some(instance.library()))
}

/// A copy of `template` whose `<playerDeviceMask>` is the concrete address of `device`, and
/// whose `<parentNode>` names the robot of that device.
fn bind_to_device(template: &Element, device: &FoundDevice) -> Element {
    let mut plugin = template.clone();
    bind_parent_node(&mut plugin, device);
    let address = device_address_element(
        device,
        template.child("playerDeviceMask").map(|m| m.pos.clone()),
    );
    let existing = plugin
        .children
        .iter()
        .position(|n| matches!(n, Node::Element(e) if e.name == "playerDeviceMask"));
    match existing {
        Some(i) => plugin.children[i] = Node::Element(address),
        None => plugin.children.insert(0, Node::Element(address)),
    }
    plugin
}

fn device_address_element(device: &FoundDevice, pos: Option<SourcePos>) -> Element {
    let mut element = Element::new("playerDeviceMask", pos.unwrap_or_else(SourcePos::generated));
    element.set_attr("host", device.host.clone());
    element.set_attr("port", device.port.to_string());
    element.set_attr("interface", device.addr.interf.to_string());
    element.set_attr("driver", device.driver.clone());
    element.set_attr("index", device.addr.index.to_string());
    element
}

fn make_ids_unique(instances: &mut [PluginInstance]) {
    let ids: Vec<String> = instances.iter().map(|i| i.id().to_string()).collect();
    let mut used: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for (instance, id) in instances.iter_mut().zip(&ids) {
        let base = if id.is_empty() {
            instance
                .library()
                .trim_start_matches("libpv3d_")
                .to_string()
        } else {
            id.clone()
        };
        let shared = ids.iter().filter(|other| *other == id).count() > 1;
        if id.is_empty() || shared {
            // robot1, robot2, ...: short, stable for a given device order, and readable.
            let n = used.entry(base.clone()).or_insert(0);
            *n += 1;
            instance.element.set_attr("id", format!("{base}{n}"));
        }
    }
}

/// The mask of a plugin element's `<playerDeviceMask>`, if it has one.
pub fn bound_mask(element: &Element) -> Option<super::device_mask::DeviceMask> {
    element
        .child("playerDeviceMask")
        .and_then(|m| read_mask(m).ok())
}
