//! Between composition elements and plugin configurations: a `<plugin>` element becomes a
//! [`PluginConfig`], and a plugin's saved state becomes an element again.

use framework::config::{DeviceRef, Param, PluginConfig};

use super::relocate::plugin_folder;
use super::{Element, Node, PluginInstance, SourcePos};

/// The configuration a plugin is made from.
pub fn config_from_instance(instance: &PluginInstance) -> PluginConfig {
    let element = &instance.element;
    let params = element
        .elements()
        .filter(|e| e.name != "playerDeviceMask")
        .map(|e| Param {
            name: e.name.clone(),
            text: e.text(),
            attributes: e
                .attributes
                .iter()
                .map(|a| (a.name.clone(), a.value.clone()))
                .collect(),
            origin: e.pos.to_string(),
        })
        .collect();
    PluginConfig {
        library: instance.library().to_string(),
        id: instance.id().to_string(),
        device: instance.device.as_ref().map(|d| DeviceRef {
            host: d.host.clone(),
            port: d.port,
            addr: d.addr,
            driver: d.driver.clone(),
        }),
        params,
        origin: element.pos.to_string(),
        base_dir: plugin_folder(element),
    }
}

/// Writes a plugin's saved state back into its element: parameters it reports replace the
/// element's text (new ones are appended); everything else in the element is kept.
pub fn write_back(element: &mut Element, saved: &PluginConfig) {
    for param in &saved.params {
        let existing = element.elements_mut().find(|e| e.name == param.name);
        match existing {
            Some(e) => {
                if !param.text.is_empty() || e.elements().next().is_none() {
                    e.children.retain(|n| !matches!(n, Node::Text(_)));
                    if !param.text.is_empty() {
                        e.children.push(Node::Text(param.text.clone()));
                    }
                }
                for (k, v) in &param.attributes {
                    e.set_attr(k, v.clone());
                }
            }
            None => {
                let mut e = Element::new(&param.name, SourcePos::generated());
                for (k, v) in &param.attributes {
                    e.set_attr(k, v.clone());
                }
                if !param.text.is_empty() {
                    e.children.push(Node::Text(param.text.clone()));
                }
                element.children.push(Node::Element(e));
            }
        }
    }
}
