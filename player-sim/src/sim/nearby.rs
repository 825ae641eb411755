//! Ray casting that scales with the number of robots: a sensor first keeps only the boxes
//! (robots and obstacles) whose bounding circle its reach touches, once per scan (the robots
//! asked are those the [`BodyIndex`](super::BodyIndex) has near it), and then each
//! ray skips, without trigonometry, every kept box whose circle it misses or that lies beyond
//! the nearest hit so far. With 256 robots a laser's 181 rays then test a handful of boxes each
//! instead of all 255 others.

use super::Simulation;
use std::cell::OnceCell;
use std::sync::Arc;

use super::body_index::BodyIndex;

mod joint;
mod mounted;
mod nearest;

use super::body_places::{Place, obstacle_place};
use super::box_cells::{BoxCells, Drawn, Placed, RayScene, cell_margin};
use super::fan_facing::Facing;
use super::geometry::slab_hit;
use super::shapes::ray_into_polygons;
use crate::world::{Polygon, ShapeSlice, slice_at};

/// A solid box prepared for many rays: its frame's sine and cosine computed once.
#[derive(Debug, Clone, Copy)]
pub struct SolidBox<'a> {
    pub x: f64,
    pub y: f64,
    sin: f64,
    cos: f64,
    half_length: f64,
    half_width: f64,
    radius: f64,
    /// Height of its top above the floor, m (for the camera).
    pub height: f64,
    /// Height of its underside above the floor, m: 0 but for bodies mounted on robots.
    pub bottom: f64,
    pub color: [u8; 3],
    /// What rangers report hitting it; negative: they see through it.
    pub ranger_return: f64,
    /// The blocks inside the box, in its frame; empty for a plain box.
    shape: &'a [Polygon],
    /// Its blocks by height, when they are not all as tall (see [`NearbyBoxes::reaching`]).
    slices: &'a [ShapeSlice],
    /// The world's raster when rays meet the box's cells on it, as rangers do
    /// (`sim/box_cells.rs`, [`NearbyBoxes::on_raster`]); 0: its exact outline (the camera).
    resolution: f64,
    /// A robot's body or mounted body: which of the robots' index's bodies, whose cells are
    /// drawn once for every scan ([`NO_BODY`]: an obstacle, or a body cut by height).
    body: u32,
}

/// What of a box on the raster a ray may meet ([`SolidBox::near`]).
pub(super) enum Near<'c> {
    Beside,
    Cells(&'c BoxCells),
    Exact(Option<f64>),
}

/// Is a body at `place` taken in by a sensor at `at` reaching `reach`, whose beams (if
/// `facing` says) point into a half-plane: within reach, and not wholly behind it.
fn taken_in(place: &Place, at: (f64, f64), reach: f64, facing: Option<Facing>) -> bool {
    place.within(at, reach) && facing.is_none_or(|f| f.may_see((place.x, place.y), place.radius))
}

/// [`SolidBox::body`] of a box whose cells each scan draws for itself.
const NO_BODY: u32 = u32::MAX;

impl SolidBox<'_> {
    /// Where the ray from `(x, y)` along the unit `(dx, dy)` enters the box, if ahead: its
    /// cells on the world's raster when [`NearbyBoxes::on_raster`] (drawn into `cells` the
    /// first time a ray needs them), else its exact outline.
    fn hit(
        &self,
        cells: Option<Drawn<'_>>,
        scene: Option<&RayScene>,
        x: f64,
        y: f64,
        dx: f64,
        dy: f64,
    ) -> Option<f64> {
        match self.near(cells, (x, y), (dx, dy)) {
            Near::Beside => None,
            Near::Cells(drawn) => {
                let beyond = self.far_side((x, y), (dx, dy)).max(0.0);
                match scene {
                    Some(scene) => drawn.cast_in(scene, (x, y), (dx, dy), beyond),
                    None => drawn.cast((x, y), (dx, dy), beyond),
                }
            }
            Near::Exact(d) => d,
        }
    }

    /// What of the box the ray from `(x, y)` along the unit `(dx, dy)` may meet. On the
    /// world's raster (`cells` given, [`NearbyBoxes::on_raster`]): nothing when its line passes
    /// beyond the box widened by its cells' margin (most rays near its circle pass beside it,
    /// and drawing its cells costs more than this test), else its cells, drawn into `cells`
    /// the first time. Off the raster, or for a box too large for cells, where the ray enters
    /// its exact outline.
    pub(super) fn near<'c>(
        &self,
        cells: Option<Drawn<'c>>,
        (x, y): (f64, f64),
        (dx, dy): (f64, f64),
    ) -> Near<'c> {
        let Some(cells) = cells.filter(|_| self.resolution != 0.0) else {
            return Near::Exact(self.exact_hit(x, y, dx, dy));
        };
        let margin = cell_margin(self.resolution);
        let ((ox, oy), (lx, ly)) = self.in_frame(x, y, dx, dy);
        let (hx, hy) = (self.half_length + margin, self.half_width + margin);
        if slab_hit(ox, oy, lx, ly, hx, hy).is_none() {
            return Near::Beside;
        }
        match cells.get_or_init(|| BoxCells::of(&self.placed(), self.resolution)) {
            Some(drawn) => Near::Cells(drawn),
            None => Near::Exact(self.exact_hit(x, y, dx, dy)),
        }
    }

    /// How far along the ray from `(x, y)` along the unit `(dx, dy)` the box's far side lies,
    /// at most: its bounding circle (which takes in its cells' margin) along the line.
    pub(super) fn far_side(&self, (x, y): (f64, f64), (dx, dy): (f64, f64)) -> f64 {
        (self.x - x) * dx + (self.y - y) * dy + self.radius
    }

    fn placed(&self) -> Placed<'_> {
        Placed {
            x: self.x,
            y: self.y,
            sin: self.sin,
            cos: self.cos,
            half_length: self.half_length,
            half_width: self.half_width,
            shape: self.shape,
        }
    }

    /// The ray's origin and direction in the box's own frame (centred, its length along x).
    #[inline]
    fn in_frame(&self, x: f64, y: f64, dx: f64, dy: f64) -> ((f64, f64), (f64, f64)) {
        let (rx, ry) = (x - self.x, y - self.y);
        (
            (
                self.cos * rx + self.sin * ry,
                -self.sin * rx + self.cos * ry,
            ),
            (
                self.cos * dx + self.sin * dy,
                -self.sin * dx + self.cos * dy,
            ),
        )
    }

    /// Where the ray enters the box's exact outline.
    fn exact_hit(&self, x: f64, y: f64, dx: f64, dy: f64) -> Option<f64> {
        let ((ox, oy), (lx, ly)) = self.in_frame(x, y, dx, dy);
        let hit = slab_hit(ox, oy, lx, ly, self.half_length, self.half_width);
        if self.shape.is_empty() {
            return hit;
        }
        hit.and_then(|_| ray_into_polygons(self.shape, ox, oy, lx, ly))
    }

    /// Does the ray come near enough to the box's bounding circle, ahead and before `limit`?
    fn may_hit(&self, x: f64, y: f64, dx: f64, dy: f64, limit: f64) -> bool {
        let (cx, cy) = (self.x - x, self.y - y);
        let along = cx * dx + cy * dy;
        let across = cx * dy - cy * dx;
        across.abs() <= self.radius && along + self.radius >= 0.0 && along - self.radius <= limit
    }
}

/// The boxes a sensor at one place could see within its reach.
#[derive(Debug, Clone, Default)]
pub struct NearbyBoxes<'a> {
    boxes: Vec<SolidBox<'a>>,
    /// Each box's cells on the world's raster, drawn when a ray first needs them (empty
    /// unless [`NearbyBoxes::on_raster`]).
    cells: Vec<OnceCell<Option<BoxCells>>>,
    /// The robots' index the robots were asked of, which draws their cells for every scan.
    index: Option<Arc<BodyIndex>>,
    /// What the index was asked (`(x, y, reach)`) and the robots it gave, in order, kept for
    /// [`NearbyBoxes::with_mounted`] to ask no more when it asks the same.
    asked: Option<((f64, f64, f64), Vec<usize>)>,
    /// How rangers walk to the cells: Stage's path for a sensor's range among the regions it
    /// walks (see [`NearbyBoxes::walked_in`]).
    scene: Option<Arc<RayScene>>,
    /// The half-plane of the scan's beams, behind which no box is taken in.
    facing: Option<Facing>,
}

impl<'a> NearbyBoxes<'a> {
    /// Every robot but `except` and every obstacle whose bounding circle comes within `reach`
    /// of `(x, y)`.
    pub fn around(sim: &'a Simulation, except: Option<usize>, x: f64, y: f64, reach: f64) -> Self {
        Self::around_facing(sim, except, (x, y), reach, None)
    }

    /// [`NearbyBoxes::around`] leaving out the boxes wholly behind `facing`, the half-plane of
    /// a scan's beams (and, through [`NearbyBoxes::with_mounted`], the mounted bodies there).
    pub(super) fn around_facing(
        sim: &'a Simulation,
        except: Option<usize>,
        (x, y): (f64, f64),
        reach: f64,
        facing: Option<Facing>,
    ) -> Self {
        // The robots in the cells within reach, not every robot: in increasing order, as
        // every robot was asked before, so that ties between boxes go the same way.
        let mut near = Vec::new();
        let index = sim.body_index();
        index.near(x, y, reach, &mut near);
        // At most every robot asked and every obstacle: one allocation, not a doubling series.
        let mut boxes = Vec::with_capacity(near.len() + sim.world.obstacles.len());
        // The robots placed once for every scan by the index.
        let robots = near
            .iter()
            .copied()
            .filter(move |&i| Some(i) != except)
            .map(|i| {
                let spec = &sim.world.robots[i];
                let shape = (&spec.shape[..], &spec.shape_slices[..]);
                (
                    index.place(i),
                    i as u32,
                    spec.size,
                    spec.color,
                    spec.ranger_return,
                    shape,
                )
            });
        let resolution = sim.world.resolution;
        let obstacles = sim
            .world
            .obstacles
            .iter()
            .enumerate()
            .filter(|(k, _)| !sim.holds(except, *k))
            .map(|(_, o)| {
                let place = obstacle_place(o, resolution);
                let shape = (&o.shape[..], &o.shape_slices[..]);
                (place, NO_BODY, o.size, o.color, o.ranger_return, shape)
            });
        boxes.extend(
            robots
                .chain(obstacles)
                .filter(|(place, ..)| taken_in(place, (x, y), reach, facing))
                .map(
                    |(place, body, size, color, ranger_return, (shape, slices))| SolidBox {
                        x: place.x,
                        y: place.y,
                        sin: place.sin,
                        cos: place.cos,
                        half_length: size[0] / 2.0,
                        half_width: size[1] / 2.0,
                        radius: place.radius,
                        height: size[2],
                        bottom: 0.0,
                        color,
                        ranger_return,
                        shape,
                        slices,
                        resolution: 0.0,
                        // A body cut by height has cells of its own for each height.
                        body: if slices.is_empty() { body } else { NO_BODY },
                    },
                ),
        );
        NearbyBoxes {
            boxes,
            cells: Vec::new(),
            index: Some(index),
            asked: Some(((x, y, reach), near)),
            scene: None,
            facing,
        }
    }

    /// Only the boxes standing at the height `z` (a beam there passes over or under the
    /// rest), as Stage tests a ray's height against a body's, ends included.
    /// A box drawn with blocks of different heights keeps only the blocks at `z`.
    pub fn reaching(mut self, z: f64) -> Self {
        self.boxes.retain_mut(|b| {
            if !(b.bottom..=b.height).contains(&z) {
                return false;
            }
            if b.slices.is_empty() {
                return true;
            }
            match slice_at(b.slices, z - b.bottom) {
                Some(slice) => {
                    b.shape = &slice.shape;
                    true
                }
                None => false,
            }
        });
        self
    }

    /// Rays meet the boxes as Stage's rangers meet them: on the world's raster of `resolution`
    /// (see `sim/box_cells.rs`), not on their exact outlines.
    pub fn on_raster(mut self, resolution: f64) -> Self {
        for b in &mut self.boxes {
            b.resolution = resolution;
        }
        self.cells = self.boxes.iter().map(|_| OnceCell::new()).collect();
        self
    }

    /// Rays walk to the boxes' cells along the path Stage's rays take in `scene` (see
    /// `sim/raster_walk.rs`).
    pub(super) fn walked_in(mut self, scene: Arc<RayScene>) -> Self {
        self.scene = Some(scene);
        self
    }

    /// Where box `k`'s cells are drawn; `None` unless [`NearbyBoxes::on_raster`].
    fn drawn(&self, k: usize) -> Option<Drawn<'_>> {
        let own = self.cells.get(k)?;
        let body = self.boxes[k].body;
        let step = self.index.as_ref().filter(|_| body != NO_BODY);
        Some(match step.and_then(|index| index.drawn(body as usize)) {
            Some(cells) => Drawn::Step(cells),
            None => Drawn::Scan(own),
        })
    }

    pub fn len(&self) -> usize {
        self.boxes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.boxes.is_empty()
    }

    /// Box `k`'s bounding circle: centre and radius.
    pub fn circle(&self, k: usize) -> (f64, f64, f64) {
        let b = &self.boxes[k];
        (b.x, b.y, b.radius)
    }
}
