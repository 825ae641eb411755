//! Frames and poses: the frame tree `world` → robot → sensor (from each device's geometry),
//! Player's 2-D and 3-D poses as Foxglove poses, Player's seconds as Foxglove timestamps.

use foxglove::messages::{FrameTransform, Pose, Quaternion, Timestamp, Vector3};
use player_proto::interfaces::common::{Pose2d, Pose3d};

/// The fixed frame every robot moves in.
pub const WORLD: &str = "world";

/// A robot's body frame: its position2d pose in the world.
pub fn robot_frame(robot: &str) -> String {
    robot.to_string()
}

/// A device's frame, a child of its robot's, placed by the device's geometry.
pub fn device_frame(robot: &str, interf: &str, index: u16) -> String {
    format!("{robot}/{interf}/{index}")
}

/// Player's timestamp (seconds, f64) as a Foxglove timestamp; out of range clamps.
pub fn timestamp(seconds: f64) -> Timestamp {
    if seconds.is_nan() || seconds <= 0.0 {
        return Timestamp::MIN;
    }
    if seconds >= f64::from(u32::MAX) {
        return Timestamp::MAX;
    }
    let sec = seconds.floor();
    let nsec = ((seconds - sec) * 1e9).round().min(999_999_999.0);
    Timestamp::new(sec as u32, nsec as u32)
}

/// Roll, pitch, yaw (Player's order, applied yaw first) as a unit quaternion.
pub fn quaternion(roll: f64, pitch: f64, yaw: f64) -> Quaternion {
    let (sr, cr) = (roll / 2.0).sin_cos();
    let (sp, cp) = (pitch / 2.0).sin_cos();
    let (sy, cy) = (yaw / 2.0).sin_cos();
    Quaternion {
        x: sr * cp * cy - cr * sp * sy,
        y: cr * sp * cy + sr * cp * sy,
        z: cr * cp * sy - sr * sp * cy,
        w: cr * cp * cy + sr * sp * sy,
    }
}

pub fn pose2d(p: &Pose2d) -> Pose {
    Pose {
        position: Some(Vector3 {
            x: p.px,
            y: p.py,
            z: 0.0,
        }),
        orientation: Some(quaternion(0.0, 0.0, p.pa)),
    }
}

pub fn pose3d(p: &Pose3d) -> Pose {
    Pose {
        position: Some(Vector3 {
            x: p.px,
            y: p.py,
            z: p.pz,
        }),
        orientation: Some(quaternion(p.proll, p.ppitch, p.pyaw)),
    }
}

/// The transform placing `child` at `pose` in `parent`.
pub fn transform(time: Timestamp, parent: &str, child: &str, pose: Pose) -> FrameTransform {
    FrameTransform {
        timestamp: Some(time),
        parent_frame_id: parent.into(),
        child_frame_id: child.into(),
        translation: pose.position,
        rotation: pose.orientation,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_yaw_is_a_rotation_about_z() {
        let q = quaternion(0.0, 0.0, std::f64::consts::FRAC_PI_2);
        let half = std::f64::consts::FRAC_1_SQRT_2;
        assert!(
            (q.z - half).abs() < 1e-12 && (q.w - half).abs() < 1e-12,
            "{q:?}"
        );
        assert!(q.x.abs() < 1e-12 && q.y.abs() < 1e-12);
    }

    #[test]
    fn seconds_become_a_timestamp_and_clamp() {
        let t = timestamp(1_700_000_000.25);
        assert_eq!((t.sec(), t.nsec()), (1_700_000_000, 250_000_000));
        assert_eq!(timestamp(-3.0), Timestamp::MIN);
        assert_eq!(timestamp(f64::NAN), Timestamp::MIN);
        assert_eq!(timestamp(1e12), Timestamp::MAX);
    }
}
