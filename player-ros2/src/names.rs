//! ROS 2's names for a Player robot: its namespace (its name, else `HOST_PORT`, made a legal
//! ROS name), its topics (`/ns/scan`, a second device's `/ns/scan_1`) and its frames
//! (`ns/odom`, `ns/base_link`, `ns/laser`), as REP-105 names them for several robots in one
//! tf tree.

use player_proto::RobotId;

/// A robot's namespace: letters, digits and single `_`s, not starting with a digit.
pub fn namespace(robot: &RobotId) -> String {
    let raw = match robot.name() {
        Some(name) => name.to_string(),
        None => format!("{}_{}", robot.host(), robot.port()),
    };
    let mut ns = String::with_capacity(raw.len());
    for c in raw.chars() {
        let c = if c.is_ascii_alphanumeric() { c } else { '_' };
        // ROS 2 names take no run of underscores.
        if !(c == '_' && ns.ends_with('_')) {
            ns.push(c);
        }
    }
    if ns.starts_with(|c: char| c.is_ascii_digit()) || ns.is_empty() {
        ns.insert_str(0, "robot_");
    }
    ns
}

/// A topic of the robot: `/ns/base`, and `/ns/base_i` for device index `i` > 0.
pub fn topic(ns: &str, base: &str, index: u16) -> String {
    if index == 0 {
        format!("/{ns}/{base}")
    } else {
        format!("/{ns}/{base}_{index}")
    }
}

/// A frame of the robot: `ns/base`, `ns/base_i` for index `i` > 0.
pub fn frame(ns: &str, base: &str, index: u16) -> String {
    if index == 0 {
        format!("{ns}/{base}")
    } else {
        format!("{ns}/{base}_{index}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn robots_are_named_as_ros_allows() {
        let r0 = RobotId::new("localhost", 6665).named("r0").unwrap();
        assert_eq!(namespace(&r0), "r0");
        assert_eq!(
            namespace(&RobotId::new("localhost", 6665)),
            "localhost_6665"
        );
        assert_eq!(
            namespace(&RobotId::new("127.0.0.1", 6666)),
            "robot_127_0_0_1_6666"
        );
        let dashed = RobotId::new("h", 1).named("pioneer-2.b").unwrap();
        assert_eq!(namespace(&dashed), "pioneer_2_b");
        let doubled = RobotId::new("h", 1).named("a-.b").unwrap();
        assert_eq!(namespace(&doubled), "a_b");
        assert_eq!(topic("r0", "scan", 0), "/r0/scan");
        assert_eq!(topic("r0", "scan", 2), "/r0/scan_2");
        assert_eq!(frame("r0", "laser", 1), "r0/laser_1");
    }
}
