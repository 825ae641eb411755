//! `person( … )`: a walking person, two legs a laser sees, so that a people detector has
//! something real to find. Not a Stage model (Stage has none): player-sim's own, written
//!
//! ```text
//! person( name "visitor" pose [ 1 2 0 0 ] path [ 1 2  4 2  4 5 ] speed 0.6 )
//! person( name "pupil" pose [ 0 0 0 0 ] wander 2.5 speed 0.4 )
//! ```
//!
//! `path` is a loop of way-points (x y pairs, m), walked in order and back to the first;
//! `wander R` instead picks way-points at random (from the world's seed) within R m of the
//! start, avoiding walls; neither: the person stands. `speed` in m/s (0.5). Each leg is a
//! box obstacle of `leg_size` (0.12 m) on a side, named "<name> left leg" and "<name> right
//! leg": rangers, cameras and robots meet them as any box; the person walks through robots.

use super::properties::{err, numbers, opt_number, pose_of};
use super::{BoxObstacle, Model, Pose, World};
use crate::worldfile::WorldFileError;

/// How far apart the legs stand across the walking direction, m.
pub const STANCE_WIDTH: f64 = 0.2;
const DEFAULT_LEG_SIZE: f64 = 0.12;
const DEFAULT_SPEED: f64 = 0.5;
/// A leg is as tall as this, m.
const LEG_HEIGHT: f64 = 0.9;
const TROUSERS: [u8; 3] = [60, 60, 120];

/// Where a person goes.
#[derive(Debug, Clone, PartialEq)]
pub enum Walk {
    Stand,
    /// A loop of way-points.
    Path(Vec<(f64, f64)>),
    /// Random way-points within this radius of the start.
    Wander(f64),
}

#[derive(Debug, Clone, PartialEq)]
pub struct PersonSpec {
    pub name: String,
    pub start: Pose,
    pub walk: Walk,
    /// m/s.
    pub speed: f64,
    /// The obstacles that are the left and right legs.
    pub legs: [usize; 2],
}

impl World {
    /// Reads a `person` and adds its legs to the obstacles.
    pub(super) fn person(&mut self, model: &Model) -> Result<(), WorldFileError> {
        let name = super::properties::name_of(model, &format!("person{}", self.people.len()));
        let start = pose_of(model)?;
        let speed = opt_number(model, "speed")?.unwrap_or(DEFAULT_SPEED);
        let leg_size = opt_number(model, "leg_size")?.unwrap_or(DEFAULT_LEG_SIZE);
        if !(speed.is_finite() && speed >= 0.0) {
            return Err(err(&model.pos, "a person's speed must be 0 or more m/s"));
        }
        if !(leg_size.is_finite() && leg_size > 0.0) {
            return Err(err(&model.pos, "a person's leg_size must be more than 0 m"));
        }
        let walk = match (model.get("path"), opt_number(model, "wander")?) {
            (Some(p), _) => {
                let n = numbers(Some(p), 2, &p.pos)?;
                if n.len() % 2 != 0 {
                    return Err(err(&p.pos, "path must be x y pairs"));
                }
                Walk::Path(n.chunks_exact(2).map(|c| (c[0], c[1])).collect())
            }
            (None, Some(radius)) if radius > 0.0 => Walk::Wander(radius),
            _ => Walk::Stand,
        };
        let mut legs = [0; 2];
        for (leg, side) in legs.iter_mut().zip(["left", "right"]) {
            *leg = self.obstacles.len();
            self.obstacles.push(BoxObstacle::plain(
                format!("{name} {side} leg"),
                start,
                [leg_size, leg_size, LEG_HEIGHT],
                TROUSERS,
            ));
        }
        self.people.push(PersonSpec {
            name,
            start,
            walk,
            speed,
            legs,
        });
        Ok(())
    }
}
