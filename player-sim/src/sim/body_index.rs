//! A uniform grid over the robots' bodies, so that a sensor or a moving robot asks only the
//! robots in the cells its reach touches instead of every robot: at 1 024 robots, asking every
//! robot was a million distance checks a step for the lasers and as many for the collisions.
//!
//! The grid spans the robots' centres themselves (not the floorplan), so a robot outside the
//! hall is indexed like any other. Cells are sized for about one robot each. A query returns
//! every robot whose bounding circle may come within the reach (a superset: callers keep their
//! exact tests), in increasing robot order, so that results do not depend on the index.

use std::marker::PhantomData;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

use super::RobotState;
use super::body_places::{Place, places};
use super::body_pose::body_at;
use super::box_cells::{BoxCells, DrawnCells};
use super::raster_walk::RegionMap;
use crate::world::{Pose, World, floor_i64};

/// The robots bucketed by cell; built from one set of poses.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyIndex {
    /// The robot poses it was built from: a cached index is reused only while they stand.
    poses: Vec<Pose>,
    /// World position of cell (0, 0)'s south-west corner.
    origin: (f64, f64),
    cell: f64,
    columns: usize,
    rows: usize,
    /// Cell `k`'s robots are `members[starts[k]..starts[k + 1]]`, in increasing order.
    starts: Vec<u32>,
    members: Vec<u32>,
    /// The largest bounding radius of any robot's body.
    max_radius: f64,
    /// Each robot's `(sin, cos)` of its heading and of its body's (its heading turned by its
    /// `origin`): taken once per index, not by every scan that sees the robot.
    trig: Vec<[(f64, f64); 2]>,
    /// Robot `i`'s mounted bodies are `drawn`'s bodies `robots + mounted[i]..`, after the
    /// robots' own.
    mounted: Vec<u32>,
    /// The bodies' cells on the world's raster, drawn once for every scan of these poses.
    drawn: DrawnCells,
    /// Where each body lies (numbered as `drawn`'s): placed once for every scan.
    places: Vec<Place>,
    /// The regions of Stage's raster the walls and these bodies hold, over the whole world
    /// (`sim/ray_scene.rs`): held once for every scan; `None` for a world too large.
    world_regions: OnceLock<Option<Arc<RegionMap>>>,
}

impl BodyIndex {
    /// Buckets the robots of `world` in the states `robots`.
    pub fn build(world: &World, robots: &[RobotState]) -> BodyIndex {
        let centres: Vec<(f64, f64)> = robots
            .iter()
            .zip(&world.robots)
            .map(|(state, spec)| {
                let body = body_at(state.pose, spec.origin);
                (body.x, body.y)
            })
            .collect();
        let max_radius = world
            .robots
            .iter()
            .map(|r| r.size[0].hypot(r.size[1]) / 2.0)
            .fold(0.0, f64::max);
        let finite = centres
            .iter()
            .filter(|(x, y)| x.is_finite() && y.is_finite());
        let (mut x0, mut y0, mut x1, mut y1) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for (i, &(x, y)) in finite.enumerate() {
            if i == 0 {
                (x0, y0, x1, y1) = (x, y, x, y);
            }
            (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
        }
        // About one robot per cell, but never cells smaller than a robot, nor more cells than
        // a few per robot (robots strung out along a line).
        let n = centres.len().max(1) as f64;
        let (w, h) = (x1 - x0, y1 - y0);
        let mut cell = (w.max(1e-9) * h.max(1e-9) / n)
            .sqrt()
            .max(2.0 * max_radius)
            .max(0.25);
        let lines = |cell: f64| ((w / cell).floor() + 1.0, (h / cell).floor() + 1.0);
        if !(w.is_finite() && h.is_finite()) {
            cell = f64::INFINITY;
        }
        while cell.is_finite() && lines(cell).0 * lines(cell).1 > 4.0 * n + 16.0 {
            cell *= 2.0;
        }
        let (columns, rows) = if cell.is_finite() {
            let (c, r) = lines(cell);
            (c as usize, r as usize)
        } else {
            (1, 1)
        };
        let trig: Vec<[(f64, f64); 2]> = robots
            .iter()
            .zip(&world.robots)
            .map(|(state, spec)| {
                let heading = state.pose.a.sin_cos();
                let body = if spec.origin.a == 0.0 {
                    heading
                } else {
                    body_at(state.pose, spec.origin).a.sin_cos()
                };
                [heading, body]
            })
            .collect();
        let mut mounted = Vec::with_capacity(world.robots.len());
        let mut bodies = world.robots.len();
        for spec in &world.robots {
            mounted.push((bodies - world.robots.len()) as u32);
            bodies += spec.mounted_bodies.len();
        }
        let places = places(world, robots, &trig);
        let mut index = BodyIndex {
            places,
            world_regions: OnceLock::new(),
            trig,
            mounted,
            drawn: DrawnCells::new(bodies),
            poses: robots.iter().map(|r| r.pose).collect(),
            origin: (x0, y0),
            cell,
            columns,
            rows,
            starts: vec![0; columns * rows + 1],
            members: vec![0; centres.len()],
            max_radius,
        };
        // A counting sort by cell: robots stay in increasing order within each cell.
        let cells: Vec<usize> = centres.iter().map(|&(x, y)| index.cell_of(x, y)).collect();
        for &k in &cells {
            index.starts[k + 1] += 1;
        }
        for k in 0..columns * rows {
            index.starts[k + 1] += index.starts[k];
        }
        let mut next = index.starts.clone();
        for (robot, &k) in cells.iter().enumerate() {
            index.members[next[k] as usize] = robot as u32;
            next[k] += 1;
        }
        index
    }

    /// Robot `i`'s `(sin, cos)` of its heading, then of its body's.
    pub fn trig(&self, i: usize) -> [(f64, f64); 2] {
        self.trig[i]
    }

    /// Which of [`BodyIndex::drawn`]'s bodies robot `i`'s mounted body `k` is (robot `i`'s own
    /// body is body `i`).
    pub(super) fn mounted_body(&self, i: usize, k: usize) -> usize {
        self.mounted.len() + self.mounted[i] as usize + k
    }

    /// Where body `k`'s cells on the world's raster are drawn, once for every scan of these
    /// poses.
    pub(super) fn drawn(&self, k: usize) -> Option<&OnceLock<Option<BoxCells>>> {
        self.drawn.get(k)
    }

    /// Where body `k` (numbered as in [`BodyIndex::drawn`]) lies.
    pub(super) fn place(&self, k: usize) -> Place {
        self.places[k]
    }

    /// How many bodies it places: the robots' own, then their mounted bodies.
    pub(super) fn bodies(&self) -> usize {
        self.places.len()
    }

    /// The regions the walls and these bodies hold over the whole world, held by `hold` the
    /// first time they are asked for; `None` for a world too large for one map.
    pub(super) fn world_regions(
        &self,
        hold: impl FnOnce() -> Option<RegionMap>,
    ) -> Option<&Arc<RegionMap>> {
        self.world_regions
            .get_or_init(|| hold().map(Arc::new))
            .as_ref()
    }

    /// Was the index built from robots standing where these stand?
    pub fn is_for(&self, robots: &[RobotState]) -> bool {
        self.poses.len() == robots.len() && self.poses.iter().zip(robots).all(|(p, r)| *p == r.pose)
    }

    /// The cell holding `(x, y)`, clamped to the grid (a non-finite centre lands in cell 0).
    fn cell_of(&self, x: f64, y: f64) -> usize {
        let (cx, cy) = self.column_row(x, y);
        cy * self.columns + cx
    }

    fn column_row(&self, x: f64, y: f64) -> (usize, usize) {
        let clamp = |v: f64, n: usize| {
            if v.is_nan() {
                0
            } else {
                // The floor in integers (a call into libm otherwise), clamped to the grid.
                floor_i64(v).clamp(0, (n - 1) as i64) as usize
            }
        };
        (
            clamp((x - self.origin.0) / self.cell, self.columns),
            clamp((y - self.origin.1) / self.cell, self.rows),
        )
    }

    /// Every robot whose body's centre lies within `reach` plus the largest body radius of
    /// `(x, y)` along each axis (and possibly others), in increasing order: the robots whose
    /// bounding circle may come within `reach` of the point.
    pub fn near(&self, x: f64, y: f64, reach: f64, out: &mut Vec<usize>) {
        out.clear();
        // A hair more than the callers' exact tests ask, for their rounding.
        let r = (reach + self.max_radius) * (1.0 + 1e-9) + 1e-9;
        // A negative or NaN reach touches nothing.
        if r.is_nan() || r < 0.0 {
            return;
        }
        let (c0, r0) = self.column_row(x - r, y - r);
        let (c1, r1) = self.column_row(x + r, y + r);
        for row in r0..=r1 {
            let (a, b) = (row * self.columns + c0, row * self.columns + c1 + 1);
            let span = self.starts[a] as usize..self.starts[b] as usize;
            out.extend(self.members[span].iter().map(|&m| m as usize));
        }
        // Each cell's robots are in order, but not one cell's after another's.
        if r1 > r0 || c1 > c0 {
            out.sort_unstable();
        }
    }
}

/// The index of the robots where they stand now, kept between sensors of one step: rebuilt
/// when a robot has moved since (any pose may be set from outside between steps).
#[derive(Debug, Default)]
pub struct IndexCache {
    cached: Mutex<Option<Arc<BodyIndex>>>,
    /// Open [`Hold`]s: while one lives the robots cannot move (it borrows them), so the
    /// cached index is handed out without comparing every pose again — a million comparisons
    /// a step when 1 024 scans each checked 1 024 poses.
    holds: AtomicUsize,
}

impl Clone for IndexCache {
    /// A clone starts empty: its simulation will move on its own.
    fn clone(&self) -> Self {
        IndexCache::default()
    }
}

impl IndexCache {
    /// The index for `robots` where they stand, built now unless the cached one is for them.
    pub fn get(&self, world: &World, robots: &[RobotState]) -> Arc<BodyIndex> {
        let mut cached = self.cached.lock().unwrap_or_else(|e| e.into_inner());
        match &*cached {
            Some(index) if self.holds.load(Ordering::Acquire) > 0 || index.is_for(robots) => {
                index.clone()
            }
            _ => {
                let index = Arc::new(BodyIndex::build(world, robots));
                *cached = Some(index.clone());
                index
            }
        }
    }

    /// Makes the cached index the one for `robots` (checked or built once, now) and keeps it
    /// so, unchecked, for as long as the hold lives: the hold borrows `robots`, so none can
    /// move meanwhile. The cache must be the one of the simulation `robots` belong to.
    pub fn hold<'a>(&'a self, world: &World, robots: &'a [RobotState]) -> Hold<'a> {
        let mut cached = self.cached.lock().unwrap_or_else(|e| e.into_inner());
        if !cached.as_ref().is_some_and(|index| index.is_for(robots)) {
            *cached = Some(Arc::new(BodyIndex::build(world, robots)));
        }
        self.holds.fetch_add(1, Ordering::AcqRel);
        Hold {
            cache: self,
            _robots: PhantomData,
        }
    }
}

/// See [`IndexCache::hold`].
pub struct Hold<'a> {
    cache: &'a IndexCache,
    _robots: PhantomData<&'a [RobotState]>,
}

impl Drop for Hold<'_> {
    fn drop(&mut self) {
        self.cache.holds.fetch_sub(1, Ordering::AcqRel);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::Simulation;
    use crate::sim::test_randoms::randoms;

    #[test]
    fn a_query_holds_every_robot_within_reach_in_order() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/swarm.world");
        let mut sim = Simulation::new(World::load(&path).unwrap());
        let mut next = randoms(0x5EED);
        for (i, r) in sim.robots.iter_mut().enumerate() {
            // Most in the hall, some far outside it, some stacked on one spot, some on the
            // whole metres where cell borders are likely.
            r.pose = match i % 8 {
                0 => Pose {
                    x: 300.0 * next() - 150.0,
                    y: 300.0 * next() - 150.0,
                    a: 6.0 * next(),
                },
                1 => Pose {
                    x: 2.0,
                    y: 2.0,
                    a: 0.0,
                },
                2 => Pose {
                    x: (40.0 * next() - 20.0).round(),
                    y: (40.0 * next() - 20.0).round(),
                    a: 1.0,
                },
                _ => Pose {
                    x: 64.0 * next() - 32.0,
                    y: 64.0 * next() - 32.0,
                    a: 6.0 * next(),
                },
            };
        }
        let index = BodyIndex::build(&sim.world, &sim.robots);
        assert!(index.is_for(&sim.robots));
        let mut near = Vec::new();
        for _ in 0..2000 {
            let (x, y) = (340.0 * next() - 170.0, 340.0 * next() - 170.0);
            let reach = [0.0, 0.3, 2.5, 8.0, 60.0][(next() * 5.0) as usize % 5];
            index.near(x, y, reach, &mut near);
            assert!(near.windows(2).all(|w| w[0] < w[1]), "in increasing order");
            for (k, (state, spec)) in sim.robots.iter().zip(&sim.world.robots).enumerate() {
                let body = body_at(state.pose, spec.origin);
                let radius = spec.size[0].hypot(spec.size[1]) / 2.0;
                if (body.x - x).hypot(body.y - y) <= reach + radius {
                    assert!(
                        near.contains(&k),
                        "robot {k} at {body:?} from ({x}, {y}) within {reach}"
                    );
                }
            }
        }
        sim.robots[3].pose.x += 0.01;
        assert!(
            !index.is_for(&sim.robots),
            "a moved robot makes the index stale"
        );
    }
}
