//! `<addParser element="..."/>`: extension elements are enabled by name from a registry built
//! into the program. A composition file never names code to load.

use super::error::ConfigError;
use super::xml_tree::Element;

/// The extension elements built into pv3d, and the plugin that all of a composition's
/// elements of that name become (one plugin for all `<zone>`s).
const BUILT_IN: &[(&str, &str)] = &[
    ("zone", "libpv3d_zones"),
    // Not a plugin: the viewer runs the reactions gathered under this name.
    ("reaction", super::reaction::REACTIONS_LIBRARY),
];

/// The plugin library an extension element becomes, if it becomes one.
pub fn extension_plugin(element: &str) -> Option<&'static str> {
    BUILT_IN
        .iter()
        .find(|(name, _)| *name == element)
        .map(|(_, library)| *library)
}

/// The extension element names this program knows how to parse.
#[derive(Debug, Clone, Default)]
pub struct ParserRegistry {
    known: Vec<&'static str>,
}

impl ParserRegistry {
    /// The extensions built into pv3d: `<zone>` (named ground zones and who is in them) and
    /// `<reaction>` (what happens on an awareness event).
    pub fn standard() -> ParserRegistry {
        ParserRegistry {
            known: BUILT_IN.iter().map(|(name, _)| *name).collect(),
        }
    }

    pub fn new(known: &[&'static str]) -> ParserRegistry {
        ParserRegistry {
            known: known.to_vec(),
        }
    }

    /// Checks an `<addParser>` element and returns the element name it enables.
    pub fn enable<'a>(&self, add_parser: &'a Element) -> Result<&'a str, ConfigError> {
        let attr = add_parser.attribute("element").ok_or_else(|| {
            ConfigError::at(
                add_parser.pos.clone(),
                "<addParser> needs an element attribute naming the extension element it enables",
            )
        })?;
        if let Some(extra) = add_parser.attributes.iter().find(|a| a.name != "element") {
            return Err(ConfigError::at(
                extra.pos.clone(),
                format!(
                    "unknown attribute {} on <addParser>; expected element",
                    extra.name
                ),
            ));
        }
        if !self.known.contains(&attr.value.as_str()) {
            return Err(ConfigError::at(
                attr.pos.clone(),
                format!(
                    "no parser for <{}> is built into pv3d; known extension elements: {}",
                    attr.value,
                    if self.known.is_empty() {
                        "none".to_string()
                    } else {
                        self.known.join(", ")
                    }
                ),
            ));
        }
        Ok(&attr.value)
    }

    /// A hint for an unknown element that a registered parser could handle.
    pub fn hint(&self, element: &str) -> String {
        if self.known.contains(&element) {
            format!(" (enable it with <addParser element=\"{element}\"/>)")
        } else {
            String::new()
        }
    }
}
