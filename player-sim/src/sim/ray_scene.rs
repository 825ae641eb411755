//! The regions of Stage's raster a sensor's rays walk cell by cell (`sim/raster_walk.rs`):
//! those that hold a wall or a body. Stage draws every body into its raster, wherever it
//! stands, so a ray walks a region holding any cell of any robot, mounted body or obstacle,
//! and its path depends on them.
//!
//! The walls' and the robots' bodies' regions are held once a step in one map of the whole
//! world, shared by every scan of the step ([`world_regions`]): a scan only reads it. In the
//! 1 024-robot swarm each scan had built a map of its own reach (the walls' regions copied in,
//! then each body's), a tenth of the run. A scan with an obstacle near its reach (obstacles
//! may move between the robots' steps, and are not kept with them) or in a world too large
//! for one map holds its own reach's regions, the same ones.

use std::sync::Arc;

use super::Simulation;
use super::body_index::BodyIndex;
use super::body_places::obstacle_place;
use super::box_cells::RayScene;
use super::raster_walk::{RegionMap, region_of};
use crate::world::floor_i64;

/// The most regions the world's map may have (4 Mi, 4 MiB; 1.3 km each way at 2 cm): a larger
/// world's scans each hold the regions of their own reach.
const MOST_REGIONS: i64 = 1 << 22;

/// Cells beyond its reach a scan's own map spans, each way: the walk's path may stray past
/// the reach by its last steps (`raster_walk.rs`).
const SPAN_MARGIN: i64 = 64;

/// The regions a sensor at `at` reaching `reach` walks, and its reach.
pub(super) fn ray_scene(sim: &Simulation, at: (f64, f64), reach: f64) -> RayScene {
    let resolution = sim.world.resolution;
    let index = sim.body_index();
    let world = index.world_regions(|| world_regions(sim, &index));
    let far = holding_within(reach, resolution);
    let near_obstacle = sim
        .world
        .obstacles
        .iter()
        .any(|o| obstacle_place(o, resolution).within(at, far));
    if let Some(world) = world.filter(|_| !near_obstacle) {
        return RayScene {
            range: reach,
            regions: world.clone(),
        };
    }
    RayScene {
        range: reach,
        regions: Arc::new(own_regions(sim, &index, (at, reach), world.map(|w| &**w))),
    }
}

/// The regions a sensor at `at` reaching `reach` walks, on a map of its reach alone: the
/// world's map's there (`world`), else the walls' and the bodies' near enough to hold one of
/// them; and the obstacles'.
fn own_regions(
    sim: &Simulation,
    index: &BodyIndex,
    (at, reach): ((f64, f64), f64),
    world: Option<&RegionMap>,
) -> RegionMap {
    let resolution = sim.world.resolution;
    let far = holding_within(reach, resolution);
    let span = |v: f64, s: f64| floor_i64((v + s * reach) / resolution) + SPAN_MARGIN * s as i64;
    let mut regions = RegionMap::over(
        (span(at.0, -1.0), span(at.1, -1.0)),
        (span(at.0, 1.0), span(at.1, 1.0)),
    );
    match world {
        Some(world) => regions.hold_all(world),
        None => {
            if let Some(raster) = sim.wall_raster() {
                regions.hold_all(raster.regions());
            }
            let mut near = Vec::new();
            index.near(at.0, at.1, far, &mut near);
            hold_robots(sim, index, near.into_iter(), &mut regions);
        }
    }
    for o in &sim.world.obstacles {
        let place = obstacle_place(o, resolution);
        if place.within(at, far) {
            place
                .placed(o.size, &o.shape)
                .add_regions(resolution, &mut regions);
        }
    }
    regions
}

/// How far from a sensor reaching `reach` a body may stand and still hold a region of the
/// sensor's own map: its span, out to the regions' edges, across the diagonal.
fn holding_within(reach: f64, resolution: f64) -> f64 {
    (reach + 2.0 * SPAN_MARGIN as f64 * resolution) * std::f64::consts::SQRT_2
}

/// The regions the walls and every robot's body and mounted bodies hold, over the whole
/// world; `None` when that map would have more than [`MOST_REGIONS`].
fn world_regions(sim: &Simulation, index: &BodyIndex) -> Option<RegionMap> {
    let resolution = sim.world.resolution;
    let (mut low, mut high) = ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN));
    let mut take = |(x0, y0): (i64, i64), (x1, y1): (i64, i64)| {
        low = (low.0.min(x0), low.1.min(y0));
        high = (high.0.max(x1), high.1.max(y1));
    };
    let raster = sim.wall_raster();
    if let Some(raster) = &raster {
        let (a, b) = raster.cell_bounds();
        take(a, b);
    }
    for k in 0..index.bodies() {
        let p = index.place(k);
        let cell = |v: f64| floor_i64(v / resolution);
        let (x0, y0) = (cell(p.x - p.radius) - 1, cell(p.y - p.radius) - 1);
        let (x1, y1) = (cell(p.x + p.radius) + 1, cell(p.y + p.radius) + 1);
        // A body placed nowhere (a non-finite pose) holds nothing.
        if [p.x, p.y, p.radius].iter().all(|v| v.is_finite()) {
            take((x0, y0), (x1, y1));
        }
    }
    if low.0 > high.0 {
        return Some(RegionMap::default());
    }
    let side = |a: i64, b: i64| region_of(b) - region_of(a) + 1;
    if side(low.0, high.0).saturating_mul(side(low.1, high.1)) > MOST_REGIONS {
        return None;
    }
    let mut regions = RegionMap::over(low, high);
    if let Some(raster) = &raster {
        regions.hold_all(raster.regions());
    }
    hold_robots(sim, index, 0..sim.world.robots.len(), &mut regions);
    Some(regions)
}

/// Holds in `regions` the regions of robots `robots`' bodies and mounted bodies: whole, even
/// a body cut by height (Stage's raster holds all its blocks).
fn hold_robots(
    sim: &Simulation,
    index: &BodyIndex,
    robots: impl Iterator<Item = usize>,
    regions: &mut RegionMap,
) {
    let resolution = sim.world.resolution;
    for i in robots {
        let spec = &sim.world.robots[i];
        let body = std::iter::once((i, spec.size, &spec.shape[..]));
        let mounted = spec
            .mounted_bodies
            .iter()
            .enumerate()
            .map(|(k, body)| (index.mounted_body(i, k), body.size, &body.shape[..]));
        for (number, size, shape) in body.chain(mounted) {
            index
                .place(number)
                .placed(size, shape)
                .add_regions(resolution, regions);
        }
    }
}

#[cfg(test)]
mod tests;
