//! What travels on the page's WebSocket, as JSON text frames: player-proto's own types (a
//! message's body is `player_proto::message::Body`, a device a `DevAddr`, a pose a `Pose2d`),
//! in an envelope that says which robot and what kind of message.

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::Position2dCmdVel;
use player_proto::message::Body;
use player_proto::wire::DevAddr;
use serde::{Deserialize, Serialize};

/// Where a robot's connection stands, as its row shows it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case", tag = "state", content = "why")]
pub enum Link {
    /// Not heard from yet.
    Connecting,
    Connected,
    /// The server went away (why); the relay is trying again.
    Reconnecting(String),
}

/// Server → page.
#[derive(Debug, Serialize)]
#[serde(rename_all = "snake_case", tag = "type")]
pub enum ToPage<'a> {
    /// First on every socket: whether this page may command, and the rule that decided.
    Hello { controller: bool, rule: String },
    /// A robot's connection changed.
    Robot { robot: &'a str, link: &'a Link },
    /// The walls of the world the robots are in, where the relay knows them.
    World { walls: &'a crate::walls::Walls },
    /// A message a robot's server sent: data, or a reply that describes a device.
    Message {
        robot: &'a str,
        kind: Kind,
        device: DevAddr,
        subtype: u8,
        /// The server's timestamp, s.
        time: f64,
        body: &'a Body,
    },
    /// Once a second: a row per robot.
    Status { rows: &'a [Row] },
    /// A command this page may not send, or one that is wrong; nothing was sent.
    Refused { why: String },
}

/// A server message's kind, as the page tells them apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    Data,
    Reply,
}

/// A robot's row in the status table.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    pub robot: String,
    pub link: Link,
    pub devices: Vec<DeviceRow>,
}

/// A device's rate and the age of its newest data.
#[derive(Debug, Clone, Serialize)]
pub struct DeviceRow {
    pub device: DevAddr,
    /// Readings per second over the last second, as `DeviceStats::updates` counts them (a
    /// ranger's ranges and intensities, stamped alike, are one reading).
    pub hz: f64,
    /// Seconds since the newest data; `None` before any.
    pub age: Option<f64>,
    /// Whether the pages are sent its data: false for a device no open page shows (a robot
    /// out of every page's view, a camera), which the relay then does not subscribe to.
    pub shown: bool,
}

/// Page → server: what the page has in view (from any page), and the controller's commands,
/// in player-proto's types.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(rename_all = "snake_case", tag = "type", deny_unknown_fields)]
pub enum FromPage {
    /// The robots the page has in view: it is sent their sensors (at most
    /// [`crate::views::SENSORS_IN_VIEW`] robots'), and every robot's pose.
    Show { robots: Vec<String> },
    /// Go to `goal` (world pose): through the robot's planner of the same index when it has
    /// one, else as a position command to the base.
    Goal {
        robot: String,
        device: DevAddr,
        goal: Pose2d,
    },
    /// Drive a position2d device; the page repeats it while a key is held, and the server
    /// stops the base when the repeats stop (see `control::DEAD_MAN`).
    Velocity {
        robot: String,
        device: DevAddr,
        command: Position2dCmdVel,
    },
}
