//! The navigation drivers of a .cfg, read as Player reads them: `amcl` (odometry, laser and
//! map from `requires`, `init_pose`, `update_thresh`, `pf_min_samples`), `fakelocalize`
//! (`model`, a simulation in `requires`) and `wavefront` (`output` and `input` position2d,
//! the map; `safety_dist`, `max_radius`, `dist_penalty`, `distance_epsilon`, `angle_epsilon`,
//! `replan_dist_thresh`, `replan_min_time`, `add_rotational_waypoints`). Lengths are metres,
//! angles degrees, as in Player's .cfg. Every other option is reported as ignored.

use std::sync::Arc;

use player_proto::wire::Interface;

use super::drivers::at;
use super::{DriverBlock, ServedDevice, Source};
use crate::nav::localize::{DEFAULT_PARTICLES, DEFAULT_UPDATE_ANGLE, DEFAULT_UPDATE_DISTANCE};
use crate::nav::{
    LocalizeSettings, LocalizerKind, NavDriver, PlannerSettings, PlannerSpec, PoseInput,
};
use crate::sim::Simulation;
use crate::world::{Pose, World};
use crate::worldfile::WorldFileError;

/// Options every driver block has.
const COMMON: &[&str] = &[
    "name",
    "provides",
    "requires",
    "plugin",
    "alwayson",
    "report_as",
];
const AMCL_READ: &[&str] = &["init_pose", "update_thresh", "pf_min_samples"];
const FAKE_READ: &[&str] = &["model"];
const WAVEFRONT_READ: &[&str] = &[
    "safety_dist",
    "max_radius",
    "dist_penalty",
    "distance_epsilon",
    "angle_epsilon",
    "replan_dist_thresh",
    "replan_min_time",
    "add_rotational_waypoints",
];

/// wavefront's defaults (Player's).
const SAFETY_DIST: f64 = 0.25;
const MAX_RADIUS: f64 = 1.0;
const DIST_PENALTY: f64 = 1.0;
const DISTANCE_EPSILON: f64 = 0.5;
const ANGLE_EPSILON_DEG: f64 = 10.0;
const REPLAN_DIST: f64 = 2.0;
const REPLAN_TIME: f64 = 2.0;

/// The source of a device a navigation block provides, or `None` for an interface the driver
/// does not provide (reported in `ignored`).
pub(super) fn source(
    driver: &DriverBlock,
    world: &World,
    served: &[ServedDevice],
    interf: Interface,
    ignored: &mut Vec<String>,
) -> Result<Option<Source>, WorldFileError> {
    let name = driver.name.as_str();
    let (read, source) = match (name, interf) {
        ("amcl", Interface::LOCALIZE) => (AMCL_READ, Source::Localize(amcl(driver, served)?)),
        ("amcl", Interface::POSITION2D) => (AMCL_READ, Source::Estimate(amcl(driver, served)?)),
        ("fakelocalize", Interface::LOCALIZE) => {
            (FAKE_READ, Source::Localize(fake(driver, world, served)?))
        }
        ("fakelocalize", Interface::POSITION2D) => {
            (FAKE_READ, Source::Estimate(fake(driver, world, served)?))
        }
        ("wavefront", Interface::PLANNER) => {
            (WAVEFRONT_READ, Source::Planner(wavefront(driver, served)?))
        }
        (_, other) => {
            note(
                ignored,
                driver.ignored(&format!("{other} of driver {name:?}")),
            );
            return Ok(None);
        }
    };
    let unread: Vec<&str> = driver
        .block
        .properties
        .iter()
        .map(|p| p.name.as_str())
        .filter(|n| !COMMON.contains(n) && !read.contains(n))
        .collect();
    if !unread.is_empty() {
        let what = format!("{name} options {} (not simulated)", unread.join(", "));
        note(ignored, driver.ignored(&what));
    }
    Ok(Some(source))
}

fn note(ignored: &mut Vec<String>, note: String) {
    if !ignored.contains(&note) {
        ignored.push(note);
    }
}

/// The robot a required position2d is, or an error naming the entry.
fn robot_of(
    driver: &DriverBlock,
    text: &str,
    device: Option<&ServedDevice>,
) -> Result<usize, WorldFileError> {
    match device.map(|d| &d.source) {
        Some(Source::Position { robot }) => Ok(*robot),
        Some(_) => Err(driver.error(format!("{text} is not a robot's position2d"))),
        None => Err(driver.error(format!(
            "{} requires {text}, which no driver provides before it",
            driver.name
        ))),
    }
}

/// Checks that a required device, when listed, is provided.
fn check_provided(
    driver: &DriverBlock,
    found: Option<(&str, Option<&ServedDevice>)>,
) -> Result<(), WorldFileError> {
    match found {
        Some((text, None)) => Err(driver.error(format!(
            "{} requires {text}, which no driver provides before it",
            driver.name
        ))),
        _ => Ok(()),
    }
}

fn number(driver: &DriverBlock, name: &str, default: f64) -> Result<f64, WorldFileError> {
    match driver.block.get(name) {
        None => Ok(default),
        Some(p) => p
            .value
            .as_f64()
            .filter(|v| v.is_finite())
            .ok_or_else(|| at(p, format!("{name} must be a number"))),
    }
}

fn tuple(driver: &DriverBlock, name: &str, len: usize) -> Result<Option<Vec<f64>>, WorldFileError> {
    match driver.block.get(name) {
        None => Ok(None),
        Some(p) => match p.value.numbers() {
            Some(n) if n.len() >= len => Ok(Some(n)),
            _ => Err(at(p, format!("{name} must be a list of {len} numbers"))),
        },
    }
}

fn amcl(
    driver: &DriverBlock,
    served: &[ServedDevice],
) -> Result<NavDriver<LocalizeSettings>, WorldFileError> {
    let (text, odometry) = driver
        .required_as(served, Interface::POSITION2D, Some("odometry"))
        .ok_or_else(|| driver.error("amcl needs requires [ \"odometry:::position2d:N\" … ]"))?;
    let robot = robot_of(driver, text, odometry)?;
    check_provided(driver, driver.required_as(served, Interface::LASER, None))?;
    check_provided(driver, driver.required_as(served, Interface::MAP, None))?;
    let init_pose = tuple(driver, "init_pose", 3)?.map(|n| Pose {
        x: n[0],
        y: n[1],
        a: n[2].to_radians(),
    });
    let thresh = tuple(driver, "update_thresh", 2)?;
    let particles = number(driver, "pf_min_samples", DEFAULT_PARTICLES as f64)?;
    let settings = LocalizeSettings {
        kind: LocalizerKind::Amcl,
        robot,
        init_pose,
        update_distance: thresh.as_ref().map_or(DEFAULT_UPDATE_DISTANCE, |t| t[0]),
        update_angle: thresh.map_or(DEFAULT_UPDATE_ANGLE, |t| t[1].to_radians()),
        particles: particles.max(1.0) as usize,
    };
    Ok(NavDriver {
        id: driver.id,
        spec: Arc::new(settings),
    })
}

fn fake(
    driver: &DriverBlock,
    world: &World,
    served: &[ServedDevice],
) -> Result<NavDriver<LocalizeSettings>, WorldFileError> {
    match driver.required_as(served, Interface::SIMULATION, None) {
        None => return Err(driver.error("fakelocalize needs requires [ \"simulation:N\" ]")),
        found => check_provided(driver, found)?,
    }
    let model = driver
        .block
        .get("model")
        .and_then(|p| p.value.as_str())
        .ok_or_else(|| driver.error("fakelocalize needs a model \"name\""))?;
    let robot = world
        .robots
        .iter()
        .position(|r| r.name == model)
        .ok_or_else(|| driver.error(format!("fakelocalize: no robot named {model:?}")))?;
    let settings = LocalizeSettings {
        kind: LocalizerKind::Fake,
        robot,
        init_pose: None,
        update_distance: 0.0,
        update_angle: 0.0,
        particles: 1,
    };
    Ok(NavDriver {
        id: driver.id,
        spec: Arc::new(settings),
    })
}

fn wavefront(
    driver: &DriverBlock,
    served: &[ServedDevice],
) -> Result<NavDriver<PlannerSpec>, WorldFileError> {
    let (text, output) = driver
        .required_as(served, Interface::POSITION2D, Some("output"))
        .ok_or_else(|| driver.error("wavefront needs requires [ \"output:::position2d:N\" … ]"))?;
    let robot = robot_of(driver, text, output)?;
    let (text, input) = driver
        .required_as(served, Interface::POSITION2D, Some("input"))
        .ok_or_else(|| driver.error("wavefront needs requires [ \"input:::position2d:N\" … ]"))?;
    let input = match input.map(|d| &d.source) {
        Some(Source::Estimate(localizer)) => PoseInput::Localizer(localizer.id),
        Some(Source::Position { robot: r }) if *r == robot => PoseInput::Odometry,
        Some(_) => {
            return Err(driver.error(format!(
                "{text} is neither a localizer's position2d nor the output robot's"
            )));
        }
        None => {
            return Err(driver.error(format!(
                "wavefront requires {text}, which no driver provides before it"
            )));
        }
    };
    let map = match driver.required_as(served, Interface::MAP, None) {
        Some((
            _,
            Some(ServedDevice {
                source: Source::Map(map),
                ..
            }),
        )) => map.clone(),
        Some((text, _)) => {
            return Err(driver.error(format!(
                "wavefront requires {text}, which no mapfile provides before it"
            )));
        }
        None => return Err(driver.error("wavefront needs requires [ \"map:N\" … ]")),
    };
    let settings = PlannerSettings {
        dist_eps: number(driver, "distance_epsilon", DISTANCE_EPSILON)?,
        ang_eps: number(driver, "angle_epsilon", ANGLE_EPSILON_DEG)?.to_radians(),
        replan_dist: number(driver, "replan_dist_thresh", REPLAN_DIST)?,
        replan_time: number(driver, "replan_min_time", REPLAN_TIME)?,
        rotational_waypoints: number(driver, "add_rotational_waypoints", 1.0)? != 0.0,
    };
    let spec = PlannerSpec {
        settings,
        robot,
        input,
        map,
        safety_dist: number(driver, "safety_dist", SAFETY_DIST)?,
        max_radius: number(driver, "max_radius", MAX_RADIUS)?,
        dist_penalty: number(driver, "dist_penalty", DIST_PENALTY)?,
    };
    Ok(NavDriver {
        id: driver.id,
        spec: Arc::new(spec),
    })
}

/// Starts, in `sim`, the running state of every navigation driver the served `devices` show
/// (one per driver block, however many devices show it).
pub fn attach_navigation(sim: &mut Simulation, devices: &[ServedDevice]) {
    for d in devices {
        match &d.source {
            Source::Localize(driver) | Source::Estimate(driver) => sim.attach_localizer(driver),
            Source::Planner(driver) => sim.attach_planner(driver),
            _ => {}
        }
    }
}
