//! A localizer's devices: `localize` (hypotheses when the filter updates, set pose, particles)
//! and the estimate as a `position2d` every step, which answers no request, as amcl's.

use player_proto::interfaces::localize::Localize;
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::{Body, Message};
use player_proto::server::Reply;

use super::{asks, data_of};
use crate::nav::frames::{from_pose2d, to_pose2d};
use crate::nav::{LocalizeSettings, LocalizerKind, NavDriver};
use crate::sim::Simulation;

pub(super) fn answer(
    sim: &mut Simulation,
    driver: &NavDriver<LocalizeSettings>,
    request: &Message,
) -> Reply {
    let robot = driver.spec.robot;
    let truth = sim.robots[robot].pose;
    match &request.body {
        Body::Localize(Localize::SetPose(set)) if asks(request, Localize::REQ_SET_POSE) => {
            let mean = from_pose2d(set.mean);
            if driver.spec.kind == LocalizerKind::Fake {
                // fakelocalize moves the model in the simulation.
                sim.robots[robot].pose = mean;
            }
            match sim.nav_mut().localizer_mut(driver.id) {
                Some(localizer) => {
                    localizer.set_pose(mean, truth);
                    Reply::Ack(Body::Empty)
                }
                None => Reply::Nack,
            }
        }
        _ if asks(request, Localize::REQ_GET_PARTICLES) => match sim.nav().localizer(driver.id) {
            Some(localizer) => Reply::Ack(Body::Localize(Localize::Particles(
                localizer.particles(truth),
            ))),
            None => Reply::Nack,
        },
        _ => Reply::Nack,
    }
}

/// A new subscriber gets the current belief at the next step, as amcl's setup sends one.
pub(super) fn subscribed(sim: &mut Simulation, driver: &NavDriver<LocalizeSettings>) {
    if let Some(localizer) = sim.nav_mut().localizer_mut(driver.id) {
        localizer.refresh();
    }
}

/// The hypotheses, when the filter updated during the last step.
pub(super) fn hypotheses(
    sim: &Simulation,
    driver: &NavDriver<LocalizeSettings>,
) -> Vec<(u8, Body)> {
    let Some(localizer) = sim.nav().localizer(driver.id).filter(|l| l.updated) else {
        return Vec::new();
    };
    let truth = sim.robots[driver.spec.robot].pose;
    vec![data_of(
        Localize::DATA_HYPOTHS,
        localizer.hypotheses(truth, sim.time),
    )]
}

/// The estimate as position2d data, every step.
pub(super) fn estimate(sim: &Simulation, driver: &NavDriver<LocalizeSettings>) -> Vec<(u8, Body)> {
    let Some(localizer) = sim.nav().localizer(driver.id) else {
        return Vec::new();
    };
    let pose = localizer.estimate(sim.robots[driver.spec.robot].pose);
    let state = Position2dData {
        pos: to_pose2d(pose),
        ..Position2dData::default()
    };
    vec![data_of(Position2d::DATA_STATE, state)]
}
