//! Player poses as scene transforms, written once so that every component places things the
//! same way.
//!
//! Player's `player_pose3d_t` gives a position and roll, pitch and yaw about the parent's x, y
//! and z axes, applied in that order (roll first): the rotation is `Rz(yaw) · Ry(pitch) ·
//! Rx(roll)`, and the position is added after rotating. A `player_pose2d_t` is the same with
//! only a yaw, on the parent's ground plane.

use glam::{Affine3A, EulerRot, Quat, Vec3};
use player_proto::interfaces::common::{Pose2d, Pose3d};

/// The transform from the frame `pose` describes to its parent's.
pub fn transform_of(pose: &Pose3d) -> Affine3A {
    let rotation = Quat::from_euler(
        EulerRot::ZYX,
        pose.pyaw as f32,
        pose.ppitch as f32,
        pose.proll as f32,
    );
    let position = Vec3::new(pose.px as f32, pose.py as f32, pose.pz as f32);
    Affine3A::from_rotation_translation(rotation, position)
}

/// The transform of a planar pose: yaw `pa` about z, then `(px, py)` on the ground.
pub fn transform_of_2d(pose: &Pose2d) -> Affine3A {
    let position = Vec3::new(pose.px as f32, pose.py as f32, 0.0);
    Affine3A::from_rotation_translation(Quat::from_rotation_z(pose.pa as f32), position)
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use super::*;

    fn near(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    #[test]
    fn yaw_turns_ahead_to_the_left_and_position_comes_after() {
        let pose = Pose3d {
            px: 1.0,
            py: 2.0,
            pz: 0.5,
            pyaw: FRAC_PI_2,
            ..Default::default()
        };
        let ahead = transform_of(&pose).transform_point3(Vec3::X);
        assert!(near(ahead, Vec3::new(1.0, 3.0, 0.5)), "{ahead}");
    }

    #[test]
    fn roll_is_applied_before_pitch() {
        // Roll takes +y to +z, pitch then takes +z to +x. The other order would leave +y
        // on +z.
        let pose = Pose3d {
            proll: FRAC_PI_2,
            ppitch: FRAC_PI_2,
            ..Default::default()
        };
        let left = transform_of(&pose).transform_vector3(Vec3::Y);
        assert!(near(left, Vec3::X), "{left}");
    }

    #[test]
    fn pitch_is_applied_before_yaw() {
        // Pitch tips +x down to -z, which yaw leaves alone; yaw first would carry +x to +y,
        // which pitch leaves alone.
        let pose = Pose3d {
            ppitch: FRAC_PI_2,
            pyaw: FRAC_PI_2,
            ..Default::default()
        };
        let ahead = transform_of(&pose).transform_vector3(Vec3::X);
        assert!(near(ahead, Vec3::NEG_Z), "{ahead}");
    }

    #[test]
    fn a_planar_pose_is_a_yaw_and_a_ground_position() {
        let pose = Pose2d::new(-1.0, 0.5, FRAC_PI_2);
        let ahead = transform_of_2d(&pose).transform_point3(Vec3::X);
        assert!(near(ahead, Vec3::new(-1.0, 1.5, 0.0)), "{ahead}");
        let flat = Pose3d {
            px: -1.0,
            py: 0.5,
            pyaw: FRAC_PI_2,
            ..Default::default()
        };
        let same = transform_of(&flat).transform_point3(Vec3::new(0.3, -0.2, 0.1));
        let planar = transform_of_2d(&pose).transform_point3(Vec3::new(0.3, -0.2, 0.1));
        assert!(
            near(same, planar),
            "the 2-D form is the 3-D one without tilt"
        );
    }
}
