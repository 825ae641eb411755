//! `<parentNode interface="position2d" index="0"/>`: the device on the same Player server whose
//! scene node a sensor hangs below, so that the sensor moves with its robot. The parent's
//! plugin may be created later or publish its node later; the link attaches when it can.

use crate::config::PluginConfig;
use crate::plugin::{AnchorKey, PluginContext};
use crate::scene::NodeId;

#[derive(Debug, Clone, PartialEq)]
pub struct ParentLink {
    key: Option<AnchorKey>,
    attached: bool,
}

impl ParentLink {
    /// The link a plugin's `parentNode` parameter asks for (none without one, or without a
    /// device to say which server).
    pub fn from_config(config: &PluginConfig) -> ParentLink {
        let key = match (config.param("parentNode"), &config.device) {
            (Some(p), Some(device)) => Some(AnchorKey {
                host: device.host.clone(),
                port: device.port,
                interface: p.attr("interface").unwrap_or("position2d").to_string(),
                index: p.attr("index").and_then(|i| i.parse().ok()).unwrap_or(0),
            }),
            _ => None,
        };
        ParentLink {
            key,
            attached: false,
        }
    }

    /// Puts `node` below its parent once the parent's node is known.
    pub fn attach(&mut self, node: NodeId, ctx: &mut PluginContext<'_>) {
        if self.attached {
            return;
        }
        let Some(parent) = self.key.as_ref().and_then(|k| ctx.anchors.find(k)) else {
            return;
        };
        if let Some(object) = ctx.scene.get_mut(node) {
            object.parent = Some(parent);
        }
        self.attached = true;
    }
}
