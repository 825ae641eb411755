//! A scan's boxes listed once: the boxes about a sensor within its whole range, every robot's
//! among them (its own too: Stage walks the regions they lie in, `scan_caster::ray_scene`),
//! narrowed to those its beams may meet — not its own robot's, within the farthest wall its
//! beams met — instead of asked of the robots' index and placed a second time.

use super::{NearbyBoxes, Owner};
use crate::sim::Simulation;

impl<'a> NearbyBoxes<'a> {
    /// The boxes [`NearbyBoxes::around`] and [`NearbyBoxes::with_mounted`] would give with
    /// `except` and `reach` (at most the reach these were listed for, with no robot left out),
    /// in the same order: the same boxes, by the same test.
    pub(in crate::sim) fn narrowed(
        &self,
        sim: &Simulation,
        except: usize,
        (x, y): (f64, f64),
        reach: f64,
    ) -> NearbyBoxes<'a> {
        let except = Some(except);
        let kept = self.boxes.iter().filter(|b| {
            let theirs = match b.owner {
                Owner::Robot(i) => Some(i as usize) == except,
                Owner::Obstacle(k) => sim.holds(except, k as usize),
            };
            let (ex, ey) = (b.x - x, b.y - y);
            let within = reach + b.radius;
            !theirs && within >= 0.0 && ex * ex + ey * ey <= within * within
        });
        NearbyBoxes {
            boxes: kept.copied().collect(),
            cells: Vec::new(),
            index: self.index.clone(),
            asked: None,
            scene: None,
        }
    }
}
