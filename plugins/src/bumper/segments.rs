//! Where each bumper is on its robot, as a polyline: a straight bar across the bumper's
//! heading, or an arc when the device gives it a radius of curvature (a round robot's bumper
//! ring). Pure geometry, tested without a scene.

use glam::{Vec2, Vec3};
use player_proto::interfaces::bumper::BumperDefine;

/// Segments of a curved bumper's arc.
pub const ARC_SEGMENTS: usize = 6;

/// The bumper's outline in its robot's frame, from one end to the other.
pub fn bumper_polyline(bumper: &BumperDefine) -> Vec<Vec3> {
    let centre = Vec2::new(bumper.pose.px as f32, bumper.pose.py as f32);
    let z = bumper.pose.pz as f32;
    let yaw = bumper.pose.pyaw as f32;
    let length = bumper.length.max(0.0);
    if bumper.radius > 0.0 {
        // The arc's centre lies `radius` behind the bumper; its ends `length` apart along it.
        let pivot = centre - Vec2::from_angle(yaw) * bumper.radius;
        let half = length / bumper.radius / 2.0;
        (0..=ARC_SEGMENTS)
            .map(|k| {
                let a = yaw - half + 2.0 * half * k as f32 / ARC_SEGMENTS as f32;
                (pivot + Vec2::from_angle(a) * bumper.radius).extend(z)
            })
            .collect()
    } else {
        let across = Vec2::from_angle(yaw).perp() * (length / 2.0);
        vec![(centre - across).extend(z), (centre + across).extend(z)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::interfaces::common::Pose3d;

    fn bumper(x: f64, yaw: f64, length: f32, radius: f32) -> BumperDefine {
        BumperDefine {
            pose: Pose3d {
                px: x,
                pyaw: yaw,
                ..Pose3d::default()
            },
            length,
            radius,
        }
    }

    #[test]
    fn a_straight_bumper_lies_across_its_heading() {
        let line = bumper_polyline(&bumper(0.25, 0.0, 0.4, 0.0));
        assert_eq!(line.len(), 2);
        assert!((line[0] - Vec3::new(0.25, -0.2, 0.0)).length() < 1e-6);
        assert!((line[1] - Vec3::new(0.25, 0.2, 0.0)).length() < 1e-6);
    }

    #[test]
    fn a_curved_bumper_is_an_arc_through_its_pose() {
        let arc = bumper_polyline(&bumper(0.2, std::f64::consts::FRAC_PI_2, 0.3, 0.2));
        assert_eq!(arc.len(), ARC_SEGMENTS + 1);
        // Pivot at (0.2, −0.2): every point 0.2 m from it, the middle one at the pose.
        for p in &arc {
            assert!((p.truncate() - Vec2::new(0.2, -0.2)).length() - 0.2 < 1e-5);
        }
        assert!((arc[ARC_SEGMENTS / 2] - Vec3::new(0.2, 0.0, 0.0)).length() < 1e-5);
    }
}
