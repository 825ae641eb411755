//! Robots, obstacles and bodies mounted on robots as Stage's rangers see them: not their exact
//! outlines but the cells of the world's raster (`resolution`, 2 cm unless set) that their
//! blocks' edges pass through, corners floored to whole cells — as the floorplan's walls are
//! seen ([`WallRaster`](super::WallRaster)). A chair's 3 cm leg is two or three cells, a
//! cell more to the north and east than the leg itself, and a beam passing a centimetre beside
//! the leg meets it in Stage; a beam crossing a robot's outline where its cells leave a gap by
//! the diagonal passes. Only the outline is marked, as Stage marks it: a ray starting inside a
//! box meets its far side.
//!
//! A box's cells are drawn when a ray comes near it (a few per beam at most, after the scan's
//! pruning), into a small grid around the box, and the ray is walked through them with the
//! walls' walk ([`walk`]), so that a box and a wall in the same cell read the same.

use std::cell::OnceCell;
use std::sync::OnceLock;

use smallvec::SmallVec;

use super::raster_walk::{Both, Cells, Listed, Nowhere, Ray, RegionMap, Regions, walk};
use super::wall_raster::line_cells;
use crate::world::{Polygon, floor_i64};

/// Boxes whose cells would number more than this are cast exactly instead (a hall-sized
/// obstacle at a fine resolution).
const MOST_CELLS: i64 = 1 << 22;

/// How far a box's cells on a raster of `resolution` reach beyond its outline, as a ray's
/// line passes them: a floored corner's cell and the cell beside it that rays look into west
/// and south of the origin, in both axes (2√2 cells), and the 2.2 cells Stage's stepped path
/// may stray from the line (`sim/raster_walk.rs`), rounded up. Rays whose line passes farther
/// from the outline than this miss the box.
pub(super) fn cell_margin(resolution: f64) -> f64 {
    if resolution.is_finite() && resolution > 0.0 {
        6.0 * resolution
    } else {
        0.0
    }
}

/// What a ray's walk needs to take Stage's path: the sensor's range (its steps' slope comes
/// from it) and the regions holding something about the sensor (the walls' and the bodies').
#[derive(Debug, Clone, Default)]
pub(super) struct RayScene {
    pub range: f64,
    pub regions: std::sync::Arc<RegionMap>,
}

/// Each block's corners in world cells, a plain box's kept inline.
pub(super) type CornerCells = SmallVec<[SmallVec<[(i64, i64); 4]>; 1]>;

/// A box placed in the world: centre, frame, half sizes, and its blocks in its frame (empty: the
/// box itself is the one block).
#[derive(Debug, Clone, Copy)]
pub(super) struct Placed<'a> {
    pub x: f64,
    pub y: f64,
    pub sin: f64,
    pub cos: f64,
    pub half_length: f64,
    pub half_width: f64,
    pub shape: &'a [Polygon],
}

impl Placed<'_> {
    /// `(lx, ly)` of the box's frame in world cells (floored, as Stage floors a block's
    /// corners).
    fn cell(&self, [lx, ly]: [f64; 2], per_metre: f64) -> (i64, i64) {
        let x = self.x + self.cos * lx - self.sin * ly;
        let y = self.y + self.sin * lx + self.cos * ly;
        (floor_i64(x * per_metre), floor_i64(y * per_metre))
    }

    /// The corners of each block in world cells: kept inline for a plain box (the world's
    /// map of regions takes every robot's corners each step).
    pub(super) fn corner_cells(&self, per_metre: f64) -> CornerCells {
        if self.shape.is_empty() {
            let (h, w) = (self.half_length, self.half_width);
            let corners = [[h, w], [-h, w], [-h, -w], [h, -w]].map(|p| self.cell(p, per_metre));
            return smallvec::smallvec![SmallVec::from_buf(corners)];
        }
        self.shape
            .iter()
            .map(|polygon| polygon.iter().map(|&p| self.cell(p, per_metre)).collect())
            .collect()
    }

    /// Distance along the ray from `(x, y)` in the unit direction `(dx, dy)` to the first of
    /// the box's cells, within `max`, on a raster of `resolution`; `None` when the box is too
    /// large for one (then the caller casts exactly).
    pub(super) fn cast_cells(
        &self,
        resolution: f64,
        (x, y): (f64, f64),
        (dx, dy): (f64, f64),
        max: f64,
        scene: Option<&RayScene>,
    ) -> Option<Option<f64>> {
        let cells = BoxCells::of(self, resolution)?;
        Some(match scene {
            Some(scene) => cells.cast_in(scene, (x, y), (dx, dy), max),
            None => cells.cast((x, y), (dx, dy), max),
        })
    }
}

/// A box's outline cells in the smallest grid holding them: drawn once a scan for each box
/// its beams come near (`NearbyBoxes::on_raster`), and walked by each of those beams.
#[derive(Debug, Clone)]
pub(super) struct BoxCells {
    per_metre: f64,
    /// Global cell of the grid's first column and row.
    first: (i64, i64),
    width: i64,
    height: i64,
    solid: Vec<bool>,
    /// Stage's regions its cells lie in (walked cell by cell, not jumped).
    regions: Listed,
}

impl BoxCells {
    /// The cells of `placed` on a raster of `resolution`; `None` when the box is too large for
    /// one.
    pub(super) fn of(placed: &Placed, resolution: f64) -> Option<BoxCells> {
        let per_metre = 1.0 / resolution;
        if !(per_metre.is_finite() && per_metre > 0.0) {
            return None;
        }
        let corners = placed.corner_cells(per_metre);
        let (mut low, mut high) = ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN));
        for &(x, y) in corners.iter().flatten() {
            low = (low.0.min(x), low.1.min(y));
            high = (high.0.max(x), high.1.max(y));
        }
        if low.0 > high.0 {
            return None;
        }
        let (width, height) = (high.0 - low.0 + 1, high.1 - low.1 + 1);
        if width.saturating_mul(height) > MOST_CELLS {
            return None;
        }
        let mut solid = vec![false; (width * height) as usize];
        let mut regions = Listed::default();
        for polygon in &corners {
            for (k, &a) in polygon.iter().enumerate() {
                let b = polygon[(k + 1) % polygon.len()];
                line_cells(a, b, |x, y| {
                    let (c, r) = (x - low.0, y - low.1);
                    solid[(r * width + c) as usize] = true;
                    regions.add_cell(x, y);
                });
            }
        }
        Some(BoxCells {
            per_metre,
            first: low,
            width,
            height,
            solid,
            regions,
        })
    }
}

/// The cells of every robot's body and mounted bodies for one set of poses, each drawn the
/// first time any scan's ray needs it (`BodyIndex`): in the swarm a robot is seen by a dozen
/// scans a step, and each drew its cells anew.
#[derive(Debug, Default)]
pub(super) struct DrawnCells {
    cells: Vec<OnceLock<Option<BoxCells>>>,
}

impl DrawnCells {
    /// `count` bodies, none drawn.
    pub(super) fn new(count: usize) -> DrawnCells {
        DrawnCells {
            cells: (0..count).map(|_| OnceLock::new()).collect(),
        }
    }

    /// Body `k`'s cells, once drawn.
    pub(super) fn get(&self, k: usize) -> Option<&OnceLock<Option<BoxCells>>> {
        self.cells.get(k)
    }
}

/// Where a box's cells are drawn: for the scan alone, or for every scan of the step.
#[derive(Clone, Copy)]
pub(super) enum Drawn<'b> {
    Scan(&'b OnceCell<Option<BoxCells>>),
    Step(&'b OnceLock<Option<BoxCells>>),
}

impl<'b> Drawn<'b> {
    pub(super) fn get_or_init(
        self,
        draw: impl FnOnce() -> Option<BoxCells>,
    ) -> &'b Option<BoxCells> {
        match self {
            Drawn::Scan(cells) => cells.get_or_init(draw),
            Drawn::Step(cells) => cells.get_or_init(draw),
        }
    }
}

/// A copy draws its cells anew: they are a cache of the poses.
impl Clone for DrawnCells {
    fn clone(&self) -> DrawnCells {
        DrawnCells::new(self.cells.len())
    }
}

/// The cells are a function of the poses, which the index compares.
impl PartialEq for DrawnCells {
    fn eq(&self, other: &DrawnCells) -> bool {
        self.cells.len() == other.cells.len()
    }
}

impl BoxCells {
    /// Distance along the ray from `(x, y)` in the unit direction `(dx, dy)` to the first of
    /// the cells, within `max`.
    pub(super) fn cast(&self, (x, y): (f64, f64), (dx, dy): (f64, f64), max: f64) -> Option<f64> {
        let ray = Ray::new(self.per_metre, (x, y), (dx, dy), max)?;
        self.cast_ray(&ray, &Nowhere, max)
    }

    /// Its grid's first and last column, and its first and last row (global cells).
    pub(super) fn spans(&self) -> ((i64, i64), (i64, i64)) {
        let (x, y) = self.first;
        ((x, x + self.width - 1), (y, y + self.height - 1))
    }

    /// Distance along the ray from `(x, y)` in the unit direction `(dx, dy)` of a sensor in
    /// `scene` to the first of the cells on Stage's path, within `stop` metres.
    pub(super) fn cast_in(
        &self,
        scene: &RayScene,
        (x, y): (f64, f64),
        (dx, dy): (f64, f64),
        stop: f64,
    ) -> Option<f64> {
        let ray = Ray::new(self.per_metre, (x, y), (dx, dy), scene.range)?;
        self.cast_ray(&ray, &*scene.regions, stop)
    }

    /// Distance along `ray` (on this box's raster) to the first of the cells on Stage's path,
    /// within `stop` metres; the regions walked are the box's own and those `others` holds.
    pub(super) fn cast_ray<R: Regions + ?Sized>(
        &self,
        ray: &Ray,
        others: &R,
        stop: f64,
    ) -> Option<f64> {
        walk(self, &Both(&self.regions, others), ray, stop)
    }
}

#[cfg(test)]
impl BoxCells {
    /// The regions its cells lie in, in order.
    pub(super) fn listed_regions(&self) -> &[(i64, i64)] {
        self.regions.listed()
    }
}

impl Cells for BoxCells {
    /// Inside the grid: 0 on the outline, else 1 (walked cell by cell). Outside, the square
    /// ahead is free as far as it misses the grid along either axis: up to the grid's nearer
    /// edge along an axis the ray heads towards it, without end along one where the grid lies
    /// behind (a ray past a body, or beside it heading away, jumps to its stop).
    ///
    /// Without branches on where the cell lies: a ray's cells fall inside and outside a body's
    /// grid in no pattern a branch predictor learns, and these branches were a tenth of the
    /// walk's mispredictions.
    #[inline]
    fn ahead(&self, x: i64, y: i64, q: usize) -> u32 {
        let (c, r) = (x - self.first.0, y - self.first.1);
        let inside = (c >= 0) & (r >= 0) & (c < self.width) & (r < self.height);
        // The cell's own flag, read from the first cell when outside (the grid is never empty;
        // the index wraps where far outside, and is not used there).
        let k = (r.wrapping_mul(self.width).wrapping_add(c) & -i64::from(inside)) as usize;
        let own = u32::from(!self.solid[k]);
        // Free cells from `v` the way the ray heads along an axis of `n` cells: up to the
        // grid's near edge when it lies ahead, none when the cell is level with it, without end
        // when it lies behind.
        let free = |v: i64, n: i64, back: bool| {
            let (ahead, behind) = if back {
                (v - n + 1, v < 0)
            } else {
                (-v, v >= n)
            };
            let behind = -i64::from(behind);
            (ahead.max(0) & !behind) | (i64::MAX & behind)
        };
        let (west, south) = (q & 1 == 1, q & 2 == 2);
        let outside = free(c, self.width, west)
            .max(free(r, self.height, south))
            .clamp(1, i64::from(u32::MAX)) as u32;
        if inside { own } else { outside }
    }
}

/// The tests' small body: a 3 cm square leg, unturned, centred on `(x, y)`.
#[cfg(test)]
impl Placed<'static> {
    pub(super) fn leg(x: f64, y: f64) -> Placed<'static> {
        Placed {
            x,
            y,
            sin: 0.0,
            cos: 1.0,
            half_length: 0.015,
            half_width: 0.015,
            shape: &[],
        }
    }
}

#[cfg(test)]
mod tests;
