//! The bodies mounted on robots (a laser's head, a gripper's paddles) as boxes a ranger meets:
//! placed with the robot's sine and cosine taken once for the step, and their cells on the
//! raster drawn once for every scan of the step (the robots' index draws them).

use std::sync::Arc;

use super::{NO_BODY, NearbyBoxes, SolidBox, taken_in};
use crate::sim::BodyIndex;
use crate::sim::Simulation;

impl<'a> NearbyBoxes<'a> {
    /// Were the robots asked of `index` (or of none)?
    fn same_index(&self, index: &Arc<BodyIndex>) -> bool {
        self.index
            .as_ref()
            .is_none_or(|own| Arc::ptr_eq(own, index))
    }

    /// With the bodies mounted on every robot but `except` within `reach` of `(x, y)` (what
    /// rangers meet; the other sensors and collisions know only the robots' own bodies).
    pub fn with_mounted(
        mut self,
        sim: &'a Simulation,
        except: Option<usize>,
        (x, y): (f64, f64),
        reach: f64,
    ) -> Self {
        let index = sim.body_index();
        let near = match self.asked.take() {
            // The same question of the same index: the same robots.
            Some((asked, near)) if asked == (x, y, reach) && self.same_index(&index) => near,
            _ => {
                let mut near = Vec::new();
                index.near(x, y, reach, &mut near);
                near
            }
        };
        // The mounted bodies' cells drawn by the index the robots were asked of.
        let same = self.same_index(&index);
        for i in near.into_iter().filter(|&i| Some(i) != except) {
            let spec = &sim.world.robots[i];
            for (k, body) in spec.mounted_bodies.iter().enumerate() {
                // Placed once for every scan by the index.
                let number = index.mounted_body(i, k);
                let place = index.place(number);
                if !taken_in(&place, (x, y), reach, self.facing) {
                    continue;
                }
                self.boxes.push(SolidBox {
                    x: place.x,
                    y: place.y,
                    sin: place.sin,
                    cos: place.cos,
                    half_length: body.size[0] / 2.0,
                    half_width: body.size[1] / 2.0,
                    radius: place.radius,
                    height: body.bottom + body.size[2],
                    bottom: body.bottom,
                    color: spec.color,
                    ranger_return: body.ranger_return,
                    shape: &body.shape,
                    slices: &[],
                    resolution: 0.0,
                    body: u32::try_from(number)
                        .ok()
                        .filter(|_| same)
                        .unwrap_or(NO_BODY),
                });
            }
        }
        if self.index.is_none() {
            self.index = Some(index);
        }
        self
    }
}
