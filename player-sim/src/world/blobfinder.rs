//! Stage's `blobfinder` model as a world file writes it: an image of `image [w h]` pixels over
//! `fov` (degrees), turned by `pan`, seeing up to `range`, tracking the colours of `colors`
//! (every colour when none are given). Stage's defaults: 80 × 60 pixels, 60°, 12 m.

use super::colors;
use super::models::Model;
use super::properties::{err, number, numbers, opt_number};
use super::{Pose, World};
use crate::worldfile::{Value, WorldFileError};

const DEFAULT_RANGE: f64 = 12.0;
const DEFAULT_FOV_DEGREES: f64 = 60.0;
const DEFAULT_IMAGE: (u32, u32) = (80, 60);

/// A blobfinder on a robot.
#[derive(Debug, Clone, PartialEq)]
pub struct BlobfinderSpec {
    /// On the robot.
    pub pose: Pose,
    pub range: f64,
    /// Radians.
    pub fov: f64,
    /// Radians, added to the mount's heading.
    pub pan: f64,
    /// Pixels: one ray per column, as Stage casts them.
    pub width: u32,
    pub height: u32,
    /// The colours tracked; empty: every colour.
    pub colors: Vec<[u8; 3]>,
}

impl World {
    /// Reads a blobfinder mounted at `pose`. Like Stage, `colors` is read only as far as
    /// `colors_count` says (0 unless given), which is reported when it leaves colours out.
    pub(super) fn blobfinder(
        &mut self,
        model: &Model,
        pose: Pose,
    ) -> Result<BlobfinderSpec, WorldFileError> {
        let (width, height) = match model.get("image") {
            None => DEFAULT_IMAGE,
            Some(p) => {
                let n = numbers(Some(p), 2, &p.pos)?;
                if !(n[0] >= 1.0
                    && n[1] >= 1.0
                    && n[0] <= f64::from(u16::MAX)
                    && n[1] <= f64::from(u16::MAX))
                {
                    return Err(err(
                        &p.pos,
                        "image must be [width height], 1 to 65535 pixels each",
                    ));
                }
                (n[0] as u32, n[1] as u32)
            }
        };
        let fov = opt_number(model, "fov")?.unwrap_or(DEFAULT_FOV_DEGREES);
        if !(fov > 0.0 && fov <= 360.0) {
            let at = &model
                .get("fov")
                .expect("only a given fov is out of range")
                .pos;
            return Err(err(at, "fov must be degrees in (0, 360]"));
        }
        let mut spec = BlobfinderSpec {
            pose,
            range: opt_number(model, "range")?.unwrap_or(DEFAULT_RANGE),
            fov: fov.to_radians(),
            pan: opt_number(model, "pan")?.unwrap_or(0.0).to_radians(),
            width,
            height,
            colors: Vec::new(),
        };
        if let Some(p) = model.get("colors") {
            let count = model
                .get("colors_count")
                .map(number)
                .transpose()?
                .unwrap_or(0.0);
            let names: Vec<&Value> = match &p.value {
                Value::List(items) => items.iter().collect(),
                single => vec![single],
            };
            for value in names.iter().take(count.max(0.0) as usize) {
                let name = value
                    .as_str()
                    .ok_or_else(|| err(&p.pos, "colors must be a list of colour names"))?;
                let rgb = colors::by_name(name)
                    .ok_or_else(|| err(&p.pos, format!("unknown colour {name:?}")))?;
                spec.colors.push(rgb);
            }
            if names.len() > spec.colors.len() {
                self.ignore(
                    &format!(
                        "colors beyond colors_count {} (Stage reads no more; with none it tracks \
                     every colour)",
                        spec.colors.len()
                    ),
                    &p.pos,
                );
            }
        }
        Ok(spec)
    }
}
