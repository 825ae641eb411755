//! Player's `wavefront` as a state machine stepped with the simulation: a goal is planned over
//! the inflated map, the path thinned to waypoints, and the robot driven from one waypoint to
//! the next until it stands within `distance_epsilon` and `angle_epsilon` of the goal. What it
//! tells a client follows wavefront: the state every cycle that is more than a quarter second
//! after the last, the waypoint being driven to with the goal's heading, the index *after* it
//! (wavefront counts it up when it takes the waypoint), and, once done, the goal with neither
//! waypoint nor count. Enabling and disabling pause the driving, not the state. A replan
//! happens on a new goal, and, when `replan_dist_thresh` and `replan_min_time` are not
//! negative, after the robot moved that far and that long since the last plan.
//!
//! Unlike wavefront, a new goal that cannot be reached drops the old plan (valid 0) rather
//! than keep driving it.

use std::f64::consts::FRAC_PI_4;
use std::sync::Arc;

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::planner::{PlannerData, PlannerWaypoints};

use super::cspace::CostSpace;
use super::frames::to_pose2d;
use super::search::find_path;
use super::steer;
use super::waypoints::thin;
use crate::sim::wrap;
use crate::world::Pose;

/// wavefront publishes its state when more than this has passed since it last did, s.
const PUBLISH_AFTER: f64 = 0.25;

/// What a `.cfg` asks of wavefront, once read.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannerSettings {
    /// `distance_epsilon`, m: a waypoint is reached this near, and the goal too.
    pub dist_eps: f64,
    /// `angle_epsilon`, rad: the goal's heading is reached this near.
    pub ang_eps: f64,
    /// `replan_dist_thresh`, m, and `replan_min_time`, s: negative turns replanning off.
    pub replan_dist: f64,
    pub replan_time: f64,
    /// `add_rotational_waypoints`: turn on the spot toward a waypoint more than 45° off.
    pub rotational_waypoints: bool,
}

/// A wavefront planner's running state.
#[derive(Debug, Clone, PartialEq)]
pub struct Planner {
    pub settings: PlannerSettings,
    pub space: Arc<CostSpace>,
    pub enabled: bool,
    /// The goal; `None` until the first.
    goal: Option<Pose>,
    new_goal: bool,
    waypoints: Vec<(f64, f64)>,
    /// wavefront's `curr_waypoint`: the index after the waypoint being driven to; `None`
    /// with no plan to follow (none yet, or done).
    curr: Option<usize>,
    waypoint: Pose,
    rotating: bool,
    /// Time and place of the last plan.
    last_plan: (f64, f64, f64),
    last_publish: Option<f64>,
    /// The state goes out after this step.
    pub publish: bool,
    /// The pose the planner last read.
    pose: Pose,
    /// The robot was told to stop and has not been driven since.
    stopped: bool,
}

impl Planner {
    pub fn new(settings: PlannerSettings, space: Arc<CostSpace>) -> Planner {
        Planner {
            settings,
            space,
            enabled: true,
            goal: None,
            new_goal: false,
            waypoints: Vec::new(),
            curr: None,
            waypoint: Pose::default(),
            rotating: false,
            last_plan: (0.0, 0.0, 0.0),
            last_publish: None,
            publish: false,
            pose: Pose::default(),
            stopped: false,
        }
    }

    /// A goal command: planned at the next step.
    pub fn set_goal(&mut self, goal: Pose) {
        self.goal = Some(goal);
        self.new_goal = true;
    }

    /// One cycle at simulated time `t` with the robot believed at `pose`: the velocity to
    /// drive at (forward, turn), or `None` to leave the robot's command alone.
    pub fn step(&mut self, t: f64, pose: Pose) -> Option<(f64, f64)> {
        self.pose = pose;
        self.publish = self
            .last_publish
            .is_none_or(|last| t - last > PUBLISH_AFTER);
        if self.publish {
            self.last_publish = Some(t);
        }
        if !self.enabled {
            return self.stop();
        }
        let Some(goal) = self.goal else {
            return self.stop();
        };
        if self.new_goal || self.replan_due(t) {
            self.plan(t, goal);
        }
        let going_for_goal = self.curr == Some(self.waypoints.len());
        let to_goal = (pose.x - goal.x).hypot(pose.y - goal.y);
        if going_for_goal
            && to_goal < self.settings.dist_eps
            && wrap(goal.a - pose.a).abs() < self.settings.ang_eps
        {
            self.curr = None;
            self.new_goal = false;
            return self.stop();
        }
        let Some(curr) = self.curr else {
            return self.stop();
        };
        let to_waypoint = (pose.x - self.waypoint.x).hypot(pose.y - self.waypoint.y);
        let reached = if self.rotating {
            wrap(self.waypoint.a - pose.a).abs() < FRAC_PI_4
        } else {
            to_waypoint < self.settings.dist_eps
        };
        if (self.new_goal || reached) && curr < self.waypoints.len() {
            self.take_waypoint(curr, goal);
        }
        self.stopped = false;
        Some(steer::toward(pose, self.waypoint))
    }

    /// Moves on to waypoint `index`, or first turns toward it on the spot when it lies more
    /// than 45° off and farther than `distance_epsilon`.
    fn take_waypoint(&mut self, index: usize, goal: Pose) {
        let (x, y) = self.waypoints[index];
        self.waypoint = Pose { x, y, a: goal.a };
        self.curr = Some(index + 1);
        self.rotating = false;
        let p = self.pose;
        if self.settings.rotational_waypoints || index + 1 == 2 {
            let bearing = (y - p.y).atan2(x - p.x);
            let far = (x - p.x).hypot(y - p.y) > self.settings.dist_eps;
            if far && wrap(bearing - p.a).abs() > FRAC_PI_4 {
                self.waypoint = Pose { a: bearing, ..p };
                self.curr = Some(index);
                self.rotating = true;
            }
        }
        self.new_goal = false;
    }

    fn replan_due(&self, t: f64) -> bool {
        let (time, x, y) = self.last_plan;
        let s = &self.settings;
        let moved = (self.pose.x - x).hypot(self.pose.y - y);
        let following = self.curr.is_some();
        s.replan_dist >= 0.0
            && s.replan_time >= 0.0
            && moved > s.replan_dist
            && t - time > s.replan_time
            && following
    }

    /// Plans from the robot's pose to `goal`. A new goal with no way there leaves no plan;
    /// a replan that fails keeps the plan being followed.
    fn plan(&mut self, t: f64, goal: Pose) {
        self.last_plan = (t, self.pose.x, self.pose.y);
        let space = &*self.space;
        let path = space
            .cell_of(self.pose.x, self.pose.y)
            .zip(space.cell_of(goal.x, goal.y))
            .and_then(|(from, to)| find_path(space, from, to));
        match path {
            Some(path) => {
                self.waypoints = thin(space, &path)
                    .into_iter()
                    .map(|k| {
                        let (i, j) = space.cell_at(k);
                        space.point_of(i, j)
                    })
                    .collect();
                self.curr = Some(0);
                self.new_goal = true;
            }
            None if self.new_goal => {
                tracing::info!(
                    "wavefront: no path from ({:.2}, {:.2}) to ({:.2}, {:.2})",
                    self.pose.x,
                    self.pose.y,
                    goal.x,
                    goal.y
                );
                self.waypoints.clear();
                self.curr = None;
                self.new_goal = false;
            }
            None => tracing::debug!("wavefront: replanning failed, keeping the plan"),
        }
    }

    /// Stops the robot once, then leaves it to whoever else drives it.
    fn stop(&mut self) -> Option<(f64, f64)> {
        if self.stopped {
            return None;
        }
        self.stopped = true;
        Some((0.0, 0.0))
    }

    /// The state as wavefront sends it.
    pub fn data(&self) -> PlannerData {
        let valid = !self.waypoints.is_empty();
        let done = valid && self.curr.is_none();
        let mut data = PlannerData {
            valid: u8::from(valid),
            done: u8::from(done),
            pos: to_pose2d(self.pose),
            goal: self.goal.map(to_pose2d).unwrap_or_default(),
            ..PlannerData::default()
        };
        if let (true, false, Some(curr)) = (valid, done, self.curr) {
            data.waypoint = to_pose2d(self.waypoint);
            data.waypoint_idx = i32::try_from(curr).unwrap_or(i32::MAX);
            data.waypoints_count = u32::try_from(self.waypoints.len()).unwrap_or(u32::MAX);
        }
        data
    }

    /// The whole plan, headings 0, and its length, as wavefront answers the request (the plan
    /// stays after the goal is reached).
    pub fn waypoints(&self) -> PlannerWaypoints {
        let waypoints_distance = self
            .waypoints
            .windows(2)
            .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
            .sum();
        PlannerWaypoints {
            waypoints_distance,
            waypoints: self
                .waypoints
                .iter()
                .map(|&(x, y)| Pose2d::new(x, y, 0.0))
                .collect(),
        }
    }
}
