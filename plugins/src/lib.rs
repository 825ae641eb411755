//! The standard pv3d components, one folder each: ground (with floorplans, grid, lights),
//! laser, sonar, ranger, position2d (tele-operation), fiducial, camera, zones, power, map and image. Each is built
//! on the `framework` crate alone and can be read without the rest of the application.

use framework::PluginRegistry;

pub mod camera;
pub mod fiducial;
pub mod ground;
pub mod image;
pub mod laser;
pub mod map;
pub mod position2d;
pub mod power;
pub mod ranger;
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
    registry.register("libpv3d_power", power::PowerPlugin::create);
    registry.register("libpv3d_map", map::MapPlugin::create);
    registry.register("libpv3d_image", image::ImagePlugin::create);
    registry
}
