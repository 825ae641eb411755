//! A power pack draining as its robot moves: each step burns the pack's watts at the speeds
//! the robot really drove (a stalled robot burns only its rest watts), down to empty.
//! Nothing charges it: player-sim models no chargers.

use super::Simulation;

/// A power pack's charge and what it burnt over the last step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatteryState {
    pub joules: f64,
    pub watts: f64,
}

impl Simulation {
    /// Drains every robot's pack by one step of `dt` seconds.
    pub(super) fn drain_batteries(&mut self, dt: f64) {
        for (spec, state) in self.world.robots.iter().zip(self.robots.iter_mut()) {
            let (Some(spec), Some(battery)) = (spec.battery, state.battery.as_mut()) else {
                continue;
            };
            battery.watts = spec.watts(state.velocity);
            battery.joules = (battery.joules - battery.watts * dt).max(0.0);
        }
    }
}
