//! What a plugin needs around it in a test: a scene, the anchors sensors hang from, and a
//! device fed by hand. Shared by the plugin tests (each uses part of it).
#![allow(dead_code)]

use std::time::Instant;

use glam::Vec3;
use pv3d_plugins::config::ConfigValueError;
use pv3d_plugins::device::RecordingDevice;
use pv3d_plugins::plugin::{AnchorKey, Anchors, Plugin, PluginContext};
use pv3d_plugins::scene::{NodeId, Object3D, Scene};
use pv3d_plugins::{PluginConfig, standard_plugins};

pub struct Harness {
    pub scene: Scene,
    pub anchors: Anchors,
    pub device: RecordingDevice,
    pub now: Instant,
}

impl Default for Harness {
    fn default() -> Self {
        Harness {
            scene: Scene::new(),
            anchors: Anchors::default(),
            device: RecordingDevice::default(),
            now: Instant::now(),
        }
    }
}

impl Harness {
    /// The context a plugin is made and updated in, with the hand-fed device.
    pub fn ctx(&mut self) -> PluginContext<'_> {
        PluginContext {
            scene: &mut self.scene,
            device: Some(&self.device),
            anchors: &mut self.anchors,
            now: self.now,
        }
    }

    /// The same context for a plugin that has no device (ground, lights).
    pub fn ctx_without_device(&mut self) -> PluginContext<'_> {
        PluginContext {
            device: None,
            ..self.ctx()
        }
    }

    /// Makes the plugin `config.library` names, with the hand-fed device.
    pub fn make(&mut self, config: PluginConfig) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let create = standard_plugins()
            .constructor(&config.library)
            .unwrap_or_else(|| panic!("no plugin {}", config.library));
        create(config, &mut self.ctx())
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
