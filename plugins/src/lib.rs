//! The standard pv3d components, one folder each: ground (with floorplans, grid, lights),
//! laser, sonar, ranger, position2d (tele-operation), fiducial, camera, zones, power, map,
//! image, virtual camera and formula; for navigation and the rest of a real robot, localize,
//! planner, bumper, ir, gripper, blobfinder, ptz and pointcloud3d; and the people detector.
//! Each is built on the `framework` crate alone and can be read without the rest of the
//! application.

use framework::{Metadata, PluginRegistry};

pub mod blobfinder;
pub mod bumper;
pub mod camera;
pub mod fiducial;
pub mod formula;
pub mod gripper;
pub mod ground;
pub mod image;
pub mod ir;
pub mod laser;
pub mod localize;
pub mod map;
pub mod people;
pub mod planner;
pub mod pointcloud3d;
pub mod position2d;
pub mod power;
pub mod ptz;
pub mod ranger;
pub mod sonar;
pub mod virtual_camera;
pub mod zones;

/// Who wrote the standard components, and where to reach them: one place for all of them.
/// The project has no public address yet, so the contact fields use reserved `.invalid`
/// names (RFC 2606) until it has one.
const AUTHOR: &str = "The pv3d developers";
const EMAIL: &str = "pv3d@pv3d.invalid";
const WEB_PAGE: &str = "https://pv3d.invalid/components";

/// The metadata of a standard component: the project's author and addresses, and what this
/// component is for.
pub(crate) const fn standard_metadata(description: &'static str) -> Metadata {
    Metadata {
        author: AUTHOR,
        email: EMAIL,
        web_page: WEB_PAGE,
        description,
    }
}

/// Every plugin built into pv3d, by library name.
pub fn standard_plugins() -> PluginRegistry {
    let mut registry = PluginRegistry::default();
    registry.register(
        "libpv3d_ground",
        ground::Ground::METADATA,
        ground::Ground::create,
    );
    registry.register("libpv3d_grid", ground::Grid::METADATA, ground::Grid::create);
    registry.register(
        "libpv3d_lights",
        ground::Lights::METADATA,
        ground::Lights::create,
    );
    registry.register(
        "libpv3d_laser",
        laser::LaserPlugin::METADATA,
        laser::LaserPlugin::create,
    );
    registry.register(
        "libpv3d_people",
        people::PeoplePlugin::METADATA,
        people::PeoplePlugin::create,
    );
    registry.register(
        "libpv3d_position2d",
        position2d::Position2dPlugin::METADATA,
        position2d::Position2dPlugin::create,
    );
    registry.register(
        "libpv3d_fiducial",
        fiducial::FiducialPlugin::METADATA,
        fiducial::FiducialPlugin::create,
    );
    registry.register(
        "libpv3d_sonar",
        sonar::SonarPlugin::METADATA,
        sonar::SonarPlugin::create,
    );
    registry.register(
        "libpv3d_ranger",
        ranger::RangerPlugin::METADATA,
        ranger::RangerPlugin::create,
    );
    registry.register(
        "libpv3d_camera",
        camera::CameraPlugin::METADATA,
        camera::CameraPlugin::create,
    );
    registry.register(
        "libpv3d_zones",
        zones::ZonesPlugin::METADATA,
        zones::ZonesPlugin::create,
    );
    registry.register(
        "libpv3d_power",
        power::PowerPlugin::METADATA,
        power::PowerPlugin::create,
    );
    registry.register(
        "libpv3d_map",
        map::MapPlugin::METADATA,
        map::MapPlugin::create,
    );
    registry.register(
        "libpv3d_image",
        image::ImagePlugin::METADATA,
        image::ImagePlugin::create,
    );
    registry.register(
        "libpv3d_localize",
        localize::LocalizePlugin::METADATA,
        localize::LocalizePlugin::create,
    );
    registry.register(
        "libpv3d_planner",
        planner::PlannerPlugin::METADATA,
        planner::PlannerPlugin::create,
    );
    registry.register(
        "libpv3d_bumper",
        bumper::BumperPlugin::METADATA,
        bumper::BumperPlugin::create,
    );
    registry.register("libpv3d_ir", ir::IrPlugin::METADATA, ir::IrPlugin::create);
    registry.register(
        "libpv3d_gripper",
        gripper::GripperPlugin::METADATA,
        gripper::GripperPlugin::create,
    );
    registry.register(
        "libpv3d_pointcloud3d",
        pointcloud3d::PointCloudPlugin::METADATA,
        pointcloud3d::PointCloudPlugin::create,
    );
    registry.register(
        "libpv3d_blobfinder",
        blobfinder::BlobfinderPlugin::METADATA,
        blobfinder::BlobfinderPlugin::create,
    );
    registry.register(
        "libpv3d_ptz",
        ptz::PtzPlugin::METADATA,
        ptz::PtzPlugin::create,
    );
    registry.register(
        "libpv3d_formula",
        formula::label::FormulaPlugin::METADATA,
        formula::label::FormulaPlugin::create,
    );
    registry.register(
        "libpv3d_virtual_camera",
        virtual_camera::VirtualCameraPlugin::METADATA,
        virtual_camera::VirtualCameraPlugin::create,
    );
    registry
}
