//! Where each robot's body and each body mounted on a robot lies for one set of poses, with
//! its frame's sine and cosine and its bounding circle: worked out once a step by the robots'
//! index, not by every scan that takes the body in (each scan placed every body within its
//! sensor's range anew: in the cave, all 200 of them a scan, a twelfth of its profile).

use super::RobotState;
use super::body_pose::body_at;
use super::box_cells::{Placed, cell_margin};
use crate::world::{BoxObstacle, Polygon, Pose, World};

/// A body's place: its centre, its frame's sine and cosine, and its bounding circle's radius
/// widened by its cells' margin on the world's raster (`box_cells::cell_margin`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Place {
    pub x: f64,
    pub y: f64,
    pub sin: f64,
    pub cos: f64,
    pub radius: f64,
}

impl Place {
    /// Does the body's bounding circle come within `reach` of `(x, y)`? Squares, not `hypot`:
    /// every scan asks this of the bodies around it.
    #[inline]
    pub(super) fn within(&self, (x, y): (f64, f64), reach: f64) -> bool {
        let (ex, ey) = (self.x - x, self.y - y);
        let within = reach + self.radius;
        within >= 0.0 && ex * ex + ey * ey <= within * within
    }

    /// The body of `size` and blocks `shape` placed here.
    pub(super) fn placed<'a>(&self, size: [f64; 3], shape: &'a [Polygon]) -> Placed<'a> {
        Placed {
            x: self.x,
            y: self.y,
            sin: self.sin,
            cos: self.cos,
            half_length: size[0] / 2.0,
            half_width: size[1] / 2.0,
            shape,
        }
    }
}

/// Where obstacle `o` lies (placed by every scan: obstacles are few, and a gripper may move
/// one while the robots stand).
pub(super) fn obstacle_place(o: &BoxObstacle, resolution: f64) -> Place {
    let body = body_at(o.pose, o.origin);
    let (sin, cos) = body.a.sin_cos();
    Place {
        x: body.x,
        y: body.y,
        sin,
        cos,
        radius: bounding_radius(o.size, resolution),
    }
}

/// The radius of a box of `size`'s bounding circle, widened by its cells' margin on a raster
/// of `resolution`.
pub(super) fn bounding_radius(size: [f64; 3], resolution: f64) -> f64 {
    (size[0] * size[0] + size[1] * size[1]).sqrt() / 2.0 + cell_margin(resolution)
}

/// Each robot's body, then each robot's mounted bodies in turn, placed: robot `i`'s heading
/// and body `(sin, cos)` are `trig[i]`.
pub(super) fn places(world: &World, robots: &[RobotState], trig: &[[(f64, f64); 2]]) -> Vec<Place> {
    let resolution = world.resolution;
    let bodies = robots
        .iter()
        .zip(&world.robots)
        .zip(trig)
        .map(|((state, spec), t)| {
            let body = body_at(state.pose, spec.origin);
            let (sin, cos) = t[1];
            Place {
                x: body.x,
                y: body.y,
                sin,
                cos,
                radius: bounding_radius(spec.size, resolution),
            }
        });
    let mounted = robots
        .iter()
        .zip(&world.robots)
        .zip(trig)
        .flat_map(|((state, spec), t)| {
            let (s, c) = t[0];
            let p = state.pose;
            spec.mounted_bodies.iter().map(move |body| {
                let pose = Pose {
                    x: p.x + c * body.pose.x - s * body.pose.y,
                    y: p.y + s * body.pose.x + c * body.pose.y,
                    a: p.a + body.pose.a,
                };
                let (sin, cos) = if body.pose.a == 0.0 {
                    (s, c)
                } else {
                    pose.a.sin_cos()
                };
                Place {
                    x: pose.x,
                    y: pose.y,
                    sin,
                    cos,
                    radius: bounding_radius(body.size, resolution),
                }
            })
        });
    bodies.chain(mounted).collect()
}
