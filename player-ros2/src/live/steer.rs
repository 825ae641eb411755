//! Steering a Player robot from ROS 2, as the bridge and the relay's front both do: what ROS
//! 2 told its node, taken under the node's lock ([`Told`]), then passed on without it — its
//! `cmd_vel` to its base (checked, with a deadline), goals to its planner and starts to its
//! localizer — and its planner's path asked for whenever the plan changes. What the robot
//! says of itself once it is there is [`super::describe`].

use std::collections::HashSet;
use std::time::Instant;

use super::RobotNode;
use super::commands::{Deadline, Refused, goal, initial_pose, velocity};
use crate::msgs::{PoseStamped, PoseWithCovarianceStamped, Time, Twist};
use crate::out::Converted;
use player_proto::RobotId;
use player_proto::client::Client;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::localize::{Localize, LocalizeSetPose};
use player_proto::interfaces::planner::{Planner, PlannerCmd};
use player_proto::wire::Interface;

/// How often a followed plan is asked for again.
pub const PLAN_AGAIN: std::time::Duration = std::time::Duration::from_secs(2);

/// What ROS 2 told a robot's node since the last look.
#[derive(Debug, Default)]
pub struct Told {
    cmd_vels: Vec<Twist>,
    goals: Vec<PoseStamped>,
    starts: Vec<PoseWithCovarianceStamped>,
}

impl Told {
    /// Takes what `node` received.
    pub fn take(node: &RobotNode) -> Told {
        Told {
            cmd_vels: node.cmd_vels(),
            goals: node.goals(),
            starts: node.initial_poses(),
        }
    }
}

/// Goals to the robot's planner, starts to its localizer; what is unsound, refused (said once
/// per kind).
fn goals_and_poses(
    robot: &RobotId,
    client: &Client,
    told: &Told,
    refused: &mut HashSet<&'static str>,
) {
    let mut refuse = |kind: &'static str, why: &dyn std::fmt::Display| {
        if refused.insert(kind) {
            tracing::warn!("{robot}: refused {why} (said once)");
        }
    };
    for asked in &told.goals {
        match goal(asked) {
            Ok((x, y, a)) => {
                tracing::info!("{robot}: goal ({x:.2}, {y:.2}, {a:.2}) to its planner");
                let addr = client.addr(Interface::PLANNER, 0);
                client.command(
                    addr,
                    Planner::Goal(PlannerCmd {
                        goal: Pose2d::new(x, y, a),
                    }),
                );
            }
            Err(why) => refuse("goal", &why),
        }
    }
    for asked in &told.starts {
        match initial_pose(asked) {
            Ok(((x, y, a), cov)) => {
                let addr = client.addr(Interface::LOCALIZE, 0);
                let start = LocalizeSetPose {
                    mean: Pose2d::new(x, y, a),
                    cov,
                };
                if let Err(e) = client.request_with(addr, Localize::REQ_SET_POSE, start) {
                    tracing::warn!("{robot}: the localizer refused the initial pose: {e}");
                }
            }
            Err(why) => refuse("initial pose", &why),
        }
    }
}

/// What steering one robot remembers: when its base must be stopped, what was refused, which
/// plan was last asked for.
#[derive(Debug)]
pub struct Steering {
    robot: RobotId,
    deadline: Deadline,
    /// Kinds of refused command already said.
    refused: HashSet<&'static str>,
    /// The planner's (goal, number of way-points) when its path was last asked for, and when.
    planned: Option<((Pose2d, u32), Instant)>,
}

impl Steering {
    pub fn new(robot: &RobotId) -> Steering {
        Steering {
            robot: robot.clone(),
            deadline: Deadline::default(),
            refused: HashSet::new(),
            planned: None,
        }
    }

    /// What ROS 2 told the robot, passed on: goals and starts, then the newest sound
    /// `cmd_vel` (each unsound one refused), and a stop when they stopped coming.
    pub fn steer(&mut self, told: &Told, client: &Client) {
        goals_and_poses(&self.robot, client, told, &mut self.refused);
        let now = Instant::now();
        let base = client.position2d(0);
        let mut newest = None;
        for twist in &told.cmd_vels {
            match velocity(twist) {
                Ok(v) => newest = Some(v),
                Err(refused) => {
                    let kind = match refused {
                        Refused::NotFinite(_) => "not finite",
                        _ => "absurd",
                    };
                    if self.refused.insert(kind) {
                        tracing::warn!("{}: refused {refused} (said once)", self.robot);
                    }
                }
            }
        }
        if let Some((vx, vy, va)) = newest {
            base.set_velocity(vx, vy, va);
            self.deadline.commanded((vx, vy, va), now);
        }
        if self.deadline.expired(now) {
            tracing::info!("{}: no cmd_vel for half a second: stopping", self.robot);
            base.set_velocity(0.0, 0.0, 0.0);
        }
    }

    /// The planner's path as `/ns/plan` when its plan changed (a new goal, another number of
    /// way-points) since the last one asked for, and again every [`PLAN_AGAIN`] while it is
    /// followed, as ROS's planners publish theirs as they go: Player's planner says only how
    /// many way-points it has; the path is the reply to a request.
    pub fn plan(&mut self, ns: &str, client: &Client) -> Option<Converted> {
        let addr = client.addr(Interface::PLANNER, 0);
        let (state, stamped) = client.latest_kind(addr, Planner::DATA_STATE)?;
        let plan = (state.goal, state.waypoints_count);
        let now = Instant::now();
        let asked_lately = self
            .planned
            .is_some_and(|(p, at)| p == plan && (state.is_done() || now - at < PLAN_AGAIN));
        if !state.is_valid() || state.waypoints_count == 0 || asked_lately {
            return None;
        }
        self.planned = Some((plan, now));
        match client.fetch(addr, Planner::REQ_GET_WAYPOINTS) {
            Ok(waypoints) => {
                let stamp = Time::from_seconds(stamped.message.header.timestamp);
                Some(crate::convert::plan(ns, 0, stamp, &waypoints))
            }
            Err(e) => {
                tracing::warn!("{}: no way-points from its planner: {e}", self.robot);
                None
            }
        }
    }
}
