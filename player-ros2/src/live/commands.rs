//! Commands from ROS 2 before they reach a robot: a `cmd_vel` with a NaN, an infinity or an
//! absurd speed is refused (and said once per kind); a robot whose `cmd_vel` publisher goes
//! quiet is stopped after a deadline, so no robot keeps driving after teleop dies.

use std::time::{Duration, Instant};

use crate::msgs::{PoseStamped, PoseWithCovarianceStamped, Quaternion, Twist};

/// Farther than this from the map's origin is not a place but a mistake, m.
pub const MOST_DISTANCE: f64 = 1.0e5;

/// Faster than this is not a command but a mistake, m/s.
pub const MOST_SPEED: f64 = 5.0;
/// Faster turning than this likewise, rad/s.
pub const MOST_TURN: f64 = 10.0;
/// Without a fresh `cmd_vel` for this long, a moving robot is stopped (teleop_twist_keyboard
/// repeats its command at 10 Hz; joysticks at 20).
pub const DEADLINE: Duration = Duration::from_millis(500);

/// Why a `cmd_vel` was not forwarded.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Refused {
    #[error("a cmd_vel with a value that is not a number or infinite: {0:?}")]
    NotFinite((f64, f64, f64)),
    #[error("a cmd_vel faster than {MOST_SPEED} m/s or {MOST_TURN} rad/s: {0:?}")]
    Absurd((f64, f64, f64)),
    #[error(
        "a pose with a value that is not a number or infinite, or {MOST_DISTANCE} m away: {0:?}"
    )]
    BadPose((f64, f64, f64)),
    #[error("a pose in frame {0:?}: Player's planners and localizers take poses in the map")]
    NotInMap(String),
    #[error(
        "an initial pose whose covariance is not a covariance (negative or not finite variance)"
    )]
    BadCovariance,
}

/// (x, y, yaw): a pose in the plane, m and rad.
pub type PlanarPose = (f64, f64, f64);

/// A quaternion's turn about z.
pub fn yaw(q: &Quaternion) -> f64 {
    (2.0 * (q.w * q.z + q.x * q.y)).atan2(1.0 - 2.0 * (q.y * q.y + q.z * q.z))
}

/// A pose in the map's frame as (x, y, yaw), if sound.
fn planar(frame: &str, x: f64, y: f64, q: &Quaternion) -> Result<(f64, f64, f64), Refused> {
    if !(frame.is_empty() || frame == "map" || frame == "/map") {
        return Err(Refused::NotInMap(frame.to_string()));
    }
    let pose = (x, y, yaw(q));
    let finite = [x, y, q.x, q.y, q.z, q.w].iter().all(|v| v.is_finite());
    if !finite
        || x.abs() > MOST_DISTANCE
        || y.abs() > MOST_DISTANCE
        || (q.x, q.y, q.z, q.w) == (0.0, 0.0, 0.0, 0.0)
    {
        return Err(Refused::BadPose(pose));
    }
    Ok(pose)
}

/// The goal a `goal_pose` asks of a planner: (x, y, yaw) in the map.
pub fn goal(goal: &PoseStamped) -> Result<(f64, f64, f64), Refused> {
    let p = &goal.pose;
    planar(
        &goal.header.frame_id,
        p.position.x,
        p.position.y,
        &p.orientation,
    )
}

/// The pose and the covariance (Player's packed xx, yy, aa, xy, ya, xa) an `initialpose`
/// gives a localizer.
pub fn initial_pose(pose: &PoseWithCovarianceStamped) -> Result<(PlanarPose, [f64; 6]), Refused> {
    let p = &pose.pose.pose;
    let mean = planar(
        &pose.header.frame_id,
        p.position.x,
        p.position.y,
        &p.orientation,
    )?;
    let c = &pose.pose.covariance;
    let packed = [c[0][0], c[1][1], c[5][5], c[0][1], c[1][5], c[0][5]];
    if packed.iter().any(|v| !v.is_finite()) || packed[..3].iter().any(|&v| v < 0.0) {
        return Err(Refused::BadCovariance);
    }
    Ok((mean, packed))
}

/// The velocity (vx, vy, yaw rate) a `Twist` asks of a planar base.
pub fn velocity(twist: &Twist) -> Result<(f64, f64, f64), Refused> {
    let asked = (twist.linear.x, twist.linear.y, twist.angular.z);
    let all = [
        twist.linear.x,
        twist.linear.y,
        twist.linear.z,
        twist.angular.x,
        twist.angular.y,
        twist.angular.z,
    ];
    if all.iter().any(|v| !v.is_finite()) {
        return Err(Refused::NotFinite(asked));
    }
    if asked.0.hypot(asked.1) > MOST_SPEED || asked.2.abs() > MOST_TURN {
        return Err(Refused::Absurd(asked));
    }
    Ok(asked)
}

/// When a robot driven from ROS 2 must be stopped.
#[derive(Debug, Default)]
pub struct Deadline {
    /// When the last forwarded command came, while the robot is moving.
    moving_since: Option<Instant>,
}

impl Deadline {
    /// A command was forwarded at `now`.
    pub fn commanded(&mut self, velocity: (f64, f64, f64), now: Instant) {
        let still = velocity == (0.0, 0.0, 0.0);
        self.moving_since = (!still).then_some(now);
    }

    /// Whether the robot must be stopped now (once: then it is still).
    pub fn expired(&mut self, now: Instant) -> bool {
        match self.moving_since {
            Some(at) if now.duration_since(at) >= DEADLINE => {
                self.moving_since = None;
                true
            }
            _ => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::msgs::Vector3;

    fn twist(x: f64, z: f64) -> Twist {
        Twist {
            linear: Vector3 { x, y: 0.0, z: 0.0 },
            angular: Vector3 { x: 0.0, y: 0.0, z },
        }
    }

    #[test]
    fn absurd_commands_are_refused() {
        assert_eq!(velocity(&twist(0.5, 0.2)), Ok((0.5, 0.0, 0.2)));
        assert!(matches!(
            velocity(&twist(f64::NAN, 0.0)),
            Err(Refused::NotFinite(_))
        ));
        assert!(matches!(
            velocity(&twist(0.0, f64::INFINITY)),
            Err(Refused::NotFinite(_))
        ));
        assert!(matches!(
            velocity(&twist(40.0, 0.0)),
            Err(Refused::Absurd(_))
        ));
        assert!(matches!(
            velocity(&twist(0.0, -11.0)),
            Err(Refused::Absurd(_))
        ));
    }

    #[test]
    fn goals_and_initial_poses_are_taken_in_the_map_when_sound() {
        use crate::msgs::{Header, Pose, PoseWithCovariance, Time, covariance};
        let at = |frame: &str, x: f64| PoseStamped {
            header: Header::new(Time::default(), frame),
            pose: Pose::planar(x, 2.0, 1.0),
        };
        let (x, y, a) = goal(&at("map", 1.0)).unwrap();
        assert_eq!((x, y), (1.0, 2.0));
        assert!((a - 1.0).abs() < 1e-12);
        assert!(matches!(goal(&at("odom", 1.0)), Err(Refused::NotInMap(_))));
        assert!(matches!(
            goal(&at("map", f64::NAN)),
            Err(Refused::BadPose(_))
        ));
        assert!(matches!(goal(&at("map", 1e9)), Err(Refused::BadPose(_))));
        let start = |variance: f64| PoseWithCovarianceStamped {
            header: Header::new(Time::default(), "map"),
            pose: PoseWithCovariance {
                pose: Pose::planar(0.5, 0.0, 0.0),
                covariance: covariance([variance, variance, 0.0, 0.0, 0.0, 0.1]),
            },
        };
        let (mean, cov) = initial_pose(&start(0.25)).unwrap();
        assert_eq!((mean.0, cov), (0.5, [0.25, 0.25, 0.1, 0.0, 0.0, 0.0]));
        assert_eq!(initial_pose(&start(-1.0)), Err(Refused::BadCovariance));
    }

    #[test]
    fn a_moving_robot_left_without_commands_is_stopped_once() {
        let start = Instant::now();
        let mut deadline = Deadline::default();
        assert!(!deadline.expired(start + DEADLINE * 2), "never commanded");
        deadline.commanded((0.3, 0.0, 0.0), start);
        assert!(!deadline.expired(start + DEADLINE / 2));
        assert!(deadline.expired(start + DEADLINE));
        assert!(!deadline.expired(start + DEADLINE * 3), "once");
        deadline.commanded((0.0, 0.0, 0.0), start);
        assert!(
            !deadline.expired(start + DEADLINE * 3),
            "a stopped robot stays stopped"
        );
    }
}
