//! Reading model properties with Stage 4's units and conventions (`pose [x y z a]` with `a` in
//! degrees, colours by name or `color_rgba`), each error naming the property and where it is.

use super::Pose;
use super::colors;
use super::models::Model;
use crate::worldfile::{Pos, Property, WorldFileError};

/// Properties each kind of model reads; anything else is reported as ignored.
pub(super) const READ: &[&str] = &[
    "name",
    "pose",
    "joules",
    "joules_capacity",
    "kjoules",
    "kjoules_capacity",
    "watts",
    "mass",
    "size",
    "color",
    "color_rgba",
    "drive",
    "velocity_bounds",
    "localization",
    "localization_origin",
    "odom_error",
    // Stage 4.3 reads it but does not ramp a velocity command by it: its drives end where
    // player-sim's do without it (golden/stage/*-drives.jsonl, to the millimetre).
    "acceleration_bounds",
    "bitmap",
    "boundary",
    "origin",
    "fiducial_return",
    "obstacle_return",
    "ranger_return",
    "range_min",
    "range_max",
    "range_max_id",
    "fov",
    "range",
    "resolution",
    "ctrl",
    "gripper_return",
    "colors",
    "colors_count",
    "image",
    "pan",
    "paddle_size",
    "paddle_state",
    "autosnatch",
    "path",
    "wander",
    "speed",
    "leg_size",
];

pub(super) fn err(pos: &Pos, message: impl Into<String>) -> WorldFileError {
    WorldFileError::at(&pos.file, pos.line, pos.col, message)
}

pub(super) fn number(p: &Property) -> Result<f64, WorldFileError> {
    p.value
        .as_f64()
        .ok_or_else(|| err(&p.pos, format!("{} must be a number", p.name)))
}

pub(super) fn opt_number(m: &Model, name: &str) -> Result<Option<f64>, WorldFileError> {
    m.get(name).map(number).transpose()
}

pub(super) fn string(p: &Property) -> Result<&str, WorldFileError> {
    p.value
        .as_str()
        .ok_or_else(|| err(&p.pos, format!("{} must be a \"string\"", p.name)))
}

pub(super) fn numbers(
    p: Option<&Property>,
    at_least: usize,
    pos: &Pos,
) -> Result<Vec<f64>, WorldFileError> {
    let Some(p) = p else {
        return Err(err(pos, format!("missing a list of {at_least} numbers")));
    };
    match p.value.numbers() {
        Some(n) if n.len() >= at_least => Ok(n),
        _ => Err(err(
            &p.pos,
            format!("{} must be a list of at least {at_least} numbers", p.name),
        )),
    }
}

/// `pose [x y z a]` with `a` in degrees (Stage 4); `[x y a]` is accepted too.
pub(super) fn pose_from(p: &Property) -> Result<Pose, WorldFileError> {
    let n = numbers(Some(p), 3, &p.pos)?;
    let a = if n.len() >= 4 { n[3] } else { n[2] };
    Ok(Pose {
        x: n[0],
        y: n[1],
        a: a.to_radians(),
    })
}

pub(super) fn pose_of(m: &Model) -> Result<Pose, WorldFileError> {
    m.get("pose")
        .map(pose_from)
        .transpose()
        .map(Option::unwrap_or_default)
}

/// `origin [x y z a]`: where a model's body lies from its pose (none by default).
pub(super) fn origin_of(m: &Model) -> Result<Pose, WorldFileError> {
    m.get("origin")
        .map(pose_from)
        .transpose()
        .map(Option::unwrap_or_default)
}

/// A model's `size [x y z]` (z from `default` when not given); a negative or endless one is
/// refused where it is written (no body has one: collisions and rays would turn it inside out).
pub(super) fn size_of(m: &Model, default: [f64; 3]) -> Result<[f64; 3], WorldFileError> {
    let Some(p) = m.get("size") else {
        return Ok(default);
    };
    let n = numbers(Some(p), 2, &p.pos)?;
    let size = [n[0], n[1], n.get(2).copied().unwrap_or(default[2])];
    if !size.iter().all(|s| s.is_finite() && *s >= 0.0) {
        return Err(err(
            &p.pos,
            format!(
                "size [{} {} {}] must be finite and not negative",
                size[0], size[1], size[2]
            ),
        ));
    }
    Ok(size)
}

pub(super) fn name_of(m: &Model, default: &str) -> String {
    m.get("name")
        .and_then(|p| p.value.as_str())
        .unwrap_or(default)
        .to_string()
}

pub(super) fn color_of(m: &Model) -> Result<[u8; 3], WorldFileError> {
    if let Some(p) = m.get("color_rgba") {
        let n = numbers(Some(p), 3, &p.pos)?;
        let c = |v: f64| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        return Ok([c(n[0]), c(n[1]), c(n[2])]);
    }
    match m.get("color") {
        None => Ok([200, 200, 200]),
        Some(p) => {
            let name = string(p)?;
            if name.eq_ignore_ascii_case("random") {
                return Ok(random_color(&m.pos));
            }
            colors::by_name(name).ok_or_else(|| err(&p.pos, format!("unknown colour {name:?}")))
        }
    }
}

/// Stage's `color "random"`: a colour of its own for each model, here drawn from where the
/// model is written, so that runs stay the same.
fn random_color(pos: &Pos) -> [u8; 3] {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in pos
        .file
        .bytes()
        .chain(pos.line.to_le_bytes())
        .chain(pos.col.to_le_bytes())
    {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    // Bright enough to see against the dark floor: each channel 64 to 255.
    [h, h >> 8, h >> 16].map(|c| 64 + (c as u8) % 192)
}

/// Stage's `ranger_return`: the reflectance rangers report for this model (1 unless set);
/// negative = invisible to rangers.
pub(super) fn ranger_return_of(m: &Model) -> Result<f64, WorldFileError> {
    Ok(opt_number(m, "ranger_return")?.unwrap_or(1.0))
}

pub(super) fn fiducial_of(m: &Model) -> Result<Option<i32>, WorldFileError> {
    Ok(opt_number(m, "fiducial_return")?
        .map(|v| v as i32)
        .filter(|&v| v != 0))
}
