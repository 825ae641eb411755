//! The pv3d component model and the standard plugins.
//!
//! * [`scene`] — the tree of objects plugins fill and the viewer draws (no OpenGL here).
//! * [`plugin`] — the `Plugin` trait, its context, events, services and the registry.
//! * [`config`] — plugin parameters with defaults and errors that say where.
//! * [`device`] — what a plugin sees of its Player device.

pub mod action;
pub mod camera;
pub mod config;
pub mod device;
pub mod plugin;
pub mod scene;

pub use action::{Action, ObjectRef};
pub use config::{ConfigValueError, Param, PluginConfig};
pub use device::{DeviceAccess, LinkState, Sample};
pub use plugin::{Handled, InputEvent, Plugin, PluginContext, PluginRegistry};

pub mod fiducial;
pub mod ground;
pub mod laser;
pub mod parent_link;
pub mod position2d;
pub mod ranger;
pub mod skin;
pub mod sonar;
pub mod zones;

/// Every plugin built into pv3d, by library name.
pub fn standard_plugins() -> PluginRegistry {
    let mut registry = PluginRegistry::default();
    registry.register("libpv3d_ground", ground::Ground::create);
    registry.register("libpv3d_grid", ground::Grid::create);
    registry.register("libpv3d_lights", ground::Lights::create);
    registry.register("libpv3d_laser", laser::LaserPlugin::create);
    registry.register("libpv3d_position2d", position2d::Position2dPlugin::create);
    registry.register("libpv3d_fiducial", fiducial::FiducialPlugin::create);
    registry.register("libpv3d_sonar", sonar::SonarPlugin::create);
    registry.register("libpv3d_ranger", ranger::RangerPlugin::create);
    registry.register("libpv3d_camera", camera::CameraPlugin::create);
    registry.register("libpv3d_zones", zones::ZonesPlugin::create);
    registry
}
