//! Range sensors as `foxglove.LaserScan`: a laser's scan as it is; a ranger's as one scan when it
//! has one element (its angles from its configuration), or one scan per element, each at its
//! element's pose, when it has several (Stage's sonars); a sonar's one scan per transducer.

use foxglove::messages::{LaserScan, Pose, Timestamp};
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::laser;
use player_proto::interfaces::ranger::{RangerConfig, RangerGeometry};

use crate::frames::pose3d;

/// A laser scan in its device's frame, read from where it lies in the received body.
pub fn laser(time: Timestamp, frame: &str, scan: &laser::LaserScanView<'_>) -> LaserScan {
    LaserScan {
        timestamp: Some(time),
        frame_id: frame.into(),
        pose: Some(identity()),
        start_angle: f64::from(scan.min_angle),
        end_angle: f64::from(scan.max_angle),
        ranges: scan.ranges.iter().map(f64::from).collect(),
        intensities: scan.intensity.iter().map(|&i| f64::from(i)).collect(),
    }
}

/// What a ranger needs known to be drawn.
#[derive(Debug, Clone, Default)]
pub struct RangerState {
    pub config: Option<RangerConfig>,
    pub geometry: Option<RangerGeometry>,
}

/// A ranger's readings: one scan, or one per element; nothing while neither its configuration
/// nor its element poses are known.
pub fn ranger(time: Timestamp, frame: &str, state: &RangerState, ranges: &[f64]) -> Vec<LaserScan> {
    let elements = state
        .geometry
        .as_ref()
        .map_or(&[][..], |g| &g.element_poses[..]);
    if elements.len() > 1 && elements.len() == ranges.len() {
        return per_element(time, frame, elements, ranges.iter().copied());
    }
    match &state.config {
        Some(config) => vec![LaserScan {
            timestamp: Some(time),
            frame_id: frame.into(),
            pose: Some(elements.first().map_or_else(identity, pose3d)),
            start_angle: config.min_angle,
            end_angle: config.max_angle,
            ranges: ranges.to_vec(),
            intensities: Vec::new(),
        }],
        None => Vec::new(),
    }
}

/// A sonar's readings, one scan per transducer (known from its geometry).
pub fn sonar(time: Timestamp, frame: &str, poses: &[Pose3d], ranges: &[f32]) -> Vec<LaserScan> {
    per_element(time, frame, poses, ranges.iter().map(|&r| f64::from(r)))
}

/// One single-beam scan per element, along the element's pose.
fn per_element(
    time: Timestamp,
    frame: &str,
    poses: &[Pose3d],
    ranges: impl Iterator<Item = f64>,
) -> Vec<LaserScan> {
    poses
        .iter()
        .zip(ranges)
        .map(|(pose, range)| LaserScan {
            timestamp: Some(time),
            frame_id: frame.into(),
            pose: Some(pose3d(pose)),
            start_angle: 0.0,
            end_angle: 0.0,
            ranges: vec![range],
            intensities: Vec::new(),
        })
        .collect()
}

fn identity() -> Pose {
    pose3d(&Pose3d::default())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config() -> RangerConfig {
        RangerConfig {
            min_angle: -1.5,
            max_angle: 1.5,
            ..RangerConfig::default()
        }
    }

    #[test]
    fn a_one_element_ranger_is_one_scan_over_its_configured_angles() {
        let state = RangerState {
            config: Some(config()),
            geometry: None,
        };
        let scans = ranger(Timestamp::MIN, "r", &state, &[1.0, 2.0, 3.0]);
        assert_eq!(scans.len(), 1);
        assert_eq!((scans[0].start_angle, scans[0].end_angle), (-1.5, 1.5));
        assert_eq!(scans[0].ranges, [1.0, 2.0, 3.0]);
    }

    #[test]
    fn a_many_element_ranger_is_a_scan_per_element_at_its_pose() {
        let poses = vec![
            Pose3d {
                px: 0.1,
                ..Pose3d::default()
            },
            Pose3d {
                py: 0.2,
                pyaw: 1.0,
                ..Pose3d::default()
            },
        ];
        let state = RangerState {
            config: Some(config()),
            geometry: Some(RangerGeometry {
                element_poses: poses,
                ..RangerGeometry::default()
            }),
        };
        let scans = ranger(Timestamp::MIN, "r", &state, &[4.0, 5.0]);
        assert_eq!(scans.len(), 2);
        assert_eq!(scans[1].ranges, [5.0]);
        let at = scans[1].pose.unwrap().position.unwrap();
        assert_eq!((at.x, at.y), (0.0, 0.2));
    }

    #[test]
    fn a_ranger_nothing_is_known_of_gives_nothing() {
        assert!(ranger(Timestamp::MIN, "r", &RangerState::default(), &[1.0]).is_empty());
    }
}
