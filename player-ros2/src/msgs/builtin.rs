//! builtin_interfaces, std_msgs and rosgraph_msgs: time, headers and the clock.

use serde::{Deserialize, Serialize};

use super::RosMessage;

/// builtin_interfaces/msg/Time.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Time {
    pub sec: i32,
    pub nanosec: u32,
}

impl Time {
    /// Seconds (Player's timestamps) as ROS time; clamped to what `Time` holds.
    pub fn from_seconds(seconds: f64) -> Time {
        if !seconds.is_finite() || seconds <= 0.0 {
            return Time::default();
        }
        let whole = seconds.floor().min(f64::from(i32::MAX));
        let nanosec = (((seconds - whole) * 1e9).round() as u32).min(999_999_999);
        Time {
            sec: whole as i32,
            nanosec,
        }
    }

    /// Nanoseconds since the epoch.
    pub fn nanos(self) -> u64 {
        u64::try_from(self.sec).unwrap_or(0) * 1_000_000_000 + u64::from(self.nanosec)
    }
}

pub const TIME: &str = "int32 sec\nuint32 nanosec\n";

/// std_msgs/msg/Header.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Header {
    pub stamp: Time,
    pub frame_id: String,
}

pub const HEADER: &str = "builtin_interfaces/Time stamp\nstring frame_id\n";

impl Header {
    pub fn new(stamp: Time, frame_id: impl Into<String>) -> Header {
        Header {
            stamp,
            frame_id: frame_id.into(),
        }
    }
}

/// The dependencies of a type with a header.
pub fn header_deps() -> Vec<(&'static str, &'static str)> {
    vec![
        ("std_msgs/msg/Header", HEADER),
        ("builtin_interfaces/msg/Time", TIME),
    ]
}

/// rosgraph_msgs/msg/Clock: the simulated time, on `/clock`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Clock {
    pub clock: Time,
}

impl RosMessage for Clock {
    const TYPE: &'static str = "rosgraph_msgs/msg/Clock";
    const DEFINITION: &'static str = "builtin_interfaces/Time clock\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        vec![("builtin_interfaces/msg/Time", TIME)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seconds_become_seconds_and_nanoseconds() {
        assert_eq!(
            Time::from_seconds(12.25),
            Time {
                sec: 12,
                nanosec: 250_000_000
            }
        );
        assert_eq!(Time::from_seconds(-3.0), Time::default());
        assert_eq!(Time::from_seconds(f64::NAN), Time::default());
        assert_eq!(Time::from_seconds(1e12).sec, i32::MAX);
        assert_eq!(Time { sec: 2, nanosec: 5 }.nanos(), 2_000_000_005);
    }
}
