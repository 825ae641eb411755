//! The devices of a `stage` driver block: the simulation, or a model's position, rangers,
//! fiducial finders, cameras, blobfinders and grippers, handed out in the model's order as
//! Stage's plugin hands them out.

use player_proto::wire::Interface;

use super::{DriverBlock, Source};
use crate::world::World;
use crate::worldfile::WorldFileError;

/// How many devices of each kind one `stage` block has provided so far.
#[derive(Debug, Default)]
pub(super) struct Counts {
    rangers: usize,
    fiducials: usize,
    cameras: usize,
    blobfinders: usize,
    grippers: usize,
}

/// The source of `text` (an address the block provides), or `None` when it is ignored.
pub(super) fn source(
    driver: &DriverBlock,
    world: &World,
    text: &str,
    interf: Interface,
    counts: &mut Counts,
    ignored: &mut Vec<String>,
) -> Result<Option<Source>, WorldFileError> {
    if interf == Interface::SIMULATION {
        return Ok(Some(Source::Simulation));
    }
    let model = driver
        .block
        .get("model")
        .and_then(|p| p.value.as_str())
        .ok_or_else(|| driver.error(format!("stage driver providing {text} needs a model")))?;
    let robot = world
        .robots
        .iter()
        .position(|r| r.name == model)
        .ok_or_else(|| driver.error(format!("no robot {model:?} in the world")))?;
    let spec = &world.robots[robot];
    let next = |count: &mut usize, what: &str, has: usize| {
        next_index(count, has).ok_or_else(|| {
            driver.error(format!(
                "{text}: {model} has only {has} {what}(s) in the world, \
                 so the .cfg provides one too many"
            ))
        })
    };
    Ok(Some(match interf {
        Interface::POSITION2D => Source::Position { robot },
        Interface::RANGER => Source::Ranger {
            robot,
            ranger: next(&mut counts.rangers, "ranger", spec.rangers.len())?,
        },
        Interface::FIDUCIAL => Source::Fiducial {
            robot,
            finder: next(
                &mut counts.fiducials,
                "fiducial finder",
                spec.fiducials.len(),
            )?,
        },
        Interface::CAMERA => Source::Camera {
            robot,
            camera: next(&mut counts.cameras, "camera", spec.cameras.len())?,
            jpeg_quality: None,
        },
        Interface::BLOBFINDER => Source::Blobfinder {
            robot,
            finder: next(
                &mut counts.blobfinders,
                "blobfinder",
                spec.blobfinders.len(),
            )?,
        },
        // Stage 4's plugin refuses `power` ("doesn't support interface type 2"); Stage 3
        // served the model's power pack, as player-sim does.
        Interface::POWER if spec.battery.is_some() => Source::Power { robot },
        Interface::POWER => {
            return Err(driver.error(format!(
                "{text}: {model} has no power pack in the world (give it `joules`)"
            )));
        }
        Interface::GRIPPER => Source::Gripper {
            robot,
            gripper: next(&mut counts.grippers, "gripper", spec.grippers.len())?,
        },
        other => {
            ignored.push(driver.ignored(&format!("{other} of {model} (not simulated yet)")));
            return Ok(None);
        }
    }))
}

/// Hands out the next index of a kind of sensor, if the model has that many.
fn next_index(count: &mut usize, available: usize) -> Option<usize> {
    (*count < available).then(|| {
        *count += 1;
        *count - 1
    })
}
