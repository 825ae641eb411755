//! What a plugin needs around it in a test: a scene, the anchors sensors hang from, a device
//! fed by hand and the registry the plugin is made from. Nothing here needs a Player server, a
//! window or a GPU: a test feeds messages, calls `run`, and inspects the scene.
//!
//! ```
//! use framework::scene::{NodeId, Object3D};
//! use framework::testing::Harness;
//! use framework::{ConfigValueError, Metadata, Plugin, PluginConfig, PluginContext, PluginRegistry};
//!
//! struct Marker(NodeId, PluginConfig);
//! impl Plugin for Marker {
//!     fn save(&self) -> PluginConfig { self.1.clone() }
//!     fn title(&self) -> String { "marker".into() }
//!     fn clean(&mut self, ctx: &mut PluginContext<'_>) { ctx.scene.remove(self.0); }
//! }
//! fn create(config: PluginConfig, ctx: &mut PluginContext<'_>)
//!     -> Result<Box<dyn Plugin>, ConfigValueError> {
//!     let node = ctx.scene.add(Object3D::new("marker"));
//!     Ok(Box::new(Marker(node, config)))
//! }
//!
//! let mut registry = PluginRegistry::default();
//! let about = Metadata {
//!     author: "A. Student",
//!     email: "student@example.org",
//!     web_page: "https://example.org/marker",
//!     description: "A marker at the origin.",
//! };
//! registry.register("libmarker", about, create);
//! let mut h = Harness::with_registry(registry);
//! let config = PluginConfig { library: "libmarker".into(), ..PluginConfig::default() };
//! h.make(config).unwrap();
//! assert!(h.scene.iter().any(|(_, o)| o.name == "marker"));
//! ```

use std::time::Instant;

use crate::config::ConfigValueError;
use crate::config::PluginConfig;
use crate::device::RecordingDevice;
use crate::plugin::{AnchorKey, Anchors, Plugin, PluginContext};
use crate::registry::PluginRegistry;
use crate::scene::{NodeId, Object3D, Scene};
use glam::Vec3;

pub struct Harness {
    pub scene: Scene,
    pub anchors: Anchors,
    pub device: RecordingDevice,
    pub now: Instant,
    /// Where [`Harness::make`] finds a plugin's constructor by library name.
    pub registry: PluginRegistry,
}

impl Default for Harness {
    fn default() -> Self {
        Harness {
            scene: Scene::new(),
            anchors: Anchors::default(),
            device: RecordingDevice::default(),
            now: Instant::now(),
            registry: PluginRegistry::default(),
        }
    }
}

impl Harness {
    /// A harness whose [`Harness::make`] makes plugins from `registry`.
    pub fn with_registry(registry: PluginRegistry) -> Harness {
        Harness {
            registry,
            ..Harness::default()
        }
    }

    /// The context a plugin is made and run in, with the hand-fed device.
    pub fn ctx(&mut self) -> PluginContext<'_> {
        PluginContext::new(&mut self.scene, &mut self.anchors, self.now)
            .with_device(Some(&self.device))
    }

    /// The same context for a plugin that has no device (ground, lights).
    pub fn ctx_without_device(&mut self) -> PluginContext<'_> {
        PluginContext::new(&mut self.scene, &mut self.anchors, self.now)
    }

    /// Makes the plugin `config.library` names, with the hand-fed device.
    pub fn make(&mut self, config: PluginConfig) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let create = self
            .registry
            .constructor(&config.library)
            .unwrap_or_else(|| panic!("no plugin {}", config.library));
        create(config, &mut self.ctx())
    }

    /// Runs `plugin` once, as an iteration of the viewer does, and says whether that changed
    /// the scene (its generation moved): what a plugin's run is for, seen from outside.
    pub fn run_changes_scene(&mut self, plugin: &mut dyn Plugin) -> bool {
        let before = self.scene.generation();
        plugin.run(&mut self.ctx());
        self.scene.generation() != before
    }

    /// A robot body at `(x, 0)`, published as the anchor of `position2d:0` on
    /// localhost:6665, for sensors that hang below it.
    pub fn robot_at(&mut self, x: f32) -> NodeId {
        let mut robot = Object3D::new("robot");
        robot.transform = glam::Affine3A::from_translation(Vec3::new(x, 0.0, 0.0));
        let robot = self.scene.add(robot);
        self.anchors.publish(
            AnchorKey {
                host: "localhost".into(),
                port: 6665,
                interface: "position2d".into(),
                index: 0,
            },
            robot,
        );
        robot
    }
}
