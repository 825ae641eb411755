//! One walk a beam through the walls and the bodies it may meet together, as Stage walks its
//! raster: each cell's free square is the smallest of the walls' and the bodies', and the first
//! solid cell on the path is what the beam meets. A beam walked the walls and then, from the
//! sensor again, each body its line passed near: a third of the cave's walks, each crossing
//! the regions the walls' walk had crossed.
//!
//! The distance is the walls' and the bodies' walks' least, cell for cell: the path does not
//! depend on what the cells hold (`raster_walk.rs`). What is met in the cell where the walk
//! stops is the last of the bodies solid there, else the wall; where a wall's cell and a
//! body's further along the path read the same distance (a step across the axis distances are
//! counted along), the first on the path is met, as in Stage.

use std::cell::Cell;

use super::box_cells::BoxCells;
use super::raster_walk::{Cells, Ray, RegionMap, walk};
use super::wall_raster::WallRaster;

/// What a joint walk met: the wall, or body `k` of those walked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Met {
    Wall,
    Body(usize),
}

/// The walls (where a beam may meet them) and the bodies' cells, read as one raster.
struct Joint<'a, T> {
    walls: Option<&'a WallRaster>,
    bodies: &'a [(&'a BoxCells, T)],
    /// The columns and rows the bodies' grids span (see [`Window`]).
    window: Window,
    /// Whose was the solid cell read last.
    met: Cell<Met>,
}

/// The columns and rows the bodies' grids span, each counted the way the ray steps along it.
/// A cell before the first of them along an axis has a free square of the bodies up to there,
/// a cell past the last along an axis an endless one; only a cell within both spans is read
/// from each body. Most of a beam's reads lie before or beside the bodies it passes near (the
/// bodies were a sixth of the cave's time, each read at every cell of a beam's walk).
#[derive(Clone, Copy)]
struct Window {
    sign: (i64, i64),
    near: (i64, i64),
    far: (i64, i64),
}

impl Window {
    fn of<T>(bodies: &[(&BoxCells, T)], ray: &Ray) -> Window {
        let sign = ray.steps();
        let mut near = (i64::MAX / 4, i64::MAX / 4);
        let mut far = (i64::MIN / 4, i64::MIN / 4);
        for (body, _) in bodies {
            let (columns, rows) = body.spans();
            let (x0, x1) = (sign.0 * columns.0, sign.0 * columns.1);
            let (y0, y1) = (sign.1 * rows.0, sign.1 * rows.1);
            near = (near.0.min(x0.min(x1)), near.1.min(y0.min(y1)));
            far = (far.0.max(x0.max(x1)), far.1.max(y0.max(y1)));
        }
        Window { sign, near, far }
    }

    /// The bodies' free square at cell `(x, y)` when the cell lies outside the window: up to
    /// its near edge along the axis where it lies before it, endless where it lies past it.
    #[inline]
    fn outside(&self, x: i64, y: i64) -> Option<u32> {
        let (a, b) = (self.sign.0 * x, self.sign.1 * y);
        if a > self.far.0 || b > self.far.1 {
            return Some(u32::MAX);
        }
        let free = (self.near.0 - a).max(self.near.1 - b);
        (free > 0).then(|| free.min(i64::from(u32::MAX)) as u32)
    }
}

impl<T> Cells for Joint<'_, T> {
    #[inline]
    fn ahead(&self, x: i64, y: i64, q: usize) -> u32 {
        let walls = self.walls.map_or(u32::MAX, |w| w.ahead(x, y, q));
        if let Some(bodies) = self.window.outside(x, y) {
            return walls.min(bodies);
        }
        let mut least = walls;
        // The last body solid here, as `k + 1` (0: none); chosen without branches.
        let mut solid = 0;
        for (k, (body, _)) in self.bodies.iter().enumerate() {
            let clear = body.ahead(x, y, q);
            solid = if clear == 0 { k + 1 } else { solid };
            least = least.min(clear);
        }
        if least == 0 {
            self.met.set(match solid {
                0 => Met::Wall,
                k => Met::Body(k - 1),
            });
        }
        least
    }
}

/// Distance along `ray` to the first cell of `walls` or `bodies` (each with what it is to the
/// caller) on Stage's path through `regions` (which hold the bodies' regions), within `stop`
/// metres, and what it met there.
pub(super) fn walk_joint<T>(
    walls: Option<&WallRaster>,
    bodies: &[(&BoxCells, T)],
    regions: &RegionMap,
    ray: &Ray,
    stop: f64,
) -> Option<(f64, Met)> {
    let joint = Joint {
        walls,
        bodies,
        window: Window::of(bodies, ray),
        met: Cell::new(Met::Wall),
    };
    walk(&joint, regions, ray, stop).map(|d| (d, joint.met.get()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::box_cells::{Placed, RayScene};
    use crate::sim::test_halls::{bordered, walled};
    use crate::sim::test_randoms::randoms;
    use crate::world::floor_i64;
    use std::f64::consts::TAU;

    /// A box of random size and heading centred on `(x, y)`.
    fn turned_box(x: f64, y: f64, next: &mut impl FnMut() -> f64) -> Placed<'static> {
        let turn = TAU * next();
        Placed {
            x,
            y,
            sin: turn.sin(),
            cos: turn.cos(),
            half_length: 0.1 + 0.3 * next(),
            half_width: 0.1 + 0.2 * next(),
            shape: &[],
        }
    }

    fn drawn(placed: &[Placed], resolution: f64) -> Vec<BoxCells> {
        placed
            .iter()
            .map(|p| BoxCells::of(p, resolution).expect("cells"))
            .collect()
    }

    /// A cell the bodies' window says lies outside it has no body's cell within the square it
    /// gives (endless: none within 30 cells): bodies of up to three turned boxes about the
    /// origin, rays every way from it, cells all about.
    #[test]
    fn a_cell_outside_the_window_sees_no_body_cell_in_its_square() {
        use crate::sim::raster_walk::quadrant;
        let mut next = randoms(0x3_7a11);
        let resolution = 0.05;
        let (mut outside, mut inside) = (0, 0);
        for k in 0..60 {
            let placed: Vec<Placed> = (0..1 + k % 3)
                .map(|_| {
                    let (x, y) = (3.0 * next() - 1.5, 3.0 * next() - 1.5);
                    turned_box(x, y, &mut next)
                })
                .collect();
            let cells = drawn(&placed, resolution);
            let refs: Vec<(&BoxCells, ())> = cells.iter().map(|c| (c, ())).collect();
            let (dy, dx) = (TAU * next()).sin_cos();
            let ray = Ray::new(1.0 / resolution, (0.0, 0.0), (dx, dy), 5.0).expect("ray");
            let window = Window::of(&refs, &ray);
            let (sx, sy) = ray.steps();
            let q = quadrant(sx as f64, sy as f64);
            for _ in 0..40 {
                let (x, y) = (
                    (120.0 * next() - 60.0) as i64,
                    (120.0 * next() - 60.0) as i64,
                );
                let Some(side) = window.outside(x, y) else {
                    inside += 1;
                    continue;
                };
                outside += 1;
                let side = i64::from(side.min(30));
                for (i, j) in (0..side).flat_map(|i| (0..side).map(move |j| (i, j))) {
                    let (c, r) = (x + sx * i, y + sy * j);
                    for body in &cells {
                        assert_ne!(body.ahead(c, r, q), 0, "{k}: ({x}, {y}) square {side}");
                    }
                }
            }
        }
        assert!(outside > 1000 && inside > 100, "{outside} {inside}");
    }

    /// One walk through walls and bodies meets what the walls' walk and each body's walk from
    /// the sensor meet, the nearest of them: random rays across a hall strewn with walls, with
    /// up to three turned bodies placed near each.
    #[test]
    fn one_walk_meets_the_nearest_of_the_walls_and_the_bodies() {
        let mut next = randoms(0x1_0147);
        let rows = bordered(80, 80, |_, _| next() < 0.02);
        let resolution = 0.05;
        let raster = WallRaster::of(&walled(&rows, 0.5, resolution)).expect("walls");
        let (mut bodies_met, mut walls_met) = (0, 0);
        for k in 0..3000 {
            let (x, y) = (38.0 * next() - 19.0, 38.0 * next() - 19.0);
            let (dy, dx) = (TAU * next()).sin_cos();
            let max = [2.0, 5.0, 8.0][k % 3];
            let placed: Vec<Placed> = (0..k % 4)
                .map(|_| {
                    let along = max * next();
                    let (bx, by) = (x + dx * along, y + dy * along);
                    turned_box(bx + 0.6 * next() - 0.3, by + 0.6 * next() - 0.3, &mut next)
                })
                .collect();
            let cells = drawn(&placed, resolution);
            let span = |v: f64, s: f64| floor_i64((v + s * max) / resolution) + 64 * s as i64;
            let mut regions =
                RegionMap::over((span(x, -1.0), span(y, -1.0)), (span(x, 1.0), span(y, 1.0)));
            regions.hold_all(raster.regions());
            for p in &placed {
                p.add_regions(resolution, &mut regions);
            }
            let scene = RayScene {
                range: max,
                regions: regions.into(),
            };
            let walls = (k % 5 != 0).then_some(&raster);
            let separately = walls
                .and_then(|w| w.cast_among(x, y, dx, dy, max, &scene.regions))
                .map(|d| (d, Met::Wall));
            let separately = cells.iter().enumerate().fold(separately, |best, (b, c)| {
                match c.cast_in(&scene, (x, y), (dx, dy), max) {
                    Some(d) if best.is_none_or(|(e, _)| d <= e) => Some((d, Met::Body(b))),
                    _ => best,
                }
            });
            let ray = Ray::new(1.0 / resolution, (x, y), (dx, dy), max).expect("ray");
            let refs: Vec<(&BoxCells, ())> = cells.iter().map(|c| (c, ())).collect();
            let joint = walk_joint(walls, &refs, &scene.regions, &ray, max);
            let (got, want) = (joint.map(|(d, _)| d), separately.map(|(d, _)| d));
            assert_eq!(got, want, "{k}: ({x}, {y}) along ({dx}, {dy}) to {max}");
            // What was met reads that distance on its own walk.
            match joint {
                Some((d, Met::Body(b))) => {
                    assert_eq!(cells[b].cast_in(&scene, (x, y), (dx, dy), max), Some(d));
                    bodies_met += 1;
                }
                Some((d, Met::Wall)) => {
                    let own = walls.and_then(|w| w.cast_among(x, y, dx, dy, max, &scene.regions));
                    assert_eq!(own, Some(d), "{k}");
                    walls_met += 1;
                }
                None => {}
            }
        }
        assert!(
            bodies_met > 300 && walls_met > 300,
            "{bodies_met} {walls_met}"
        );
    }
}
