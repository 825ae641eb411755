use super::*;
use crate::sim::box_cells::{BoxCells, Placed};
use crate::sim::raster_walk::{Regions, region_of};
use crate::sim::test_randoms::randoms;
use crate::world::{BoxObstacle, Pose, World};

/// The swarm's hall with its 256 robots scattered, some far outside it, and two obstacles.
fn scattered() -> Simulation {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/swarm.world");
    let mut world = World::load(&path).expect("swarm.world");
    let obstacle = |name: &str, x: f64, y: f64| {
        BoxObstacle::plain(
            name.into(),
            Pose { x, y, a: 0.7 },
            [0.5, 0.3, 0.4],
            [0, 0, 0],
        )
    };
    world.obstacles = vec![obstacle("crate", 3.0, 4.0), obstacle("bin", -20.0, 11.0)];
    let mut sim = Simulation::new(world);
    let mut next = randoms(0x5CE4E);
    for (i, r) in sim.robots.iter_mut().enumerate() {
        let spread = if i % 16 == 0 { 200.0 } else { 60.0 };
        r.pose = Pose {
            x: spread * (next() - 0.5),
            y: spread * (next() - 0.5),
            a: 6.3 * next(),
        };
    }
    sim
}

/// The regions a sensor's scene must hold, worked out another way: the walls', and those of
/// every cell each body (however far) and each obstacle marks on the raster.
fn every_region(sim: &Simulation, index: &BodyIndex) -> RegionMap {
    let mut all = RegionMap::over((-20_000, -20_000), (20_000, 20_000));
    all.hold_all(sim.wall_raster().expect("walls").regions());
    let resolution = sim.world.resolution;
    let mut hold = |placed: Placed| {
        let cells = BoxCells::of(&placed, resolution).expect("a body's cells");
        for &(x, y) in cells.listed_regions() {
            all.hold(x, y);
        }
    };
    for (i, spec) in sim.world.robots.iter().enumerate() {
        hold(index.place(i).placed(spec.size, &spec.shape));
        for (k, m) in spec.mounted_bodies.iter().enumerate() {
            hold(
                index
                    .place(index.mounted_body(i, k))
                    .placed(m.size, &m.shape),
            );
        }
    }
    for o in &sim.world.obstacles {
        hold(obstacle_place(o, resolution).placed(o.size, &o.shape));
    }
    all
}

/// Every region within the reach of a sensor (and the margin its rays may stray) reads the
/// same in its scene as in the world: held by the walls, by any body however far it stands
/// (Stage's raster holds them all), or by an obstacle. The world's map shared by the step's
/// scans and a sensor's own map (near an obstacle, or in a world too large for one map) agree.
#[test]
fn a_scene_holds_the_regions_of_everything_within_its_reach_however_far_it_stands() {
    let sim = scattered();
    let index = sim.body_index();
    let all = every_region(&sim, &index);
    let resolution = sim.world.resolution;
    let mut next = randoms(0xA11);
    let (mut shared, mut own, mut far_bodies) = (0, 0, 0);
    for k in 0..300 {
        let at = (80.0 * (next() - 0.5), 80.0 * (next() - 0.5));
        let reach = [0.5, 3.0, 8.0][k % 3];
        let scene = ray_scene(&sim, at, reach);
        let alone = own_regions(&sim, &index, (at, reach), None);
        if Arc::ptr_eq(
            &scene.regions,
            index.world_regions(|| None).expect("one map"),
        ) {
            shared += 1;
        } else {
            own += 1;
        }
        let lowest = |v: f64| region_of(floor_i64((v - reach) / resolution) - SPAN_MARGIN);
        let highest = |v: f64| region_of(floor_i64((v + reach) / resolution) + SPAN_MARGIN);
        for y in lowest(at.1)..=highest(at.1) {
            for x in lowest(at.0)..=highest(at.0) {
                let want = all.populated(x, y);
                assert_eq!(
                    scene.regions.populated(x, y),
                    want,
                    "{at:?} {reach} ({x}, {y})"
                );
                assert_eq!(
                    alone.populated(x, y),
                    want,
                    "alone: {at:?} {reach} ({x}, {y})"
                );
            }
        }
        // Bodies beyond the reach whose regions it crosses.
        let mut near = Vec::new();
        index.near(at.0, at.1, reach, &mut near);
        far_bodies += (0..sim.robots.len())
            .filter(|i| !near.contains(i))
            .filter(|&i| index.place(i).within(at, reach + 1.0))
            .count();
    }
    assert!(shared > 100 && own > 0, "{shared} shared, {own} own maps");
    assert!(far_bodies > 0, "no body stood just beyond a reach");
}
