//! The regions of Stage's raster a sensor's rays walk cell by cell (`sim/raster_walk.rs`):
//! those within its reach that hold a wall or a body — every robot's body and mounted bodies
//! there, its own robot's among them, and the obstacles. Stage walks those regions cell by
//! cell, so its rays' paths depend on them.
//!
//! A scan reads the bodies as the robots' index placed them for the step, and each body's
//! regions as listed once for the step: in the cave a scan's reach takes in nearly all 200
//! bodies, and placing each one and listing its regions anew was a fifth of the run.

use super::Simulation;
use super::body_places::obstacle_place;
use super::box_cells::RayScene;
use super::raster_walk::RegionMap;
use crate::world::floor_i64;

/// The regions a sensor at `at` reaching `reach` walks, and its reach.
pub(super) fn ray_scene(sim: &Simulation, at: (f64, f64), reach: f64) -> RayScene {
    let resolution = sim.world.resolution;
    let span = |v: f64, s: f64| floor_i64((v + s * reach) / resolution) + 64 * s as i64;
    let (low, high) = (
        (span(at.0, -1.0), span(at.1, -1.0)),
        (span(at.0, 1.0), span(at.1, 1.0)),
    );
    let mut regions = RegionMap::over(low, high);
    if let Some(raster) = sim.wall_raster() {
        regions.hold_all(raster.regions());
    }
    let index = sim.body_index();
    let mut near = Vec::new();
    index.near(at.0, at.1, reach, &mut near);
    for &i in &near {
        let spec = &sim.world.robots[i];
        let body = std::iter::once((i, spec.size, &spec.shape[..]));
        let mounted = spec
            .mounted_bodies
            .iter()
            .enumerate()
            .map(|(k, body)| (index.mounted_body(i, k), body.size, &body.shape[..]));
        for (number, size, shape) in body.chain(mounted) {
            let place = index.place(number);
            if !place.within(at, reach) {
                continue;
            }
            // Whole, even a body cut by height: Stage's raster holds all its blocks.
            let placed = place.placed(size, shape);
            match index.held_regions(number) {
                Some(listed) => {
                    for &(x, y) in listed.get_or_init(|| placed.region_list(resolution)) {
                        regions.hold(x, y);
                    }
                }
                None => placed.add_regions(resolution, &mut regions),
            }
        }
    }
    for o in &sim.world.obstacles {
        let place = obstacle_place(o, resolution);
        if place.within(at, reach) {
            place
                .placed(o.size, &o.shape)
                .add_regions(resolution, &mut regions);
        }
    }
    RayScene {
        range: reach,
        regions,
    }
}
