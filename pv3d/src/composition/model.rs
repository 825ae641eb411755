//! A loaded composition: the Player servers to connect to, the device-mask handlers with their
//! plugin templates, the plugins named outright, and extension elements.

use std::path::{Path, PathBuf};

use super::device_mask::DeviceMask;
use super::error::{ConfigError, SourcePos};
use super::include::load_with_includes;
use super::parent_node::check_parent_node;
use super::parsers::ParserRegistry;
use super::xml_tree::Element;

/// The default Player port.
pub const DEFAULT_PORT: u16 = 6665;

/// `<playerClient host port/>`: a Player server to connect to.
#[derive(Debug, Clone, PartialEq)]
pub struct ClientDecl {
    pub host: String,
    pub port: u16,
    pub pos: SourcePos,
}

/// `<playerDeviceMask ...>` inside `<handlers>`: every matching device gets a copy of each
/// plugin template.
#[derive(Debug, Clone, PartialEq)]
pub struct MaskHandler {
    pub mask: DeviceMask,
    pub templates: Vec<Element>,
    pub pos: SourcePos,
}

/// An element handled by an extension parser registered with `<addParser>`.
#[derive(Debug, Clone, PartialEq)]
pub struct ExtensionElement {
    pub parser: String,
    pub element: Element,
}

/// One or more composition files, merged.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Composition {
    pub clients: Vec<ClientDecl>,
    pub handlers: Vec<MaskHandler>,
    /// `<plugin>` elements named outright (not templates).
    pub plugins: Vec<Element>,
    pub extensions: Vec<ExtensionElement>,
    /// The files loaded, in order.
    pub sources: Vec<PathBuf>,
}

impl Composition {
    /// Loads and merges several files, in order.
    pub fn load_files(
        paths: &[PathBuf],
        parsers: &ParserRegistry,
    ) -> Result<Composition, ConfigError> {
        let mut composition = Composition::default();
        for path in paths {
            composition.merge(Composition::load(path, parsers)?);
        }
        Ok(composition)
    }

    /// Loads one file: a `<pv3d>` composition, or a lone `<plugin>` (as a template file given
    /// on the command line is).
    pub fn load(path: &Path, parsers: &ParserRegistry) -> Result<Composition, ConfigError> {
        let root = load_with_includes(path)?;
        let mut composition = Composition::from_root(&root, parsers)?;
        composition.sources.push(path.to_path_buf());
        Ok(composition)
    }

    /// Reads a root element (includes already expanded).
    pub fn from_root(root: &Element, parsers: &ParserRegistry) -> Result<Composition, ConfigError> {
        let mut composition = Composition::default();
        match root.local_name() {
            "pv3d" => composition.read_pv3d(root, parsers)?,
            "plugin" => composition.plugins.push(checked_plugin(root)?),
            other => {
                return Err(ConfigError::at(
                    root.pos.clone(),
                    format!("unknown root element <{other}>; expected <pv3d> or <plugin>"),
                ));
            }
        }
        Ok(composition)
    }

    /// Appends another composition's contents.
    pub fn merge(&mut self, other: Composition) {
        for client in other.clients {
            if !self
                .clients
                .iter()
                .any(|c| c.host == client.host && c.port == client.port)
            {
                self.clients.push(client);
            }
        }
        self.handlers.extend(other.handlers);
        self.plugins.extend(other.plugins);
        self.extensions.extend(other.extensions);
        self.sources.extend(other.sources);
    }

    fn read_pv3d(&mut self, root: &Element, parsers: &ParserRegistry) -> Result<(), ConfigError> {
        // addParser first: an extension element may come before its registration.
        let mut enabled: Vec<&str> = Vec::new();
        for child in root.elements().filter(|e| e.name == "addParser") {
            enabled.push(parsers.enable(child)?);
        }
        for child in root.elements() {
            match child.name.as_str() {
                "handlers" => self.read_handlers(child)?,
                "plugin" => self.plugins.push(checked_plugin(child)?),
                "addParser" => {}
                name if enabled.contains(&name) => self.extensions.push(ExtensionElement {
                    parser: name.to_string(),
                    element: child.clone(),
                }),
                other => {
                    return Err(ConfigError::at(
                        child.pos.clone(),
                        format!(
                            "unknown element <{other}> in <pv3d>; expected <handlers>, <plugin> or <addParser>{}",
                            parsers.hint(other)
                        ),
                    ));
                }
            }
        }
        Ok(())
    }

    fn read_handlers(&mut self, handlers: &Element) -> Result<(), ConfigError> {
        for child in handlers.elements() {
            match child.name.as_str() {
                "playerClient" => self.clients.push(read_client(child)?),
                "playerDeviceMask" => self.handlers.push(read_mask_handler(child)?),
                other => {
                    return Err(ConfigError::at(
                        child.pos.clone(),
                        format!(
                            "unknown element <{other}> in <handlers>; expected <playerClient> or <playerDeviceMask>"
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}

fn check_attributes(element: &Element, allowed: &[&str]) -> Result<(), ConfigError> {
    for attr in &element.attributes {
        if !allowed.contains(&attr.name.as_str()) && !attr.name.starts_with("xmlns") {
            return Err(ConfigError::at(
                attr.pos.clone(),
                format!(
                    "unknown attribute {} on <{}>; expected {}",
                    attr.name,
                    element.name,
                    if allowed.is_empty() {
                        "none".to_string()
                    } else {
                        allowed.join(", ")
                    }
                ),
            ));
        }
    }
    Ok(())
}

fn read_client(element: &Element) -> Result<ClientDecl, ConfigError> {
    check_attributes(element, &["host", "port"])?;
    let port = match element.attribute("port") {
        None => DEFAULT_PORT,
        Some(attr) => attr
            .value
            .trim()
            .parse()
            .ok()
            .filter(|p| *p > 0)
            .ok_or_else(|| {
                ConfigError::at(
                    attr.pos.clone(),
                    format!("port {:?} is not a number from 1 to 65535", attr.value),
                )
            })?,
    };
    Ok(ClientDecl {
        host: element.attr("host").unwrap_or("localhost").to_string(),
        port,
        pos: element.pos.clone(),
    })
}

/// Reads a mask from attributes, or from the string form in `mask="laser:sicklms200:*"`.
pub fn read_mask(element: &Element) -> Result<DeviceMask, ConfigError> {
    check_attributes(
        element,
        &["mask", "host", "port", "interface", "driver", "index"],
    )?;
    let result = match element.attribute("mask") {
        Some(attr) => DeviceMask::parse(&attr.value).map(|mut m| {
            m.host = element.attr("host").map(str::to_string);
            m
        }),
        None => DeviceMask::from_parts(
            element.attr("host"),
            element.attr("port"),
            element.attr("interface"),
            element.attr("driver"),
            element.attr("index"),
        ),
    };
    result.map_err(|e| ConfigError::at(element.pos.clone(), format!("bad device mask: {e}")))
}

fn read_mask_handler(element: &Element) -> Result<MaskHandler, ConfigError> {
    let mask = read_mask(element)?;
    let mut templates = Vec::new();
    for child in element.elements() {
        if child.name != "plugin" {
            return Err(ConfigError::at(
                child.pos.clone(),
                format!(
                    "unknown element <{}> in <playerDeviceMask>; expected <plugin> templates (or <xi:include> of them)",
                    child.name
                ),
            ));
        }
        templates.push(checked_plugin(child)?);
    }
    Ok(MaskHandler {
        mask,
        templates,
        pos: element.pos.clone(),
    })
}

fn checked_plugin(element: &Element) -> Result<Element, ConfigError> {
    check_attributes(element, &["library", "id", "enabled"])?;
    if element.attr("library").is_none_or(|l| l.trim().is_empty()) {
        return Err(ConfigError::at(
            element.pos.clone(),
            "<plugin> needs a library attribute naming the component (e.g. libpv3d_laser)",
        ));
    }
    if let Some(mask) = element.child("playerDeviceMask") {
        read_mask(mask)?;
    }
    check_parent_node(element)?;
    Ok(element.clone())
}
