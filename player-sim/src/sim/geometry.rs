//! Rays against oriented boxes, and box overlap: what robots and obstacles are to the
//! simulator.

use super::box_cells::{Placed, RayScene, cell_margin};
use super::shapes::{outlines_overlap, ray_into_polygons};
use crate::world::{Polygon, Pose, placed};

/// A box on the ground: centre pose and full length (x) and width (y), and the blocks drawn
/// inside it, if any (then they, not the whole box, are what is solid).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroundBox<'a> {
    pub pose: Pose,
    pub length: f64,
    pub width: f64,
    /// In the box's frame; empty for a plain box.
    pub shape: &'a [Polygon],
}

impl GroundBox<'_> {
    /// `(x, y)` in the box's own frame.
    fn local_point(&self, x: f64, y: f64) -> (f64, f64) {
        let (s, c) = self.pose.a.sin_cos();
        let (dx, dy) = (x - self.pose.x, y - self.pose.y);
        (c * dx + s * dy, -s * dx + c * dy)
    }

    pub fn contains(&self, x: f64, y: f64) -> bool {
        let (lx, ly) = self.local_point(x, y);
        lx.abs() <= self.length / 2.0 && ly.abs() <= self.width / 2.0
    }

    /// Distance along the ray from `(x, y)` at `angle` to the box, if it is hit ahead.
    pub fn raycast(&self, x: f64, y: f64, angle: f64) -> Option<f64> {
        let (ox, oy) = self.local_point(x, y);
        let a = angle - self.pose.a;
        let (dx, dy) = (a.cos(), a.sin());
        let hit = slab_hit(ox, oy, dx, dy, self.length / 2.0, self.width / 2.0);
        if self.shape.is_empty() {
            return hit;
        }
        hit.and_then(|_| ray_into_polygons(self.shape, ox, oy, dx, dy))
    }

    /// Distance along the ray from `(x, y)` at `angle` to the box's cells on a raster of
    /// `resolution`, as rangers meet it (`sim/box_cells.rs`); exactly where the box is too
    /// large for a raster.
    pub fn raycast_cells(&self, resolution: f64, x: f64, y: f64, angle: f64) -> Option<f64> {
        let (dy, dx) = angle.sin_cos();
        self.raycast_cells_in(resolution, (x, y), (angle, (dx, dy)), None)
    }

    /// [`GroundBox::raycast_cells`] along the unit direction `(dx, dy)` (at `angle`), on the
    /// path Stage takes for a sensor in `scene`.
    pub(super) fn raycast_cells_in(
        &self,
        resolution: f64,
        (x, y): (f64, f64),
        (angle, (dx, dy)): (f64, (f64, f64)),
        scene: Option<&RayScene>,
    ) -> Option<f64> {
        let (sin, cos) = self.pose.a.sin_cos();
        let placed = Placed {
            x: self.pose.x,
            y: self.pose.y,
            sin,
            cos,
            half_length: self.length / 2.0,
            half_width: self.width / 2.0,
            shape: self.shape,
        };
        let beyond = (self.pose.x - x) * dx
            + (self.pose.y - y) * dy
            + self.bounding_radius()
            + cell_margin(resolution);
        placed
            .cast_cells(resolution, (x, y), (dx, dy), beyond.max(0.0), scene)
            .unwrap_or_else(|| self.raycast(x, y, angle))
    }

    /// The solid outline in world coordinates: the blocks, or the box's four corners.
    fn world_outline(&self) -> Vec<Polygon> {
        if self.shape.is_empty() {
            return vec![
                self.outline()[..4]
                    .to_vec()
                    .into_iter()
                    .map(|(x, y)| [x, y])
                    .collect(),
            ];
        }
        self.shape.iter().map(|p| placed(p, self.pose)).collect()
    }

    /// The blocks' corners and edge midpoints in world coordinates (none for a plain box):
    /// what is tested against the floorplan's walls instead of [`Self::outline`].
    pub fn shape_points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        let (s, c) = self.pose.a.sin_cos();
        let at = move |[lx, ly]: [f64; 2]| {
            (self.pose.x + c * lx - s * ly, self.pose.y + s * lx + c * ly)
        };
        self.shape.iter().flat_map(move |polygon| {
            (0..polygon.len()).flat_map(move |i| {
                let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
                [at(a), at([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0])]
            })
        })
    }

    /// Radius of the circle around the centre that holds the whole box.
    pub fn bounding_radius(&self) -> f64 {
        self.length.hypot(self.width) / 2.0
    }

    /// The four corners and four edge midpoints, for overlap tests.
    pub fn outline(&self) -> [(f64, f64); 8] {
        let (s, c) = self.pose.a.sin_cos();
        let (hx, hy) = (self.length / 2.0, self.width / 2.0);
        let at = |lx: f64, ly: f64| (self.pose.x + c * lx - s * ly, self.pose.y + s * lx + c * ly);
        [
            at(hx, hy),
            at(-hx, hy),
            at(-hx, -hy),
            at(hx, -hy),
            at(hx, 0.0),
            at(-hx, 0.0),
            at(0.0, hy),
            at(0.0, -hy),
        ]
    }

    /// Do the boxes overlap? (Outline points inside the other, either way: exact for the
    /// robot-sized boxes simulated here.)
    /// With blocks on either side, their polygons are tested exactly.
    pub fn overlaps(&self, other: &GroundBox) -> bool {
        if !(self.shape.is_empty() && other.shape.is_empty()) {
            return outlines_overlap(&self.world_outline(), &other.world_outline());
        }
        self.outline().iter().any(|&(x, y)| other.contains(x, y))
            || other.outline().iter().any(|&(x, y)| self.contains(x, y))
    }
}

/// Where a ray from `(ox, oy)` along the unit `(dx, dy)` enters the axis-aligned box of half
/// sizes `hx`, `hy` around the origin (0 if it starts inside), if it does ahead.
pub(crate) fn slab_hit(ox: f64, oy: f64, dx: f64, dy: f64, hx: f64, hy: f64) -> Option<f64> {
    let slab = |o: f64, d: f64, h: f64| -> (f64, f64) {
        if d.abs() < 1e-12 {
            if o.abs() <= h {
                (f64::NEG_INFINITY, f64::INFINITY)
            } else {
                (f64::INFINITY, f64::NEG_INFINITY)
            }
        } else {
            let (t1, t2) = ((-h - o) / d, (h - o) / d);
            (t1.min(t2), t1.max(t2))
        }
    };
    let (nx, fx) = slab(ox, dx, hx);
    let (ny, fy) = slab(oy, dy, hy);
    let (near, far) = (nx.max(ny), fx.min(fy));
    (far >= near && far >= 0.0).then_some(near.max(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rays_hit_rotated_boxes_from_outside_and_inside() {
        let b = GroundBox {
            pose: Pose {
                x: 3.0,
                y: 0.0,
                a: std::f64::consts::FRAC_PI_4,
            },
            length: 1.0,
            width: 1.0,
            shape: &[],
        };
        let hit = b.raycast(0.0, 0.0, 0.0).unwrap();
        assert!(
            (hit - (3.0 - std::f64::consts::SQRT_2 / 2.0)).abs() < 1e-9,
            "{hit}"
        );
        assert!(b.raycast(0.0, 0.0, std::f64::consts::PI).is_none());
        assert_eq!(b.raycast(3.0, 0.0, 1.0), Some(0.0));
        let c = GroundBox {
            pose: Pose {
                x: 3.6,
                y: 0.0,
                a: 0.0,
            },
            length: 0.4,
            width: 0.4,
            shape: &[],
        };
        assert!(b.overlaps(&c));
        let d = GroundBox {
            pose: Pose {
                x: 5.0,
                y: 0.0,
                a: 0.0,
            },
            length: 0.4,
            width: 0.4,
            shape: &[],
        };
        assert!(!b.overlaps(&d));
    }
}
