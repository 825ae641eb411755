//! Each step's data as the simulated devices send it: odometry, scans with their
//! intensities, sonar, camera frames, fiducials, and what the navigation and speech devices
//! publish — one message per device, a ranger's ranges then intensities (as Stage sends them).

use player_proto::interfaces::blobfinder::Blobfinder;
use player_proto::interfaces::camera::Camera;
use player_proto::interfaces::common::{Pose2d, Pose3d};
use player_proto::interfaces::fiducial::{Fiducial, FiducialData, FiducialItem};
use player_proto::interfaces::gripper::Gripper;
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::interfaces::power::Power;
use player_proto::interfaces::ranger::{Ranger, RangerIntensities, RangerRanges};
use player_proto::interfaces::sonar::{Sonar, SonarData};
use player_proto::message::Body;

use super::{
    SimDevice, blobfinder, data_of, gripper, localize, planner, power, ranger_config, speech,
};
use crate::camera_frames::camera_data;
use crate::served::Source;
use crate::sim::{RangerReturns, Simulation, fiducials, ranger_returns, ranger_scan};

impl SimDevice {
    /// This step's data messages (subtype, body), in the order they are sent: none for the
    /// simulation, ranges then intensities for a ranger (as Stage sends them), one message
    /// for every other device.
    pub fn data(sim: &Simulation, source: &Source, scan_id: u32) -> Vec<(u8, Body)> {
        vec![match *source {
            Source::Simulation | Source::Map(_) | Source::Speech(_) => return Vec::new(),
            Source::SpeechRecognition(ref input) => return speech::heard(sim, input),
            Source::Localize(ref driver) => return localize::hypotheses(sim, driver),
            Source::Estimate(ref driver) => return localize::estimate(sim, driver),
            Source::Planner(ref driver) => return planner::data(sim, driver),
            Source::Blobfinder { robot, finder } => {
                data_of(Blobfinder::DATA_BLOBS, blobfinder::data(sim, robot, finder))
            }
            Source::Gripper { robot, gripper } => {
                data_of(Gripper::DATA_STATE, gripper::data(sim, robot, gripper))
            }
            Source::Power { robot } => data_of(Power::DATA_STATE, power::data(sim, robot)),
            Source::Position { robot } => {
                let r = &sim.robots[robot];
                let (vx, vy, va) = r.velocity;
                // The true pose, or the odometry's (the world's `localization`).
                let pose = sim.reported_pose(robot);
                let state = Position2dData {
                    pos: Pose2d::new(pose.x, pose.y, pose.a),
                    vel: Pose2d::new(vx, vy, va),
                    stall: u8::from(r.stall),
                };
                data_of(Position2d::DATA_STATE, state)
            }
            Source::Ranger { robot, ranger } => {
                let spec = &sim.world.robots[robot].rangers[ranger];
                let RangerReturns {
                    ranges,
                    intensities,
                } = ranger_returns(sim, robot, spec);
                return vec![
                    data_of(Ranger::DATA_RANGE, RangerRanges { ranges }),
                    data_of(Ranger::DATA_INTNS, RangerIntensities { intensities }),
                ];
            }
            Source::Laser { robot, ranger } => {
                let spec = &sim.world.robots[robot].rangers[ranger];
                let c = ranger_config(spec);
                let returns = ranger_returns(sim, robot, spec);
                let ranges = returns.ranges.iter().map(|&r| r as f32).collect();
                // One byte per reading, as Player's rangertolaser converts Stage's values.
                let intensity: Vec<u8> = returns
                    .intensities
                    .iter()
                    .map(|&v| v.clamp(0.0, 255.0) as u8)
                    .collect();
                let scan = LaserScan {
                    min_angle: c.min_angle as f32,
                    max_angle: c.max_angle as f32,
                    resolution: c.angular_res as f32,
                    max_range: c.max_range as f32,
                    ranges,
                    intensity: intensity.into(),
                    id: scan_id,
                };
                data_of(Laser::DATA_SCAN, scan)
            }
            Source::Sonar { robot, ranger } => {
                let ranges = ranger_scan(sim, robot, &sim.world.robots[robot].rangers[ranger])
                    .into_iter()
                    .map(|r| r as f32)
                    .collect();
                data_of(Sonar::DATA_RANGES, SonarData { ranges })
            }
            Source::Camera {
                robot,
                camera,
                jpeg_quality,
            } => data_of(
                Camera::DATA_STATE,
                camera_data(sim, robot, camera, jpeg_quality),
            ),
            Source::Fiducial { robot, finder } => {
                let hits = fiducials(sim, robot, &sim.world.robots[robot].fiducials[finder]);
                let items = hits
                    .into_iter()
                    .map(|h| FiducialItem {
                        id: h.id,
                        pose: Pose3d {
                            px: h.x,
                            py: h.y,
                            pyaw: h.yaw,
                            ..Pose3d::default()
                        },
                        upose: Pose3d::default(),
                    })
                    .collect();
                data_of(Fiducial::DATA_SCAN, FiducialData { fiducials: items })
            }
        }]
    }
}
