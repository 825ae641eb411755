//! A robot's power pack as Stage's world file gives it: `joules` (or `kjoules`) fills it and
//! sets its capacity, `joules_capacity` (or `kjoules_capacity`) makes it bigger than its
//! charge, `watts` is what it burns standing still and `mass` what motion costs, by Stage's
//! rule for position models (10 W per kg per m/s, or per rad/s of turning).

use super::models::Model;
use super::properties::{err, opt_number};
use crate::worldfile::WorldFileError;

/// Stage's position models burn this much at rest when the world file says nothing.
const STAGE_BASE_WATTS: f64 = 1.0;
/// Stage's `mass` when the world file says nothing, kg.
const STAGE_DEFAULT_MASS: f64 = 10.0;
/// Stage's cost of motion: watts per kg per m/s (and per rad/s).
pub const STAGE_WATTS_PER_KG_SPEED: f64 = 10.0;
const JOULES_PER_KILOJOULE: f64 = 1000.0;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatterySpec {
    /// Joules when full.
    pub capacity: f64,
    /// Joules at the start.
    pub stored: f64,
    /// Burnt while standing still.
    pub rest_watts: f64,
    /// kg, for the cost of motion.
    pub mass: f64,
}

impl BatterySpec {
    /// The pack `model` asks for, in the order Stage reads the properties (a later one
    /// overrides), or `None` when it names neither a charge nor a capacity.
    pub(super) fn of(model: &Model) -> Result<Option<BatterySpec>, WorldFileError> {
        let kilo = |name: &str| -> Result<Option<f64>, WorldFileError> {
            Ok(opt_number(model, name)?.map(|k| k * JOULES_PER_KILOJOULE))
        };
        let mut pack: Option<(f64, f64)> = None;
        if let Some(j) = opt_number(model, "joules")? {
            pack = Some((j, j));
        }
        if let Some(c) = opt_number(model, "joules_capacity")? {
            pack = Some((pack.map_or(0.0, |p| p.0), c));
        }
        if let Some(j) = kilo("kjoules")? {
            pack = Some((j, j));
        }
        if let Some(c) = kilo("kjoules_capacity")? {
            pack = Some((pack.map_or(0.0, |p| p.0), c));
        }
        let Some((stored, capacity)) = pack else {
            return Ok(None);
        };
        if capacity <= 0.0 || stored < 0.0 {
            let at = model
                .get("joules")
                .or(model.get("kjoules"))
                .or(model.get("joules_capacity"))
                .or(model.get("kjoules_capacity"))
                .expect("one was read");
            return Err(err(
                &at.pos,
                "a power pack needs a positive capacity and a charge not below zero",
            ));
        }
        Ok(Some(BatterySpec {
            capacity,
            stored: stored.min(capacity),
            rest_watts: opt_number(model, "watts")?.unwrap_or(STAGE_BASE_WATTS),
            mass: opt_number(model, "mass")?.unwrap_or(STAGE_DEFAULT_MASS),
        }))
    }

    /// What the robot burns moving at (forward, sideways, turning) speeds, by Stage's rule.
    pub fn watts(&self, velocity: (f64, f64, f64)) -> f64 {
        let (vx, vy, va) = velocity;
        self.rest_watts + (vx.abs() + vy.abs() + va.abs()) * STAGE_WATTS_PER_KG_SPEED * self.mass
    }
}
