//! `<parentNode>` of a plugin made for a device: which scene node the plugin hangs below, on
//! the device's own Player server.
//!
//! Several robots often share one Player port, each numbering its devices alike: r0 has
//! position2d:0 and laser:0, r2 position2d:1 and laser:1. A template cannot know the index of
//! the robot, so a `parentNode` with no `index`, or `index="*"`, means "the robot this device
//! belongs to": it takes the index of the device the plugin was made for. Binding writes that
//! index out, so an emitted composition says exactly what was drawn where.

use player_proto::Interface;

use super::device_mask::FoundDevice;
use super::error::ConfigError;
use super::xml_tree::Element;

/// The parameter element naming a plugin's parent.
const PARENT_NODE: &str = "parentNode";

/// The attributes a `parentNode` may have: the parent's host and port are always the
/// device's own.
const ATTRIBUTES: &[&str] = &["interface", "index"];

/// The index value that stands for "the index of this plugin's device".
const SAME_INDEX: &str = "*";

/// Checks a plugin's `parentNode` when the composition is loaded, so that a typo is reported
/// where it was written rather than silently hanging the sensor on robot 0.
pub fn check_parent_node(plugin: &Element) -> Result<(), ConfigError> {
    let Some(parent) = plugin.child(PARENT_NODE) else {
        return Ok(());
    };
    if let Some(extra) = parent
        .attributes
        .iter()
        .find(|a| !ATTRIBUTES.contains(&a.name.as_str()))
    {
        return Err(ConfigError::at(
            extra.pos.clone(),
            format!(
                "unknown attribute {} on <parentNode>; expected {} (the parent is on the \
                 device's own server)",
                extra.name,
                ATTRIBUTES.join(", ")
            ),
        ));
    }
    if let Some(attr) = parent.attribute("interface")
        && Interface::from_name(attr.value.trim()).is_none()
    {
        return Err(ConfigError::at(
            attr.pos.clone(),
            format!(
                "unknown interface {:?} in <parentNode> (expected a Player interface name such \
                 as position2d)",
                attr.value
            ),
        ));
    }
    if let Some(attr) = parent.attribute("index") {
        let value = attr.value.trim();
        if value != SAME_INDEX && value.parse::<u16>().is_err() {
            return Err(ConfigError::at(
                attr.pos.clone(),
                format!(
                    "index {:?} of <parentNode> is not a number from 0 to 65535, or * for the \
                     index of the plugin's own device",
                    attr.value
                ),
            ));
        }
    }
    Ok(())
}

/// Writes the index of `device` into a `parentNode` that has none (or `*`).
pub fn bind_parent_node(plugin: &mut Element, device: &FoundDevice) {
    let Some(parent) = plugin.elements_mut().find(|e| e.name == PARENT_NODE) else {
        return;
    };
    let unbound = parent
        .attr("index")
        .is_none_or(|index| index.trim() == SAME_INDEX);
    if unbound {
        parent.set_attr("index", device.addr.index.to_string());
    }
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;
    use std::sync::Arc;

    use super::*;
    use crate::composition::parse_str;

    fn plugin(xml: &str) -> Element {
        parse_str(xml, Arc::new(PathBuf::from("p.xml"))).unwrap()
    }

    fn laser(index: u16) -> FoundDevice {
        FoundDevice {
            host: "localhost".into(),
            port: 6665,
            addr: format!("laser:{index}").parse().unwrap(),
            driver: "stage".into(),
        }
    }

    fn parent_index(plugin: &Element) -> Option<&str> {
        plugin.child(PARENT_NODE).and_then(|p| p.attr("index"))
    }

    #[test]
    fn no_index_or_a_star_takes_the_devices_index() {
        for xml in [
            r#"<plugin library="l"><parentNode interface="position2d"/></plugin>"#,
            r#"<plugin library="l"><parentNode interface="position2d" index="*"/></plugin>"#,
        ] {
            let mut element = plugin(xml);
            check_parent_node(&element).unwrap();
            bind_parent_node(&mut element, &laser(2));
            assert_eq!(parent_index(&element), Some("2"), "{xml}");
        }
    }

    #[test]
    fn a_written_index_is_kept() {
        let mut element = plugin(
            r#"<plugin library="l"><parentNode interface="position2d" index="0"/></plugin>"#,
        );
        bind_parent_node(&mut element, &laser(3));
        assert_eq!(parent_index(&element), Some("0"));
    }

    #[test]
    fn bad_parents_say_where_and_why() {
        let cases = [
            (
                r#"<plugin library="l"><parentNode index="x"/></plugin>"#,
                "p.xml:1:33: index \"x\"",
            ),
            (
                r#"<plugin library="l"><parentNode interface="lazer"/></plugin>"#,
                "p.xml:1:33: unknown interface \"lazer\"",
            ),
            (
                r#"<plugin library="l"><parentNode port="6666"/></plugin>"#,
                "p.xml:1:33: unknown attribute port on <parentNode>",
            ),
        ];
        for (xml, expected) in cases {
            let text = check_parent_node(&plugin(xml)).unwrap_err().to_string();
            assert!(text.starts_with(expected), "{text}");
        }
    }
}
