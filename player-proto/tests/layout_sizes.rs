//! Every structure's encoded size, empty, equals the minimum size the protocol notes give for
//! it (computed there from Player's own packers). A wrongly widened or missing field shows up
//! here for every interface, not only those with a capture.

use player_proto::interfaces::*;
use player_proto::wire::Xdr;

fn check<T: Xdr + Default>(name: &str, documented: usize) {
    let value = T::default();
    let mut out = Vec::new();
    value.encode(&mut out);
    assert_eq!(out.len(), documented, "{name}: encoded");
    assert_eq!(value.encoded_len(), documented, "{name}: encoded_len");
    assert_eq!(T::MIN_WIRE_SIZE, documented, "{name}: MIN_WIRE_SIZE");
}

macro_rules! sizes {
    ($($ty:ty => $bytes:expr),* $(,)?) => {
        #[test]
        fn every_structure_has_its_documented_size() {
            $( check::<$ty>(stringify!($ty), $bytes); )*
        }
    };
}

sizes! {
    player::DevList => 8, player::DriverInfo => 24, player::DeviceReq => 28, player::DataModeReq => 4,
    player::AuthReq => 8, player::NameServiceReq => 12, player::AddReplaceRuleReq => 20,
    universal::CapabilitiesReq => 8, universal::IntProp => 12, universal::DoubleProp => 16,
    universal::StringProp => 16, universal::BoolProp => 12,
    common::Pose2d => 24, common::Pose3d => 48, common::BBox3d => 24, common::Color => 16,
    laser::LaserScan => 36, laser::LaserScanPose => 60, laser::LaserScanAngle => 32,
    laser::LaserGeometry => 72, laser::LaserConfig => 28, laser::LaserPower => 4, laser::LaserId => 4,
    laser::LaserFilter => 12,
    sonar::SonarData => 8, sonar::SonarGeometry => 8, sonar::SonarPower => 4,
    position2d::Position2dData => 52, position2d::Position2dCmdVel => 28, position2d::Position2dCmdPos => 52,
    position2d::Position2dCmdCar => 16, position2d::Position2dCmdVelHead => 16, position2d::Position2dGeometry => 72,
    position2d::Position2dPower => 4, position2d::Position2dVelocityMode => 4, position2d::Position2dPositionMode => 4,
    position2d::Position2dSetOdom => 24, position2d::Position2dPid => 12, position2d::Position2dSpeedProfile => 8,
    fiducial::FiducialItem => 100, fiducial::FiducialData => 8, fiducial::FiducialGeometry => 88,
    fiducial::FiducialFov => 12, fiducial::FiducialId => 4,
    camera::CameraData => 32, camera::CameraSource => 12,
    ranger::RangerConfig => 56, ranger::RangerGeometry => 88, ranger::RangerRanges => 8,
    ranger::RangerRangesStamped => 160, ranger::RangerIntensities => 8, ranger::RangerIntensitiesStamped => 160,
    ranger::RangerSwitch => 4,
    simulation::SimulationPose2d => 32, simulation::SimulationPose3d => 64, simulation::SimulationProperty => 28,
    blobfinder::Blob => 40, blobfinder::BlobfinderData => 16, blobfinder::BlobfinderColor => 28,
    blobfinder::BlobfinderImager => 16,
    graphics2d::Graphics2dPoints => 24, graphics2d::Graphics2dPolygon => 44,
    graphics3d::Graphics3dDraw => 28, graphics3d::Graphics3dTranslate => 24, graphics3d::Graphics3dRotate => 32,
    bumper::BumperData => 8, bumper::BumperDefine => 56, bumper::BumperGeometry => 8,
    power::PowerData => 24, power::PowerChargePolicy => 8,
    gripper::GripperData => 12, gripper::GripperGeometry => 104,
    map::MapInfo => 36, map::MapData => 28, map::MapVector => 24,
    speech::SpeechCmd => 8,
    localize::LocalizeHypothesis => 80, localize::LocalizeData => 20, localize::LocalizeSetPose => 72,
    localize::LocalizeParticle => 32, localize::LocalizeParticles => 40,
    planner::PlannerData => 88, planner::PlannerCmd => 24, planner::PlannerWaypoints => 16,
    planner::PlannerEnable => 4,
    ptz::PtzData => 24, ptz::PtzCmd => 20, ptz::PtzStatus => 4, ptz::PtzGeometry => 72,
    ptz::PtzGeneric => 8, ptz::PtzControlMode => 4,
    ir::IrData => 16, ir::IrPose => 8, ir::IrPower => 4,
    pointcloud3d::PointCloud3dElement => 40, pointcloud3d::PointCloud3dData => 8,
    speech_recognition::SpeechRecognitionData => 8,
}
