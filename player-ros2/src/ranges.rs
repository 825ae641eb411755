//! Sonar and ranger arrays as ROS 2's `sensor_msgs/msg/PointCloud2`, one cloud per device in
//! the robot's `base_link`: each transducer's echo is the point its range away along its
//! axis, placed by the device's geometry, with fields `x`, `y`, `z` and `range` (float32).
//!
//! Why a cloud and not one `sensor_msgs/msg/Range` per transducer: Range changed its layout
//! in Iron (a `variance` field was added), so no one Range is read by both Humble and Jazzy;
//! a cloud is one topic per device instead of sixteen, needs no frame per transducer on
//! `/tf_static`, and is what rviz2 draws and Nav2's obstacle layer marks and clears with.
//! A ranger with one element and many readings (a laser served as a ranger) fans its
//! readings out over its configured angles.

use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::ranger::{RangerConfig, RangerGeometry};

use crate::msgs::{Header, POINT_FIELD_FLOAT32, PointCloud2, PointField};

/// What a ranger's readings need known to be placed.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RangerState {
    pub geometry: Option<RangerGeometry>,
    pub config: Option<RangerConfig>,
}

/// A place and heading in the plane, with a height: what a transducer's pose says of where
/// its echo lies (roll and pitch of Player's sonars and rangers are 0).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct Mount {
    x: f64,
    y: f64,
    z: f64,
    yaw: f64,
}

impl Mount {
    fn of(pose: &Pose3d) -> Mount {
        Mount {
            x: pose.px,
            y: pose.py,
            z: pose.pz,
            yaw: pose.pyaw,
        }
    }

    /// `inner`, given on this mount, as seen from what this mount is on.
    fn then(self, inner: Mount) -> Mount {
        let (s, c) = self.yaw.sin_cos();
        Mount {
            x: self.x + c * inner.x - s * inner.y,
            y: self.y + s * inner.x + c * inner.y,
            z: self.z + inner.z,
            yaw: self.yaw + inner.yaw,
        }
    }

    /// The echo `range` metres along this mount's axis: x, y, z and the range.
    fn echo(self, range: f64) -> [f32; 4] {
        let (s, c) = self.yaw.sin_cos();
        [
            (self.x + c * range) as f32,
            (self.y + s * range) as f32,
            self.z as f32,
            range as f32,
        ]
    }
}

/// A sonar's echoes, its transducers' poses on the robot given by its geometry; `None` while
/// the geometry is not known or does not match the readings.
pub fn sonar(header: Header, poses: &[Pose3d], ranges: &[f32]) -> Option<PointCloud2> {
    if poses.len() != ranges.len() || ranges.is_empty() {
        return None;
    }
    let echoes = poses
        .iter()
        .zip(ranges)
        .map(|(pose, &r)| Mount::of(pose).echo(f64::from(r)));
    Some(cloud(header, echoes))
}

/// A ranger's echoes: one per element at its pose when it has as many elements as readings
/// (a sonar ring), else its readings fanned over its configured angles from its one element;
/// `None` while what is needed is not known.
pub fn ranger(header: Header, state: &RangerState, ranges: &[f64]) -> Option<PointCloud2> {
    let geometry = state.geometry.as_ref()?;
    let device = Mount::of(&geometry.pose);
    let elements = &geometry.element_poses;
    if ranges.is_empty() {
        return None;
    }
    if elements.len() == ranges.len() {
        let echoes = elements
            .iter()
            .zip(ranges)
            .map(|(pose, &r)| device.then(Mount::of(pose)).echo(r));
        return Some(cloud(header, echoes));
    }
    let config = state.config.as_ref()?;
    let element = elements
        .first()
        .map_or(device, |e| device.then(Mount::of(e)));
    let step = match ranges.len() {
        1 => 0.0,
        n => (config.max_angle - config.min_angle) / (n - 1) as f64,
    };
    let echoes = ranges.iter().enumerate().map(|(i, &r)| {
        let beam = Mount {
            yaw: config.min_angle + step * i as f64,
            ..Mount::default()
        };
        element.then(beam).echo(r)
    });
    Some(cloud(header, echoes))
}

/// The cloud of `echoes`, one row.
fn cloud(header: Header, echoes: impl Iterator<Item = [f32; 4]>) -> PointCloud2 {
    let mut data = Vec::new();
    let mut count = 0u32;
    let mut dense = true;
    for echo in echoes {
        dense &= echo.iter().all(|v| v.is_finite());
        for value in echo {
            data.extend_from_slice(&value.to_le_bytes());
        }
        count += 1;
    }
    let field = |name: &str, offset| PointField {
        name: name.into(),
        offset,
        datatype: POINT_FIELD_FLOAT32,
        count: 1,
    };
    PointCloud2 {
        header,
        height: 1,
        width: count,
        fields: vec![
            field("x", 0),
            field("y", 4),
            field("z", 8),
            field("range", 12),
        ],
        is_bigendian: false,
        point_step: 16,
        row_step: 16 * count,
        data,
        is_dense: dense,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(x: f64, y: f64, yaw: f64) -> Pose3d {
        Pose3d {
            px: x,
            py: y,
            pyaw: yaw,
            ..Pose3d::default()
        }
    }

    fn points(cloud: &PointCloud2) -> Vec<[f32; 4]> {
        cloud
            .data
            .chunks_exact(16)
            .map(|p| {
                std::array::from_fn(|i| f32::from_le_bytes(p[i * 4..i * 4 + 4].try_into().unwrap()))
            })
            .collect()
    }

    #[test]
    fn a_sonar_echo_lies_its_range_along_its_transducer() {
        let poses = [
            pose(0.1, 0.0, 0.0),
            pose(0.0, 0.1, std::f64::consts::FRAC_PI_2),
        ];
        let cloud = sonar(Header::default(), &poses, &[1.0, 2.0]).unwrap();
        let p = points(&cloud);
        assert_eq!((cloud.width, cloud.row_step, cloud.data.len()), (2, 32, 32));
        assert_eq!(p[0], [1.1, 0.0, 0.0, 1.0]);
        assert!(
            (p[1][0]).abs() < 1e-6 && (p[1][1] - 2.1).abs() < 1e-6,
            "{p:?}"
        );
        assert!(
            sonar(Header::default(), &poses, &[1.0]).is_none(),
            "geometry of another sonar"
        );
        let lost = sonar(Header::default(), &poses, &[f32::NAN, 1.0]).unwrap();
        assert!(!lost.is_dense);
    }

    #[test]
    fn a_ranger_places_elements_on_its_own_pose_or_fans_its_one_element() {
        let ring = RangerState {
            geometry: Some(RangerGeometry {
                pose: pose(1.0, 0.0, std::f64::consts::PI),
                element_poses: vec![pose(0.5, 0.0, 0.0)],
                ..RangerGeometry::default()
            }),
            config: None,
        };
        let p = points(&ranger(Header::default(), &ring, &[1.0]).unwrap());
        // Facing backwards 1 m ahead of the base, its element 0.5 m further along: -0.5.
        assert!((p[0][0] + 0.5).abs() < 1e-6, "{p:?}");
        assert!(
            ranger(Header::default(), &ring, &[1.0, 1.0, 1.0]).is_none(),
            "no config"
        );
        let fan = RangerState {
            config: Some(RangerConfig {
                min_angle: -1.0,
                max_angle: 1.0,
                ..RangerConfig::default()
            }),
            geometry: Some(RangerGeometry::default()),
        };
        let p = points(&ranger(Header::default(), &fan, &[2.0, 2.0, 2.0]).unwrap());
        assert!((p[1][0] - 2.0).abs() < 1e-6 && (p[0][1] + 2.0 * 1f32.sin()).abs() < 1e-6);
        assert!(ranger(Header::default(), &RangerState::default(), &[1.0]).is_none());
    }
}
