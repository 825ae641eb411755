//! A ray's way across regions where nothing is marked: Stage does not walk their cells but
//! moves the ray's point along its line to where it crosses into the next region
//! (`raster_walk.rs`).

use super::{Ray, cell_of, region_of};

/// Where a ray crossing empty regions crosses into the next one, across a column of regions
/// and across a row, and how far (in Stage's sum of the moves along both axes) each lies.
pub(super) struct Crossings {
    across_x: (f64, f64),
    across_y: (f64, f64),
    to_x: f64,
    to_y: f64,
    /// From one crossing to the next of each kind, and its length.
    jump_x: (f64, f64),
    jump_y: (f64, f64),
    length_x: f64,
    length_y: f64,
}

impl Crossings {
    /// The crossings ahead of `at`, on the line through it along `ray`.
    pub(super) fn new(ray: &Ray, at: (f64, f64)) -> Crossings {
        let (sx, sy) = (ray.step.0 as f64, ray.step.1 as f64);
        let tan = ray.sin / ray.cos;
        let corner = |v: f64| (region_of(cell_of(v)) * 32) as f64;
        // Heading west or south, Stage aims a cell past the region's edge.
        let towards = |v: f64, s: f64| {
            if s < 0.0 {
                corner(v) - v - 1.0
            } else {
                corner(v) + 32.0 - v
            }
        };
        let x_move = towards(at.0, sx);
        let y_move = towards(at.1, sy);
        let (x_rise, y_run) = (x_move * tan, y_move / tan);
        let jump_x = (sx * 32.0, sx * 32.0 * tan);
        let jump_y = (sy * 32.0 / tan, sy * 32.0);
        Crossings {
            across_x: (at.0 + x_move, at.1 + x_rise),
            across_y: (at.0 + y_run, at.1 + y_move),
            to_x: x_move.abs() + x_rise.abs(),
            to_y: y_run.abs() + y_move.abs(),
            jump_x,
            jump_y,
            length_x: jump_x.0.abs() + jump_x.1.abs(),
            length_y: jump_y.0.abs() + jump_y.1.abs(),
        }
    }

    /// The nearer crossing and how far it is, the next of its kind set up; `None` when neither
    /// can be reached.
    pub(super) fn next(&mut self) -> Option<((f64, f64), f64)> {
        if self.to_x < self.to_y {
            let reached = (self.across_x, self.to_x);
            self.across_x = (
                self.across_x.0 + self.jump_x.0,
                self.across_x.1 + self.jump_x.1,
            );
            self.to_y -= self.to_x;
            self.to_x = self.length_x;
            (reached.1 > 0.0).then_some(reached)
        } else {
            let reached = (self.across_y, self.to_y);
            self.across_y = (
                self.across_y.0 + self.jump_y.0,
                self.across_y.1 + self.jump_y.1,
            );
            self.to_x -= self.to_y;
            self.to_y = self.length_y;
            (reached.1 > 0.0).then_some(reached)
        }
    }
}
