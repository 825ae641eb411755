//! How a ranger's scan casts its beams. On Stage's raster of the floorplan, each beam is one
//! walk through the walls and the boxes (robots, obstacles, bodies mounted on robots) in its
//! direction within the sensor's range, as Stage walks it (`sim/joint_walk.rs`): the first
//! cell on its path that holds anything is what it meets. A beam that can meet neither a wall
//! (`wall_free.rs`, `wall_box_beams.rs`) nor a box (`beams.rs`) reads its maximum unwalked.
//!
//! On a floorplan too large for a raster, whose rays meet its own grid, the walls are cast
//! first, every beam, and then only the boxes within the farthest wall any beam met: behind
//! every wall a beam met, no box can be nearer than that wall. A beam turned by angular noise
//! is not the fan's beam whose wall was cast: it is cast alone, against the boxes within the
//! sensor's whole reach (listed only when such a beam comes).

use std::cell::OnceCell;
use std::sync::{Arc, Mutex};

use super::Simulation;
use super::beams::{BeamBoxes, Fan};
use super::box_cells::RayScene;
use super::directions::Directions;
use super::fan_facing::Facing;
use super::nearby::NearbyBoxes;
use super::ray_scene::ray_scene;
use super::wall_beams::WallBeams;
use super::wall_free::beams_meeting;
use super::wall_raster::WallRaster;
use crate::world::{OccupancyGrid, Pose};

/// What a beam hit: its distance, and the `ranger_return` of the thing hit.
pub(super) type Hit = (f64, f64);

/// What a ranger's rays meet of the floorplan: Stage's raster of its walls (the world's
/// `resolution`), or, for a world too large for one, the floorplan's own grid.
#[derive(Clone, Copy)]
pub(super) enum Walls<'a> {
    Raster(&'a WallRaster),
    Grid(&'a OccupancyGrid),
}

/// The walls a sensor at `(x, y)` reaching `max` with beams `fan` sees, and which of its beams
/// may meet them: none when its rays pass through them (negative `ranger_return`); on Stage's
/// raster, the beams towards the parts of its reach not known free of walls (`sim/wall_free.rs`:
/// asked once for the scan instead of by every beam's walk); on the floorplan's own grid, the
/// beams towards its wall rectangles within reach.
fn walls_seen(
    sim: &Simulation,
    x: f64,
    y: f64,
    max: f64,
    fan: Fan,
) -> Option<(Walls<'_>, Option<Vec<bool>>)> {
    if sim.world.floor_ranger_return < 0.0 {
        return None;
    }
    if let Some(raster) = sim.wall_raster() {
        // The walls' boxes first (a hall's few walls), else the clearances' quadtree.
        if let Some(beams) = raster.beams_to_walls(x, y, max, fan) {
            return beams
                .contains(&true)
                .then_some((Walls::Raster(raster), Some(beams)));
        }
        let mut parts = Vec::new();
        if !raster.walled_parts(x, y, max, &mut parts) {
            return Some((Walls::Raster(raster), None));
        }
        let beams = beams_meeting(&parts, x, y, fan);
        return (!parts.is_empty()).then_some((Walls::Raster(raster), Some(beams)));
    }
    let grid = sim.world.floor.as_ref()?;
    grid.walls_within(x, y, max).then(|| {
        let beams = WallBeams::new(grid, x, y, max, fan);
        let may_meet = (0..fan.count).map(|i| beams.may_meet(i)).collect();
        (Walls::Grid(grid), Some(may_meet))
    })
}

/// The boxes a sensor at `at` sees within `reach` at height `z`, and each beam's share of them;
/// rays walk to them as in `scene`.
fn boxes_within<'a>(
    sim: &'a Simulation,
    robot: usize,
    (at, reach): ((f64, f64), f64),
    fan: Fan,
    z: f64,
    scene: Arc<RayScene>,
) -> (NearbyBoxes<'a>, BeamBoxes) {
    let facing = Facing::of(fan, at);
    let boxes = NearbyBoxes::around_facing(sim, Some(robot), at, reach, facing)
        .with_mounted(sim, Some(robot), at, reach)
        .reaching(z)
        .on_raster(sim.world.resolution)
        .walked_in(scene);
    let circles = (0..boxes.len()).map(|k| boxes.circle(k));
    let by_beam = BeamBoxes::new(circles, at.0, at.1, fan);
    (boxes, by_beam)
}

/// Do the floorplan's walls stand as high as a beam at `z`?
pub(super) fn walls_reach(sim: &Simulation, z: f64) -> bool {
    (0.0..=sim.world.floor_height).contains(&z)
}

/// A sensor's caster: given a beam's number and direction, what it hits; and which of its fan's
/// own beams may meet anything. The others read their maximum uncast: in the swarm seven beams
/// in ten, each of which had cost a call, its direction and its lists' checks.
pub(super) struct Caster<'s> {
    pub cast: Box<dyn Fn(usize, f64) -> Option<Hit> + 's>,
    pub busy: Vec<bool>,
}

/// The caster of robot `robot`'s sensor at `origin` reaching `max`, with beams `fan` at height
/// `z`.
pub(super) fn caster<'s>(
    sim: &'s Simulation,
    robot: usize,
    origin: Pose,
    max: f64,
    fan: Fan,
    z: f64,
) -> Caster<'s> {
    let at = (origin.x, origin.y);
    // Only the beams that may meet a wall walk the walls.
    let seen = walls_reach(sim, z)
        .then(|| walls_seen(sim, at.0, at.1, max, fan))
        .flatten();
    let (walls, wall_beams) = seen.map_or((None, None), |(walls, beams)| (Some(walls), beams));
    // Shared by the boxes' walks, not copied for each.
    let scene = Arc::new(ray_scene(sim, at, max));
    let raster = match walls {
        Some(Walls::Grid(grid)) => {
            let (cast, busy) =
                grid_caster(sim, robot, (at, max), (fan, z), scene, grid, wall_beams);
            return Caster {
                cast: Box::new(cast),
                busy,
            };
        }
        Some(Walls::Raster(raster)) => Some(raster),
        None => None,
    };
    // Stage's raster: one walk a beam through the walls and the boxes in its direction
    // (`sim/joint_walk.rs`), the boxes those within the sensor's range.
    let (boxes, by_beam) = boxes_within(sim, robot, (at, max), fan, z, scene);
    let directions = sim.fan_directions.of(robot, fan);
    let (resolution, floor_return) = (sim.world.resolution, sim.world.floor_ranger_return);
    let busy = (0..fan.count)
        .map(|beam| {
            let walls = raster.is_some() && wall_beams.as_ref().is_none_or(|w| w[beam]);
            walls || !by_beam.of(beam).is_empty()
        })
        .collect();
    let cast = Box::new(move |beam, angle| {
        let direction = directions.of_beam(beam, angle);
        // A beam turned off its fan's direction walks the walls whether or not the fan's
        // beam may meet them.
        let nominal = angle == fan_angle(fan, beam);
        let may_meet = !nominal || wall_beams.as_ref().is_none_or(|w| w[beam]);
        let walls = raster.filter(|_| may_meet);
        let ahead = by_beam.of(beam);
        // Nothing in this beam's direction: its maximum.
        if walls.is_none() && ahead.is_empty() {
            return None;
        }
        boxes
            .nearest_joint(ahead, (walls, resolution), at, direction, max, |b| {
                b.ranger_return >= 0.0
            })
            .map(|(d, met)| (d, met.map_or(floor_return, |b| b.ranger_return)))
    });
    Caster { cast, busy }
}

/// [`caster`] for a floorplan too large for Stage's raster, whose rays meet its own grid: the
/// walls first, every beam, and then only the boxes within the farthest wall any beam met. With
/// it, which of the fan's beams may meet anything.
fn grid_caster<'s>(
    sim: &'s Simulation,
    robot: usize,
    (at, max): ((f64, f64), f64),
    (fan, z): (Fan, f64),
    scene: Arc<RayScene>,
    grid: &'s OccupancyGrid,
    wall_beams: Option<Vec<bool>>,
) -> (impl Fn(usize, f64) -> Option<Hit> + 's, Vec<bool>) {
    let directions = sim.fan_directions.of(robot, fan);
    // The grid's own cast: no regions, no stepped path.
    let wall_along =
        move |(dx, dy): (f64, f64)| grid.raycast_along(at.0, at.1, dx, dy, max).map(|(d, _)| d);
    let fan_walls: Vec<Option<f64>> = (0..fan.count)
        .map(|beam| {
            let may_meet = wall_beams.as_ref().is_none_or(|w| w[beam]);
            may_meet
                .then(|| wall_along(directions.of_beam(beam, fan_angle(fan, beam))))
                .flatten()
        })
        .collect();
    // The farthest any beam of the fan reaches: its wall, or its range where it meets none.
    let reach = fan_walls
        .iter()
        .try_fold(0.0f64, |far, wall| wall.map(|d| far.max(d)))
        .map_or(max, |far| far.min(max));
    let (boxes, by_beam) = boxes_within(sim, robot, (at, reach), fan, z, scene.clone());
    let busy = (0..fan.count)
        .map(|beam| fan_walls[beam].is_some() || !by_beam.of(beam).is_empty())
        .collect();
    let everything = OnceCell::new();
    let floor_return = sim.world.floor_ranger_return;
    let cast = move |beam, angle| {
        let direction = directions.of_beam(beam, angle);
        let nominal = angle == fan_angle(fan, beam);
        let (wall, boxes, ahead) = if nominal {
            (fan_walls[beam], &boxes, by_beam.of(beam))
        } else {
            let (all, by_beam) = everything
                .get_or_init(|| boxes_within(sim, robot, (at, max), fan, z, scene.clone()));
            // Turned off its fan's direction: walked whether or not the fan's beam may meet
            // a wall.
            (wall_along(direction), all, by_beam.of(beam))
        };
        // Nothing in this beam's direction: its maximum.
        if wall.is_none() && ahead.is_empty() {
            return None;
        }
        let limit = wall.unwrap_or(max);
        let thing = boxes
            .nearest_among(ahead, at, direction, limit, |b| b.ranger_return >= 0.0)
            .map(|(d, b)| (d, b.ranger_return));
        thing.or(wall.map(|d| (d, floor_return)))
    };
    (cast, busy)
}

/// Each robot's last fan of beams and their directions: a robot driving straight on scans the
/// same fan step after step (the wandering swarm's robots, mostly), and the directions' 180
/// rotations, each waiting on the last, were a twentieth of its one-thread profile. The same
/// fan, bit for bit, has the same directions.
#[derive(Debug, Default)]
pub(super) struct FanDirections(Vec<Mutex<Option<Kept>>>);

/// A robot's last fan and its directions.
type Kept = (Fan, Arc<Directions>);

/// Fans of fewer beams are not kept (a ring of single-beam sonars would replace its robot's
/// fan sensor by sensor).
const KEPT_FROM: usize = 16;

impl FanDirections {
    /// Room for `robots` robots' fans.
    pub(super) fn new(robots: usize) -> FanDirections {
        FanDirections((0..robots).map(|_| Mutex::new(None)).collect())
    }

    /// The directions of robot `robot`'s fan `fan`: its last ones if that was this fan.
    fn of(&self, robot: usize, fan: Fan) -> Arc<Directions> {
        let Some(slot) = self.0.get(robot).filter(|_| fan.count >= KEPT_FROM) else {
            return Arc::new(Directions::of(fan));
        };
        let mut kept = slot.lock().unwrap_or_else(|e| e.into_inner());
        let same = |f: &Fan| {
            (f.first.to_bits(), f.step.to_bits(), f.count)
                == (fan.first.to_bits(), fan.step.to_bits(), fan.count)
        };
        match &*kept {
            Some((f, directions)) if same(f) => directions.clone(),
            _ => {
                let directions = Arc::new(Directions::of(fan));
                *kept = Some((fan, directions.clone()));
                directions
            }
        }
    }
}

/// A copy keeps none: they are a cache.
impl Clone for FanDirections {
    fn clone(&self) -> FanDirections {
        FanDirections::new(self.0.len())
    }
}

/// The direction of the fan's beam `i`, as the scan computes it.
fn fan_angle(fan: Fan, i: usize) -> f64 {
    fan.first + i as f64 * fan.step
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_kept_fan_has_the_directions_of_its_own() {
        let kept = FanDirections::new(2);
        let fan = |first: f64, count: usize| Fan {
            first,
            step: std::f64::consts::PI / 180.0,
            count,
        };
        // Kept, asked again, replaced by a turned fan, and a robot the cache has no room for.
        for (robot, f) in [
            (0, fan(0.3, 181)),
            (0, fan(0.3, 181)),
            (0, fan(0.3 + 1e-15, 181)),
            (1, fan(-2.0, 181)),
            (0, fan(0.3, 8)),
            (5, fan(1.0, 181)),
        ] {
            let (got, want) = (kept.of(robot, f), Directions::of(f));
            for i in 0..f.count {
                let angle = fan_angle(f, i);
                assert_eq!(got.of_beam(i, angle), want.of_beam(i, angle), "beam {i}");
            }
        }
        let again = kept.of(0, fan(0.3 + 1e-15, 181));
        assert!(Arc::ptr_eq(&again, &kept.of(0, fan(0.3 + 1e-15, 181))));
    }
}
