//! Compositions: the XML files that say which Player servers to use and which plugins to make
//! of their devices.
//!
//! `pv3d a.xml b.xml` loads each file (expanding `xi:include`s relative to the including file),
//! merges them, and, once the servers have reported their devices, [`instantiate`]s the
//! handlers' plugin templates for every device that fits a mask (the [`Composer`] does this
//! for each server as it answers, and [`config_from_instance`] hands the result to a plugin).
//! [`emit_document`] writes the result back as a composition that runs as it is. Every error
//! names file:line:column.

mod composer;
mod device_ledger;
mod device_mask;
mod emit;
mod error;
mod include;
mod instantiate;
mod model;
mod parent_node;
mod parsers;
mod plugin_config;
mod reaction;
mod relocate;
mod xml_tree;

pub use composer::{Composer, DeviceChanges, listed_devices};
pub use device_mask::{DeviceMask, FoundDevice, MaskError};
pub use emit::{emit_document, to_xml_string};
pub use error::{ConfigError, SourcePos};
pub use instantiate::{
    PluginInstance, bind_named, bound_mask, instantiate, instantiate_handlers, is_extension_plugin,
};
pub use model::{ClientDecl, Composition, DEFAULT_PORT, ExtensionElement, MaskHandler};
pub use parsers::{ParserRegistry, extension_plugin};
pub use plugin_config::{config_from_instance, write_back};
pub use reaction::{
    REACTIONS_LIBRARY, Reaction, ReactionAction, Trigger, parse_reaction, parse_reactions,
    plain_element,
};
pub use xml_tree::{Attribute, Element, Node, parse_str};
