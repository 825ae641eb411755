//! Drivers stepped with the simulation that are not part of it: Player's navigation drivers,
//! which a served `.cfg` starts, steer robots before they move and watch them after. The
//! simulation knows them only through this trait, so that it depends on nothing above it
//! (`nav` and `served` depend on the simulation, never the other way).

use std::any::Any;
use std::fmt::Debug;

use super::Simulation;

/// What runs with every step of a [`Simulation`], beside its robots. `Sync`: a step's scans
/// read the simulation, drivers included, from several threads.
pub trait Drivers: Any + Debug + Send + Sync {
    /// Before the robots move: may change their commands.
    fn before_motion(&mut self, sim: &mut Simulation);
    /// Once the robots moved.
    fn after_motion(&mut self, sim: &mut Simulation);
    /// A copy, for a cloned simulation.
    fn clone_box(&self) -> Box<dyn Drivers>;
}

/// No drivers: a simulation on its own.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoDrivers;

impl Drivers for NoDrivers {
    fn before_motion(&mut self, _: &mut Simulation) {}

    fn after_motion(&mut self, _: &mut Simulation) {}

    fn clone_box(&self) -> Box<dyn Drivers> {
        Box::new(NoDrivers)
    }
}

impl Clone for Box<dyn Drivers> {
    fn clone(&self) -> Self {
        self.clone_box()
    }
}

impl Simulation {
    /// Runs `phase` of the drivers, which are taken out of the simulation meanwhile (so that
    /// they may change it).
    pub(super) fn run_drivers(&mut self, phase: fn(&mut dyn Drivers, &mut Simulation)) {
        let mut drivers = std::mem::replace(&mut self.drivers, Box::new(NoDrivers));
        phase(drivers.as_mut(), self);
        self.drivers = drivers;
    }
}
