//! The components built into the program, by library name, each with the paper's metadata:
//! who wrote it, how to reach them, where to read more, and what it is for — so that a person
//! looking at a composition can tell what each part is and whom to ask about it.

use crate::config::{ConfigValueError, PluginConfig};
use crate::plugin::{Plugin, PluginContext};

/// Makes a plugin from its configuration.
pub type Constructor =
    fn(PluginConfig, &mut PluginContext<'_>) -> Result<Box<dyn Plugin>, ConfigValueError>;

/// What a component says about itself; the item tree shows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Metadata {
    pub author: &'static str,
    pub email: &'static str,
    pub web_page: &'static str,
    /// One or two sentences: what the component shows or lets a person do.
    pub description: &'static str,
}

/// A registered component: its library name, its metadata and how to make it.
#[derive(Debug, Clone, Copy)]
pub struct Component {
    pub library: &'static str,
    pub metadata: Metadata,
    pub constructor: Constructor,
}

/// The components built into the program, by library name (`libpv3d_laser`).
#[derive(Default)]
pub struct PluginRegistry {
    components: Vec<Component>,
}

impl PluginRegistry {
    /// Adds a component; its metadata travels with it to every plugin made from it.
    pub fn register(
        &mut self,
        library: &'static str,
        metadata: Metadata,
        constructor: Constructor,
    ) {
        self.components.push(Component {
            library,
            metadata,
            constructor,
        });
    }

    pub fn libraries(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.components.iter().map(|c| c.library)
    }

    pub fn find(&self, library: &str) -> Option<&Component> {
        self.components.iter().find(|c| c.library == library)
    }

    pub fn constructor(&self, library: &str) -> Option<Constructor> {
        self.find(library).map(|c| c.constructor)
    }
}
