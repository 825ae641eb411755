//! The `planner` interface (code 44): a 2-D path planner (Player's `wavefront`) that takes a
//! goal, plans waypoints through the map and drives a position2d device along them.

use super::common::{BoolValue, Pose2d};

/// Request subtype whose request body is empty (the ACK carries the waypoints).
pub const REQ_GET_WAYPOINTS: u8 = 1;

xdr_struct! {
    /// `player_planner_data_t`: progress along the current plan.
    #[derive(Copy)]
    pub struct PlannerData {
        /// Non-zero when a path to the goal was found.
        pub valid: u8,
        /// Non-zero once the goal is reached.
        pub done: u8,
        /// Where the robot is, m, m, rad.
        pub pos: Pose2d,
        pub goal: Pose2d,
        /// The waypoint being driven to.
        pub waypoint: Pose2d,
        /// Index of `waypoint` in the plan. Meaningless without a plan or once done: the
        /// definition allows a negative value there, `wavefront` sends 0.
        pub waypoint_idx: i32,
        /// How many waypoints the plan has. Only a number: the waypoints themselves come with
        /// a GET_WAYPOINTS request.
        pub waypoints_count: u32,
    }
}

xdr_struct! {
    /// `player_planner_cmd_t`: where to go (GOAL), or where planning starts from (START).
    #[derive(Copy)]
    pub struct PlannerCmd {
        /// m, m, rad.
        pub goal: Pose2d,
    }
}

xdr_struct! {
    /// `player_planner_waypoints_req_t`: the whole plan.
    pub struct PlannerWaypoints {
        /// Length of the path through all the waypoints, m.
        pub waypoints_distance: f64,
        pub waypoints: Vec<Pose2d>,
    }
}

/// `player_planner_enable_req_t`: 1 resumes plan execution, 0 stops the robot (null reply).
pub type PlannerEnable = BoolValue;

interface_messages! {
    /// Messages of the `planner` interface.
    pub enum Planner for PLANNER {
        Data 1 as DATA_STATE => State(PlannerData),
        Command 1 as CMD_GOAL => Goal(PlannerCmd),
        Command 2 as CMD_START => Start(PlannerCmd),
        Request 1 as REQ_GET_WAYPOINTS => Waypoints(PlannerWaypoints),
        Request 2 as REQ_ENABLE => Enable(PlannerEnable),
    }
}

impl PlannerData {
    pub fn is_valid(&self) -> bool {
        self.valid != 0
    }

    pub fn is_done(&self) -> bool {
        self.done != 0
    }
}
