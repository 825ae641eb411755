//! The simulation: fixed steps, robots driven by velocity or position commands, collisions
//! that stop a robot and set its stall flag, and sensors by ray casting. Deterministic: the
//! same world and commands give the same trajectory.

mod battery;
mod beams;
mod blobfinder;
mod body_index;
mod body_places;
mod body_pose;
mod box_cells;
mod box_regions;
mod camera;
mod cell_blocks;
mod directions;
mod drivers;
mod fan_facing;
mod geometry;
mod gripper;
mod joint_walk;
mod nearby;
mod noise;
mod odometry;
mod parallel_scans;
mod position_control;
mod quick_angles;
mod raster_walk;
mod ray_scene;
mod scan_caster;
mod sensors;
mod shapes;
#[cfg(test)]
mod test_halls;
#[cfg(test)]
mod test_randoms;
mod walking;
mod wall_beams;
mod wall_box_beams;
mod wall_boxes;
mod wall_free;
mod wall_raster;
mod wall_tiles;
mod wall_walk;
mod wander;

pub use battery::BatteryState;
pub use blobfinder::{Blob, blobs};
pub use body_index::BodyIndex;
pub use body_pose::{body_at, on_robot};
pub use camera::{Frame, render_camera};
pub use drivers::{Drivers, NoDrivers};
pub use geometry::GroundBox;
pub use gripper::{BEAM_BITS, GripperCommand, GripperState, Paddles};
pub use nearby::{NearbyBoxes, SolidBox};
pub use noise::Noise;
pub use odometry::{integrate, odometry_error};
pub use position_control::goto_velocity;
pub use sensors::{
    FiducialHit, RangerReturns, fiducials, ranger_returns, ranger_scan, ranger_scan_exhaustive,
};
pub use walking::WalkerState;
pub use wall_raster::WallRaster;
pub use wander::WanderState;

use body_index::IndexCache;

use crate::world::{Drive, Pose, World};

/// What a robot is told to do.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Command {
    /// Velocity in the robot frame: forward m/s, sideways m/s (omni only), turn rad/s.
    Velocity { vx: f64, vy: f64, va: f64 },
    /// Go to this pose (position mode), in the frame the robot reports its pose in, steered
    /// as Stage steers (see [`goto_velocity`]).
    GoTo { target: Pose },
}

/// A robot's moving state.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotState {
    pub pose: Pose,
    /// Where its localization puts it: with odom, the odometry's reading (what position2d
    /// reports); with gps, where it stood before the last step's motion, which Stage's
    /// position controller steers from (see [`Simulation::reported_pose`]).
    pub estimate: Pose,
    /// Actual velocity over the last step (robot frame).
    pub velocity: (f64, f64, f64),
    pub stall: bool,
    pub command: Command,
    /// How Stage's wander controller is turning, for a robot with `ctrl "wander"`.
    pub wander: WanderState,
    /// One per gripper the robot has.
    pub grippers: Vec<GripperState>,
    /// Its power pack, if the world gives it one.
    pub battery: Option<BatteryState>,
}

/// The simulated world in motion.
#[derive(Debug, Clone)]
pub struct Simulation {
    pub world: World,
    pub robots: Vec<RobotState>,
    /// Simulated seconds since the start.
    pub time: f64,
    pub steps: u64,
    /// Sensor noise and its seed; none by default. The wander controller draws from the
    /// seed too.
    pub noise: Noise,
    /// For each obstacle, the (robot, gripper) holding it.
    pub carried_by: Vec<Option<(usize, usize)>>,
    /// The drivers stepped with it (the navigation drivers the served `.cfg` files run).
    pub drivers: Box<dyn Drivers>,
    /// One per `world.people`: where each walking person is.
    pub walkers: Vec<WalkerState>,
    /// The robots bucketed by where they stand, for the sensors of this step.
    bodies: IndexCache,
    /// Stage's raster of the floorplan's walls, made on first use (the walls never move).
    walls: std::sync::OnceLock<Option<std::sync::Arc<WallRaster>>>,
    /// Threads a step may cast its controllers' scans on (see [`Simulation::set_threads`]).
    threads: usize,
    /// Each robot's last fan of laser beams and their directions, for its next scan.
    fan_directions: scan_caster::FanDirections,
}

const STOP: Command = Command::Velocity {
    vx: 0.0,
    vy: 0.0,
    va: 0.0,
};

impl Simulation {
    pub fn new(world: World) -> Simulation {
        let robots = world
            .robots
            .iter()
            .map(|r| RobotState {
                pose: r.pose,
                estimate: r.localization.odometry_start(r.pose),
                velocity: (0.0, 0.0, 0.0),
                stall: false,
                command: STOP,
                wander: WanderState::default(),
                grippers: r.grippers.iter().map(GripperState::new).collect(),
                battery: r.battery.map(|b| BatteryState {
                    joules: b.stored,
                    watts: 0.0,
                }),
            })
            .collect();
        let carried_by = vec![None; world.obstacles.len()];
        let walkers = world
            .people
            .iter()
            .map(|p| WalkerState::at(p.start))
            .collect();
        let mut sim = Simulation {
            world,
            robots,
            time: 0.0,
            steps: 0,
            noise: Noise::default(),
            carried_by,
            drivers: Box::new(NoDrivers),
            walkers,
            bodies: IndexCache::default(),
            walls: std::sync::OnceLock::new(),
            threads: parallel_scans::default_threads(),
            fan_directions: scan_caster::FanDirections::default(),
        };
        sim.fan_directions = scan_caster::FanDirections::new(sim.robots.len());
        for i in 0..sim.walkers.len() {
            sim.place_legs(i);
        }
        sim
    }

    /// The floorplan's walls as Stage's rangers see them (see [`WallRaster`]); `None` without
    /// walls or for a world too large for the raster.
    pub fn wall_raster(&self) -> Option<&WallRaster> {
        self.walls
            .get_or_init(|| WallRaster::of(&self.world).map(std::sync::Arc::new))
            .as_deref()
    }

    /// Lets a step cast the scans its controllers read on up to `threads` threads (1: on the
    /// caller's alone; by default the machine's cores, at most 8, taken only when a step has
    /// dozens of scans). The run is the same on any number: each scan reads only the world as
    /// the step found it.
    pub fn set_threads(&mut self, threads: usize) {
        self.threads = threads.max(1);
    }

    /// Does robot `robot` hold obstacle `obstacle` (so that it neither bumps into nor sees it)?
    pub fn holds(&self, robot: Option<usize>, obstacle: usize) -> bool {
        robot.is_some()
            && self
                .carried_by
                .get(obstacle)
                .copied()
                .flatten()
                .map(|(r, _)| r)
                == robot
    }

    /// The robot named `name`.
    pub fn robot_index(&self, name: &str) -> Option<usize> {
        self.world.robots.iter().position(|r| r.name == name)
    }

    /// Robot `i`'s footprint when it stands at `pose` (its body shifted by its `origin`).
    pub fn footprint(&self, i: usize, pose: Pose) -> GroundBox<'_> {
        let spec = &self.world.robots[i];
        GroundBox {
            pose: body_at(pose, spec.origin),
            length: spec.size[0],
            width: spec.size[1],
            shape: &spec.shape,
        }
    }

    /// The robots bucketed by where they stand now (built once for all the sensors of a
    /// step, again whenever a robot has moved).
    pub fn body_index(&self) -> std::sync::Arc<BodyIndex> {
        self.bodies.get(&self.world, &self.robots)
    }

    /// Runs `f`, which reads many sensors (a served step's scans), with the robots' index
    /// checked once for all of them instead of once per sensor: the robots cannot move while
    /// `f` borrows the simulation.
    pub fn sensing<R>(&self, f: impl FnOnce(&Simulation) -> R) -> R {
        let _hold = self.bodies.hold(&self.world, &self.robots);
        f(self)
    }

    /// Every solid thing but robot `except`, as boxes.
    pub fn boxes_except(&self, except: Option<usize>) -> impl Iterator<Item = GroundBox<'_>> + '_ {
        let robots = self
            .robots
            .iter()
            .enumerate()
            .filter(move |(i, _)| Some(*i) != except)
            .map(|(i, r)| self.footprint(i, r.pose));
        let obstacles = self
            .world
            .obstacles
            .iter()
            .enumerate()
            .filter(move |(k, _)| !self.holds(except, *k))
            .map(|(_, o)| GroundBox {
                pose: body_at(o.pose, o.origin),
                length: o.size[0],
                width: o.size[1],
                shape: &o.shape,
            });
        robots.chain(obstacles)
    }

    /// Would robot `i` at `pose` hit a wall or another body? `index` holds the robots where
    /// they stood when it was built; none has moved more than `drift` since.
    fn collides(&self, i: usize, pose: Pose, index: &BodyIndex, drift: f64) -> bool {
        let me = self.footprint(i, pose);
        if let Some(floor) = &self.world.floor {
            let hits_wall = if me.shape.is_empty() {
                me.outline().iter().any(|&(x, y)| floor.occupied_at(x, y))
            } else {
                me.shape_points().any(|(x, y)| floor.occupied_at(x, y))
            };
            if hits_wall {
                return true;
            }
        }
        // Only boxes whose bounding circles meet can overlap: a cheap test first.
        let reach = me.bounding_radius();
        let meets = |b: &GroundBox| {
            let apart = (b.pose.x - pose.x).hypot(b.pose.y - pose.y);
            apart <= reach + b.bounding_radius() && b.overlaps(&me)
        };
        let mut near = Vec::new();
        index.near(pose.x, pose.y, reach + drift, &mut near);
        let robots = near
            .into_iter()
            .filter(|&k| k != i)
            .map(|k| self.footprint(k, self.robots[k].pose));
        let obstacles = self
            .world
            .obstacles
            .iter()
            .enumerate()
            .filter(|(k, o)| o.obstacle_return && !self.holds(Some(i), *k))
            .map(|(_, o)| GroundBox {
                pose: body_at(o.pose, o.origin),
                length: o.size[0],
                width: o.size[1],
                shape: &o.shape,
            });
        { robots }.chain(obstacles).any(|b| meets(&b))
    }

    /// Advances the world by one step of `world.interval` seconds.
    pub fn step(&mut self) {
        let dt = self.world.interval;
        self.wander_all();
        self.run_drivers(|drivers, sim| drivers.before_motion(sim));
        self.walk_people();
        // Where the robots stand before they move; a robot that has moved since is within
        // `drift` of where the index has it.
        let index = BodyIndex::build(&self.world, &self.robots);
        let mut drift = 0.0f64;
        for i in 0..self.robots.len() {
            let (vx, vy, va) = self.velocity_for(i);
            let vy = if self.world.robots[i].drive == Drive::Omni {
                vy
            } else {
                0.0
            };
            self.integrate_odometry(i, (vx, vy, va), dt);
            let p = self.robots[i].pose;
            let (s, c) = p.a.sin_cos();
            let next = Pose {
                x: p.x + (c * vx - s * vy) * dt,
                y: p.y + (s * vx + c * vy) * dt,
                a: wrap(p.a + va * dt),
            };
            let moving = vx != 0.0 || vy != 0.0 || va != 0.0;
            if moving && self.collides(i, next, &index, drift) {
                self.robots[i].stall = true;
                self.robots[i].velocity = (0.0, 0.0, 0.0);
            } else {
                let origin = self.world.robots[i].origin;
                let (from, to) = (body_at(p, origin), body_at(next, origin));
                drift = drift.max((to.x - from.x).hypot(to.y - from.y));
                self.robots[i].stall = false;
                self.robots[i].pose = next;
                self.robots[i].velocity = (vx, vy, va);
            }
        }
        self.drain_batteries(dt);
        self.run_drivers(|drivers, sim| drivers.after_motion(sim));
        self.carry();
        for robot in 0..self.robots.len() {
            for gripper in 0..self.robots[robot].grippers.len() {
                self.update_gripper(robot, gripper);
            }
        }
        self.time += dt;
        self.steps += 1;
    }

    /// The velocity robot `i` drives at this step: as commanded, within its bounds.
    fn velocity_for(&mut self, i: usize) -> (f64, f64, f64) {
        let wanted = self.commanded_velocity(i);
        self.world.robots[i].velocity_bounds.clamp(wanted)
    }

    /// The velocity robot `i` is told to drive at this step.
    fn commanded_velocity(&mut self, i: usize) -> (f64, f64, f64) {
        match self.robots[i].command {
            Command::Velocity { vx, vy, va } => (vx, vy, va),
            Command::GoTo { target } => {
                goto_velocity(self.world.robots[i].drive, self.robots[i].estimate, target)
            }
        }
    }
}

/// An angle in (-π, π].
pub fn wrap(a: f64) -> f64 {
    let w = (a + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
    if w <= -std::f64::consts::PI {
        w + std::f64::consts::TAU
    } else {
        w
    }
}
