//! A wavefront planner's device: its state when the planner publishes it, goal commands, the
//! waypoints and enable requests. Start commands are for wavefront's offline planner and are
//! ignored, as wavefront ignores them on its online one.

use player_proto::interfaces::planner::Planner as PlannerMsg;
use player_proto::message::{Body, Message};
use player_proto::server::Reply;

use super::{asks, data_of};
use crate::nav::frames::from_pose2d;
use crate::nav::{NavDriver, PlannerSpec};
use crate::sim::Simulation;

pub(super) fn answer(
    sim: &mut Simulation,
    driver: &NavDriver<PlannerSpec>,
    request: &Message,
) -> Reply {
    let Some(planner) = sim.nav_mut().planner_mut(driver.id) else {
        return Reply::Nack;
    };
    if asks(request, PlannerMsg::REQ_GET_WAYPOINTS) {
        return Reply::Ack(Body::Planner(PlannerMsg::Waypoints(planner.waypoints())));
    }
    match &request.body {
        Body::Planner(PlannerMsg::Enable(on)) if asks(request, PlannerMsg::REQ_ENABLE) => {
            planner.enabled = on.is_on();
            Reply::Ack(Body::Empty)
        }
        _ => Reply::Nack,
    }
}

pub(super) fn command(sim: &mut Simulation, driver: &NavDriver<PlannerSpec>, command: &Message) {
    let Some(planner) = sim.nav_mut().planner_mut(driver.id) else {
        return;
    };
    match &command.body {
        Body::Planner(PlannerMsg::Goal(cmd)) => planner.set_goal(from_pose2d(cmd.goal)),
        other => tracing::debug!("planner command {other:?} ignored, as wavefront ignores it"),
    }
}

/// The state, on the steps the planner publishes it.
pub(super) fn data(sim: &Simulation, driver: &NavDriver<PlannerSpec>) -> Vec<(u8, Body)> {
    match sim.nav().planner(driver.id).filter(|p| p.publish) {
        Some(planner) => vec![data_of(PlannerMsg::DATA_STATE, planner.data())],
        None => Vec::new(),
    }
}
