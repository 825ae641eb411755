//! Sensors by ray casting: a ranger's beams against the floorplan, the boxes and the other
//! robots; fiducial markers within range, field of view and line of sight.

use super::beams::Fan;
use super::body_pose::on_robot;
use super::box_cells::RayScene;
use super::directions::Directions;
use super::ray_scene::ray_scene;
use super::scan_caster::{Hit, caster, walls_reach};
use super::{GroundBox, Simulation, wrap};
use crate::world::{FiducialSpec, Pose, RangerSpec, slice_at};

/// Distance to the floorplan's walls along a ray, up to `scene`'s range, on Stage's path
/// through `scene`'s regions.
fn floor_distance(
    sim: &Simulation,
    x: f64,
    y: f64,
    (angle, (dx, dy)): (f64, (f64, f64)),
    scene: &RayScene,
) -> Option<f64> {
    let max = scene.range;
    match sim.wall_raster() {
        Some(raster) => raster.cast_among(x, y, dx, dy, max, &scene.regions),
        None => sim.world.floor.as_ref()?.raycast(x, y, angle, max),
    }
}

/// The same distance by testing every box: the unpruned reference the pruned cast is tested
/// against and the benchmark's baseline (for worlds where rangers see everything). The beam's
/// direction is the scan's own (`Directions`): Stage's stepped path turns on its last bits.
fn cast_exhaustive(
    sim: &Simulation,
    from: usize,
    (x, y, z): (f64, f64, f64),
    (angle, direction): (f64, (f64, f64)),
    scene: &RayScene,
) -> Option<f64> {
    let max = scene.range;
    let floor =
        floor_distance(sim, x, y, (angle, direction), scene).filter(|_| walls_reach(sim, z));
    // The boxes in boxes_except's order (robots, then obstacles), with their heights and
    // their blocks by height.
    let robots = (0..sim.robots.len()).filter(|&i| i != from).map(|i| {
        let r = &sim.world.robots[i];
        (r.size[2], &r.shape_slices[..])
    });
    let obstacles = (0..sim.world.obstacles.len())
        .filter(|&k| !sim.holds(Some(from), k))
        .map(|k| {
            let o = &sim.world.obstacles[k];
            (o.size[2], &o.shape_slices[..])
        });
    let things = sim
        .boxes_except(Some(from))
        .zip(robots.chain(obstacles))
        .filter(|(_, (height, _))| (0.0..=*height).contains(&z))
        .filter_map(|(mut b, (_, slices))| {
            if !slices.is_empty() {
                b.shape = &slice_at(slices, z)?.shape;
            }
            b.raycast_cells_in(
                sim.world.resolution,
                (x, y),
                (angle, direction),
                Some(scene),
            )
        });
    let mounted = (0..sim.robots.len())
        .filter(|&i| i != from)
        .flat_map(|i| {
            let pose = sim.robots[i].pose;
            sim.world.robots[i]
                .mounted_bodies
                .iter()
                .map(move |m| (pose, m))
        })
        .filter(|(_, m)| (m.bottom..=m.bottom + m.size[2]).contains(&z) && m.ranger_return >= 0.0)
        .filter_map(|(pose, m)| {
            let body = GroundBox {
                pose: on_robot(pose, m.pose),
                length: m.size[0],
                width: m.size[1],
                shape: &m.shape,
            };
            body.raycast_cells_in(
                sim.world.resolution,
                (x, y),
                (angle, direction),
                Some(scene),
            )
        });
    floor
        .into_iter()
        .chain(things)
        .chain(mounted)
        .filter(|&d| d <= max)
        .min_by(f64::total_cmp)
}

/// The readings of robot `robot`'s ranger: for a one-sensor ranger, its samples spread evenly
/// over the field of view (first at -fov/2); for a ring, one reading per sensor. A beam that
/// hits nothing reads the maximum range.
pub fn ranger_scan(sim: &Simulation, robot: usize, ranger: &RangerSpec) -> Vec<f64> {
    ranger_returns(sim, robot, ranger).ranges
}

/// A ranger's readings as Stage reports them: ranges, and intensities — the `ranger_return`
/// of what each beam hit, 0 where it hit nothing.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RangerReturns {
    pub ranges: Vec<f64>,
    pub intensities: Vec<f64>,
}

/// [`ranger_scan`] with the intensities.
pub fn ranger_returns(sim: &Simulation, robot: usize, ranger: &RangerSpec) -> RangerReturns {
    scan_with(sim, robot, ranger, |origin, max, fan, z| {
        let caster = caster(sim, robot, origin, max, fan, z);
        (caster.cast, Some(caster.busy))
    })
}

/// [`ranger_scan`] testing every box against every beam (no pruning): the reference.
pub fn ranger_scan_exhaustive(sim: &Simulation, robot: usize, ranger: &RangerSpec) -> Vec<f64> {
    let scan = scan_with(sim, robot, ranger, |origin, max, fan, z| {
        let directions = Directions::of(fan);
        let scene = ray_scene(sim, (origin.x, origin.y), max);
        let cast = move |i, angle| {
            let along = (angle, directions.of_beam(i, angle));
            let at = (origin.x, origin.y, z);
            cast_exhaustive(sim, robot, at, along, &scene).map(|d| (d, 1.0))
        };
        (cast, None)
    });
    scan.ranges
}

/// A ranger's beams, each cast by the caster `prepare` makes for a sensor's origin, reach,
/// beams and height; the caster is given a beam's number and direction. With it `prepare` may
/// tell which of the fan's own beams may meet anything: without noise the others read the
/// maximum uncast.
fn scan_with<F: Fn(usize, f64) -> Option<Hit>>(
    sim: &Simulation,
    robot: usize,
    ranger: &RangerSpec,
    prepare: impl Fn(Pose, f64, Fan, f64) -> (F, Option<Vec<bool>>),
) -> RangerReturns {
    let base = on_robot(sim.robots[robot].pose, ranger.pose);
    // Sized once: grown reading by reading, a 181-beam scan reallocated both lists 8 times.
    // (A hint, bounded: a world file may ask for absurdly many samples.)
    let readings = ranger
        .sensors
        .iter()
        .fold(0usize, |n, s| n.saturating_add(s.samples.max(1)))
        .min(1 << 16);
    let mut out = RangerReturns {
        ranges: Vec::with_capacity(readings),
        intensities: Vec::with_capacity(readings),
    };
    for (index, sensor) in ranger.sensors.iter().enumerate() {
        let origin = on_robot(base, sensor.pose);
        // Tells this robot's rangers apart for the noise: where the ranger sits on the robot.
        let place = ranger.pose.x.to_bits() ^ ranger.pose.a.to_bits().rotate_left(17);
        let n = sensor.samples.max(1);
        let step = if n > 1 {
            sensor.fov / (n - 1) as f64
        } else {
            0.0
        };
        let first = if n > 1 { -sensor.fov / 2.0 } else { 0.0 };
        let fan = Fan {
            first: origin.a + first,
            step,
            count: n,
        };
        let (caster, busy) = prepare(origin, sensor.max_range, fan, sensor.z);
        // No noise of the sensor's own nor of the run's: every reading is the range itself,
        // without a draw per beam, and no beam turns off its fan's direction.
        let quiet = sensor.noise.is_none() && sim.noise.range_sd <= 0.0;
        if let Some(busy) = busy.filter(|b| quiet && b.len() == n) {
            let at = out.ranges.len();
            out.ranges
                .resize(at + n, sensor.max_range.max(sensor.min_range));
            out.intensities.resize(at + n, 0.0);
            for i in (0..n).filter(|&i| busy[i]) {
                let angle = origin.a + first + i as f64 * step + 0.0;
                if let Some((range, intensity)) = caster(i, angle) {
                    out.ranges[at + i] = range.max(sensor.min_range);
                    out.intensities[at + i] = intensity;
                }
            }
            continue;
        }
        for i in 0..n {
            let draw = [sim.steps, robot as u64, place, index as u64, i as u64];
            let turn = sim.noise.beam_turn(&sensor.noise, step, &draw);
            let angle = origin.a + first + i as f64 * step + turn;
            let (reading, intensity) = match caster(i, angle) {
                // A beam that hits nothing reads the maximum, as a real one does: no noise.
                None => (sensor.max_range, 0.0),
                Some((range, intensity)) if quiet => (range, intensity),
                Some((range, intensity)) => (
                    sim.noise.reading(
                        range,
                        &sensor.noise,
                        (sensor.min_range, sensor.max_range),
                        &draw,
                    ),
                    intensity,
                ),
            };
            out.ranges.push(reading.max(sensor.min_range));
            out.intensities.push(intensity);
        }
    }
    out
}

/// A marker a fiducial finder sees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FiducialHit {
    /// 0 beyond the finder's id range.
    pub id: i32,
    /// In the finder's frame.
    pub x: f64,
    pub y: f64,
    pub yaw: f64,
}

impl FiducialHit {
    pub fn range(&self) -> f64 {
        self.x.hypot(self.y)
    }

    pub fn bearing(&self) -> f64 {
        self.y.atan2(self.x)
    }
}

/// Markers (robots and boxes with a fiducial id) robot `robot`'s finder sees.
pub fn fiducials(sim: &Simulation, robot: usize, finder: &FiducialSpec) -> Vec<FiducialHit> {
    let at = on_robot(sim.robots[robot].pose, finder.pose);
    let robots = sim
        .world
        .robots
        .iter()
        .zip(&sim.robots)
        .enumerate()
        .filter(|(i, _)| *i != robot)
        .filter_map(|(_, (spec, state))| spec.fiducial_id.map(|id| (id, state.pose)));
    let boxes = sim
        .world
        .obstacles
        .iter()
        .filter_map(|o| o.fiducial_id.map(|id| (id, o.pose)));
    let mut hits = Vec::new();
    for (id, pose) in robots.chain(boxes) {
        let (dx, dy) = (pose.x - at.x, pose.y - at.y);
        let range = dx.hypot(dy);
        let bearing = wrap(dy.atan2(dx) - at.a);
        if range < finder.min_range || range > finder.max_range || bearing.abs() > finder.fov / 2.0
        {
            continue;
        }
        // Line of sight: nothing nearer than the marker's own box along the way.
        let blocked = sim
            .world
            .floor
            .as_ref()
            .and_then(|g| g.raycast(at.x, at.y, dy.atan2(dx), range))
            .is_some_and(|d| d < range - 0.3);
        if blocked {
            continue;
        }
        hits.push(FiducialHit {
            id: if range <= finder.max_range_id { id } else { 0 },
            x: range * bearing.cos(),
            y: range * bearing.sin(),
            yaw: wrap(pose.a - at.a),
        });
    }
    hits
}
