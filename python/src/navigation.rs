//! The navigation devices: `localize` (where am I, with how much doubt), `planner` (a path to
//! a goal, followed by the planner driver), and `speech` (say something).

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::localize::{
    Localize as LocalizeMessages, LocalizeData, LocalizeSetPose,
};
use player_proto::interfaces::planner::{Planner as PlannerMessages, PlannerCmd, PlannerData};
use player_proto::interfaces::speech::{Speech as SpeechMessages, SpeechCmd};
use player_proto::wire::PlayerString;
use pyo3::prelude::*;

use crate::link::DeviceCore;
use crate::readable::readable;

/// A pose estimate: the best hypothesis of a localization driver.
#[pyclass(frozen, get_all, module = "player3")]
#[derive(Clone)]
pub struct Estimate {
    /// `(x, y, yaw)`, m and rad, in the map's frame.
    pub pose: (f64, f64, f64),
    /// Variances of x, y and yaw (m², m², rad²).
    pub variance: (f64, f64, f64),
    /// The hypothesis' weight, 0 to 1.
    pub weight: f64,
}

#[pymethods]
impl Estimate {
    fn __repr__(&self) -> String {
        let (x, y, yaw) = self.pose;
        format!(
            "Estimate(pose=({x:.3}, {y:.3}, {yaw:.3}), weight={:.2})",
            self.weight
        )
    }
}

fn best_estimate(data: LocalizeData) -> Option<Estimate> {
    let best = data.best()?;
    Some(Estimate {
        pose: (best.mean.px, best.mean.py, best.mean.pa),
        variance: (best.cov[0], best.cov[1], best.cov[2]),
        weight: best.alpha,
    })
}

/// A `localize` device (amcl): `read()` gives the best `Estimate` (or `None` while it has no
/// hypothesis); `set_pose` tells it where the robot is.
#[pyclass(frozen, module = "player3")]
pub struct Localize {
    pub core: DeviceCore,
}
readable!(Localize, LocalizeData, best_estimate, Option<Estimate>, "pose estimate" {
    /// Tells the localizer the robot is at `(x, y, yaw)`, give or take `spread` m (and
    /// `spread` rad in yaw).
    #[pyo3(signature = (x, y, yaw, spread = 0.5))]
    fn set_pose(&self, py: Python<'_>, x: f64, y: f64, yaw: f64, spread: f64) -> PyResult<()> {
        let variance = spread * spread;
        let pose = LocalizeSetPose {
            mean: Pose2d::new(x, y, yaw),
            cov: [variance, variance, variance, 0.0, 0.0, 0.0],
        };
        self.core.set(py, LocalizeMessages::REQ_SET_POSE, pose).map(|_| ())
    }
});

/// A planner's state.
#[pyclass(frozen, get_all, module = "player3")]
#[derive(Clone)]
pub struct PlanState {
    /// Whether a path to the goal was found.
    pub valid: bool,
    /// Whether the robot has reached the goal.
    pub done: bool,
    pub pose: (f64, f64, f64),
    pub goal: (f64, f64, f64),
    /// The waypoint being driven to, and its place in the path.
    pub waypoint: (f64, f64, f64),
    pub waypoint_index: i32,
    pub waypoint_count: u32,
}

#[pymethods]
impl PlanState {
    fn __repr__(&self) -> String {
        format!(
            "PlanState(valid={}, done={}, waypoint {} of {})",
            self.valid, self.done, self.waypoint_index, self.waypoint_count
        )
    }
}

fn triple(p: &Pose2d) -> (f64, f64, f64) {
    (p.px, p.py, p.pa)
}

fn plan_state(data: PlannerData) -> PlanState {
    PlanState {
        valid: data.is_valid(),
        done: data.is_done(),
        pose: triple(&data.pos),
        goal: triple(&data.goal),
        waypoint: triple(&data.waypoint),
        waypoint_index: data.waypoint_idx,
        waypoint_count: data.waypoints_count,
    }
}

/// A `planner` (wavefront): give it a goal, it plans a path and drives the robot along it.
#[pyclass(frozen, module = "player3")]
pub struct Planner {
    pub core: DeviceCore,
}
readable!(Planner, PlannerData, plan_state, PlanState, "planner state" {
    /// Asks the planner to take the robot to `(x, y, yaw)` (map frame).
    fn set_goal(&self, x: f64, y: f64, yaw: f64) -> PyResult<()> {
        let goal = PlannerCmd {
            goal: Pose2d::new(x, y, yaw),
        };
        self.core.command(PlannerMessages::Goal(goal))
    }

    /// The current path as `[(x, y, yaw), ...]` (asked of the planner).
    #[getter]
    fn waypoints(&self, py: Python<'_>) -> PyResult<Vec<(f64, f64, f64)>> {
        let w = self.core.fetch(py, PlannerMessages::REQ_GET_WAYPOINTS)?;
        Ok(w.waypoints.iter().map(triple).collect())
    }

    /// Whether the last goal has been reached (from the newest state; `False` before any).
    #[getter]
    fn done(&self) -> bool {
        self.core
            .newest::<PlannerData>()
            .is_some_and(|(d, _)| d.is_valid() && d.is_done())
    }
});

/// A `speech` device: `say(text)`.
#[pyclass(frozen, module = "player3")]
pub struct Speech {
    pub core: DeviceCore,
}

#[pymethods]
impl Speech {
    /// Says `text` aloud (the server speaks it, or logs it).
    fn say(&self, text: &str) -> PyResult<()> {
        let cmd = SpeechCmd {
            string: PlayerString::new(text),
        };
        self.core.command(SpeechMessages::Say(cmd))
    }

    fn __repr__(&self) -> String {
        format!("<Speech {} on {}>", self.core.label, self.core.link.place)
    }
}
