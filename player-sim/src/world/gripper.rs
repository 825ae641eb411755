//! Stage's `gripper` model as a world file writes it: a body of `size` (0.2 × 0.3 × 0.2 m by
//! default) with two paddles, `paddle_size` as proportions of the body (0.66, 0.1, 0.4),
//! starting `paddle_state [ "open" | "closed" … ]`, closing by itself on a broken beam when
//! `autosnatch 1`.

use super::Pose;
use super::models::Model;
use super::properties::{err, numbers, opt_number, size_of};
use crate::worldfile::WorldFileError;

const DEFAULT_SIZE: [f64; 3] = [0.2, 0.3, 0.2];
const DEFAULT_PADDLE_SIZE: [f64; 3] = [0.66, 0.1, 0.4];

/// A gripper on a robot.
#[derive(Debug, Clone, PartialEq)]
pub struct GripperSpec {
    /// On the robot.
    pub pose: Pose,
    /// Length (x), width (y), height, m.
    pub size: [f64; 3],
    /// Proportions of `size`.
    pub paddle_size: [f64; 3],
    /// Starts with its paddles closed.
    pub closed: bool,
    pub autosnatch: bool,
}

pub(super) fn gripper(model: &Model, pose: Pose) -> Result<GripperSpec, WorldFileError> {
    let paddle_size = match model.get("paddle_size") {
        None => DEFAULT_PADDLE_SIZE,
        Some(p) => {
            let n = numbers(Some(p), 3, &p.pos)?;
            if !n[..3].iter().all(|v| *v > 0.0 && *v <= 1.0) || n[1] >= 0.5 {
                return Err(err(
                    &p.pos,
                    "paddle_size must be proportions of the body in (0, 1], the width below 0.5",
                ));
            }
            [n[0], n[1], n[2]]
        }
    };
    let closed = match model.get("paddle_state") {
        None => false,
        Some(p) => match p.value.as_str().or_else(|| match &p.value {
            crate::worldfile::Value::List(items) => items.first().and_then(|v| v.as_str()),
            _ => None,
        }) {
            Some("closed") => true,
            Some("open") => false,
            _ => {
                return Err(err(
                    &p.pos,
                    "paddle_state must start with \"open\" or \"closed\"",
                ));
            }
        },
    };
    Ok(GripperSpec {
        pose,
        size: size_of(model, DEFAULT_SIZE)?,
        paddle_size,
        closed,
        autosnatch: opt_number(model, "autosnatch")?.is_some_and(|v| v != 0.0),
    })
}
