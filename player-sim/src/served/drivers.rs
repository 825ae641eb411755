//! The drivers of a .cfg besides `stage`: converters of a Stage device (`rangertolaser`,
//! `cameracompress`), `passthrough` of a device another .cfg provides, and `mapfile`. The
//! navigation drivers (`amcl`, `fakelocalize`, `wavefront`) are read in `navigation`.

use std::sync::Arc;

use player_proto::wire::Interface;

use super::{DriverBlock, ServedDevice, Source};
use crate::mapfile::{GridMap, MapFileSettings, SharedMap};
use crate::worldfile::{Property, WorldFileError};

/// The drivers player-sim serves devices of (besides `stage`).
const SERVED: &[&str] = &[
    "rangertolaser",
    "rangertosonar",
    "cameracompress",
    "passthrough",
    "mapfile",
    "amcl",
    "fakelocalize",
    "wavefront",
    "sentences",
    "festival",
];

/// "ignored: …" for a driver player-sim does not serve at all, so that its lines are read
/// and reported but never refused.
pub(super) fn not_served(driver: &DriverBlock) -> Option<String> {
    let name = driver.name.as_str();
    if name == "stage" || SERVED.contains(&name) {
        return None;
    }
    Some(driver.ignored(&format!("driver {name:?}")))
}

/// The source of a device the block provides, or `None` when it is ignored.
pub(super) fn source(
    driver: &DriverBlock,
    served: &[ServedDevice],
    interf: Interface,
    ignored: &mut Vec<String>,
) -> Result<Option<Source>, WorldFileError> {
    let name = driver.name.as_str();
    Ok(Some(match (name, interf) {
        ("rangertolaser" | "rangertosonar", _) => {
            if driver.requires.is_empty() {
                return Err(driver.error(format!("{name} needs requires [ \"port:ranger:N\" ]")));
            }
            let from = driver.required(served).ok_or_else(|| {
                driver.error(format!(
                    "{name} requires a ranger no driver provides before it"
                ))
            })?;
            let Source::Ranger { robot, ranger } = from.source else {
                return Err(driver.error(format!("{name} must require a ranger")));
            };
            if name == "rangertolaser" {
                Source::Laser { robot, ranger }
            } else {
                Source::Sonar { robot, ranger }
            }
        }
        ("cameracompress", Interface::CAMERA) => {
            let from = driver.required(served).ok_or_else(|| {
                driver.error(format!(
                    "{name} requires a camera no driver provides before it"
                ))
            })?;
            let Source::Camera { robot, camera, .. } = from.source else {
                return Err(driver.error(format!("{name} must require a camera")));
            };
            Source::Camera {
                robot,
                camera,
                jpeg_quality: Some(jpeg_quality(driver)?),
            }
        }
        ("passthrough", _) => passthrough(driver, served, interf)?,
        ("mapfile", Interface::MAP) => Source::Map(SharedMap(Arc::new(map(driver)?))),
        (_, other) => {
            let note = driver.ignored(&format!("{other} of driver {name:?}"));
            if !ignored.contains(&note) {
                ignored.push(note);
            }
            return Ok(None);
        }
    }))
}

/// `passthrough`: the very device it requires, which an earlier .cfg must provide (player-sim
/// serves both halves of a two-process setup itself).
fn passthrough(
    driver: &DriverBlock,
    served: &[ServedDevice],
    interf: Interface,
) -> Result<Source, WorldFileError> {
    let wanted = driver.requires.first().map_or("nothing", String::as_str);
    let from = driver.required(served).ok_or_else(|| {
        driver.error(format!(
            "passthrough requires {wanted}, which no .cfg read before this one provides \
             (give the Stage .cfg first)"
        ))
    })?;
    if from.interf != interf {
        return Err(driver.error(format!(
            "passthrough provides {interf} but requires {wanted}, a {}",
            from.interf
        )));
    }
    Ok(from.source.clone())
}

/// `cameracompress`'s `image_quality` (0–1) as a JPEG quality.
fn jpeg_quality(driver: &DriverBlock) -> Result<u8, WorldFileError> {
    match driver.block.get("image_quality") {
        None => Ok(crate::camera_frames::DEFAULT_JPEG_QUALITY),
        Some(p) => match p.value.as_f64() {
            Some(q) if q > 0.0 && q <= 1.0 => Ok((q * 100.0).round().max(1.0) as u8),
            _ => Err(at(p, "image_quality must be a number in (0, 1]")),
        },
    }
}

pub(super) fn at(p: &Property, message: impl Into<String>) -> WorldFileError {
    WorldFileError::at(&p.pos.file, p.pos.line, p.pos.col, message)
}

/// `mapfile`'s map: `filename` (relative to the .cfg), `resolution` (required, positive),
/// `negate`, `origin [x y]` (the angle is ignored, as Player ignores it).
fn map(driver: &DriverBlock) -> Result<GridMap, WorldFileError> {
    let block = driver.block;
    let filename = block
        .get("filename")
        .ok_or_else(|| driver.error("mapfile needs a filename"))?;
    let file = filename
        .value
        .as_str()
        .ok_or_else(|| at(filename, "filename must be a \"string\""))?;
    let resolution = match block.get("resolution") {
        None => return Err(driver.error("mapfile needs a resolution (m per pixel)")),
        Some(p) => p
            .value
            .as_f64()
            .filter(|r| r.is_finite() && *r > 0.0)
            .ok_or_else(|| at(p, "resolution must be a positive number of metres"))?,
    };
    let negate = match block.get("negate") {
        None => false,
        Some(p) => {
            p.value
                .as_f64()
                .ok_or_else(|| at(p, "negate must be 0 or 1"))?
                != 0.0
        }
    };
    let origin = match block.get("origin") {
        None => None,
        Some(p) => match p.value.numbers() {
            Some(n) if n.len() >= 2 => Some((n[0], n[1])),
            _ => return Err(at(p, "origin must be [x y] or [x y angle]")),
        },
    };
    let settings = MapFileSettings {
        resolution,
        negate,
        origin,
    };
    GridMap::from_image(&driver.folder.join(file), &settings)
        .map_err(|e| at(filename, e.to_string()))
}
