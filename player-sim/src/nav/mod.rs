//! Player's navigation drivers, stepped with the simulation: `amcl` and `fakelocalize`
//! ([`localize`]) estimate where a robot is, `wavefront` ([`planner`]) plans over the map
//! ([`cspace`], [`search`], [`waypoints`]) and drives the robot ([`steer`]).
//!
//! The drivers a `.cfg` names become devices that carry a [`NavDriver`]; serving attaches
//! their running state to the simulation (one per driver, however many devices show it) as
//! its [`Drivers`], and every step runs the planners before the robots move and the
//! localizers after. The simulation knows them only as [`Drivers`]: this module depends on
//! it, not it on this one.

pub mod cspace;
pub mod frames;
pub mod localize;
pub mod planner;
pub mod search;
pub mod steer;
pub mod waypoints;

use std::any::Any;
use std::sync::Arc;

pub use localize::{LocalizeSettings, Localizer, LocalizerKind};
pub use planner::{Planner, PlannerSettings};

use crate::mapfile::SharedMap;
use crate::sim::{Command, Drivers, Simulation};
use crate::world::Pose;

/// One navigation driver block of a `.cfg`; two are the same when they are the same block.
#[derive(Debug, Clone)]
pub struct NavDriver<T> {
    /// Tells the driver blocks of all the `.cfg` files apart.
    pub id: usize,
    pub spec: Arc<T>,
}

impl<T> PartialEq for NavDriver<T> {
    fn eq(&self, other: &Self) -> bool {
        self.id == other.id
    }
}

impl<T> Eq for NavDriver<T> {}

/// Where a planner reads the robot's pose.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PoseInput {
    /// The robot's odometry (its true pose in the simulation).
    Odometry,
    /// The estimate of the localizer with this driver id (amcl's `position2d`).
    Localizer(usize),
}

/// What a `.cfg`'s wavefront block asks for, with what it requires resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannerSpec {
    pub settings: PlannerSettings,
    /// The robot whose position2d it drives.
    pub robot: usize,
    pub input: PoseInput,
    pub map: SharedMap,
    /// `safety_dist`, `max_radius` (m), `dist_penalty`: the C-space.
    pub safety_dist: f64,
    pub max_radius: f64,
    pub dist_penalty: f64,
}

/// The running navigation drivers of a simulation.
#[derive(Debug, Clone, Default)]
pub struct Navigation {
    pub localizers: Vec<(usize, Localizer)>,
    pub planners: Vec<(usize, Planner, Arc<PlannerSpec>)>,
}

impl Navigation {
    pub fn localizer(&self, id: usize) -> Option<&Localizer> {
        self.localizers
            .iter()
            .find(|(i, _)| *i == id)
            .map(|(_, l)| l)
    }

    pub fn localizer_mut(&mut self, id: usize) -> Option<&mut Localizer> {
        self.localizers
            .iter_mut()
            .find(|(i, _)| *i == id)
            .map(|(_, l)| l)
    }

    pub fn planner(&self, id: usize) -> Option<&Planner> {
        self.planners
            .iter()
            .find(|(i, _, _)| *i == id)
            .map(|(_, p, _)| p)
    }

    pub fn planner_mut(&mut self, id: usize) -> Option<&mut Planner> {
        self.planners
            .iter_mut()
            .find(|(i, _, _)| *i == id)
            .map(|(_, p, _)| p)
    }
}

/// No navigation drivers: what [`Simulation::nav`] shows of a simulation without any.
static NONE: Navigation = Navigation {
    localizers: Vec::new(),
    planners: Vec::new(),
};

impl Drivers for Navigation {
    /// The planners' part of a step, before the robots move.
    fn before_motion(&mut self, sim: &mut Simulation) {
        let t = sim.time;
        for k in 0..self.planners.len() {
            let spec = self.planners[k].2.clone();
            let pose = self.believed_pose(sim, spec.robot, spec.input);
            let told = self.planners[k].1.step(t, pose);
            if let Some((vx, va)) = told {
                sim.robots[spec.robot].command = Command::Velocity { vx, vy: 0.0, va };
            }
        }
    }

    /// The localizers' part of a step, once the robots moved.
    fn after_motion(&mut self, sim: &mut Simulation) {
        for (_, localizer) in &mut self.localizers {
            localizer.step(sim.robots[localizer.settings.robot].pose);
        }
    }

    fn clone_box(&self) -> Box<dyn Drivers> {
        Box::new(self.clone())
    }
}

impl Navigation {
    /// Where a planner reading `input` for `robot` believes the robot is.
    fn believed_pose(&self, sim: &Simulation, robot: usize, input: PoseInput) -> Pose {
        let truth = sim.robots[robot].pose;
        match input {
            PoseInput::Odometry => truth,
            PoseInput::Localizer(id) => self
                .localizer(id)
                .map_or(truth, |l| l.estimate(sim.robots[l.settings.robot].pose)),
        }
    }
}

impl Simulation {
    /// The navigation drivers running with this simulation (none attached: none).
    pub fn nav(&self) -> &Navigation {
        let drivers: &dyn Any = self.drivers.as_ref();
        drivers.downcast_ref::<Navigation>().unwrap_or(&NONE)
    }

    /// [`Simulation::nav`] to change: the simulation's drivers become navigation drivers
    /// (none running) if they were not.
    pub fn nav_mut(&mut self) -> &mut Navigation {
        let drivers: &mut dyn Any = self.drivers.as_mut();
        if !drivers.is::<Navigation>() {
            self.drivers = Box::new(Navigation::default());
        }
        let drivers: &mut dyn Any = self.drivers.as_mut();
        drivers
            .downcast_mut::<Navigation>()
            .expect("navigation drivers were just set")
    }

    /// Starts a localizer for `driver`, unless one runs already.
    pub fn attach_localizer(&mut self, driver: &NavDriver<LocalizeSettings>) {
        if self.nav().localizer(driver.id).is_none() {
            let truth = self.robots[driver.spec.robot].pose;
            let localizer = Localizer::new((*driver.spec).clone(), truth);
            self.nav_mut().localizers.push((driver.id, localizer));
        }
    }

    /// Starts a planner for `driver`, unless one runs already. The robot's radius is half its
    /// width, as wavefront reads it from the position2d geometry.
    pub fn attach_planner(&mut self, driver: &NavDriver<PlannerSpec>) {
        if self.nav().planner(driver.id).is_some() {
            return;
        }
        let spec = &driver.spec;
        let radius = self.world.robots[spec.robot].size[1] / 2.0;
        let space = cspace::CostSpace::new(
            &spec.map.0,
            radius + spec.safety_dist,
            spec.max_radius,
            spec.dist_penalty,
        );
        let planner = Planner::new(spec.settings.clone(), Arc::new(space));
        self.nav_mut()
            .planners
            .push((driver.id, planner, driver.spec.clone()));
    }

    /// Where a planner reading `input` for `robot` believes the robot is.
    pub fn believed_pose(&self, robot: usize, input: PoseInput) -> Pose {
        self.nav().believed_pose(self, robot, input)
    }
}
