//! A robot's power pack served as Player's `power` interface: charge in percent and joules,
//! the watts burnt over the last step, a nominal voltage, and "not charging" (no chargers are
//! simulated). Stage's own plugin for this interface was never ported to Stage 4, so the
//! fields follow Player's `power` documentation rather than a Stage driver.

use player_proto::interfaces::power::{
    MASK_CHARGING, MASK_JOULES, MASK_PERCENT, MASK_VOLTS, MASK_WATTS, PowerData,
};

use crate::sim::Simulation;

/// What a 12 V lead-acid pack (a Pioneer's) reports; Stage's power packs have no voltage.
const NOMINAL_VOLTS: f32 = 12.0;
const FULL_PERCENT: f64 = 100.0;
/// Player's `charging`: 0 is neither charging nor discharging into something else.
const NOT_CHARGING: i32 = 0;

/// The pack of `robot`, or an empty message with no valid field when it has none.
pub(super) fn data(sim: &Simulation, robot: usize) -> PowerData {
    let (Some(spec), Some(state)) = (sim.world.robots[robot].battery, sim.robots[robot].battery)
    else {
        return PowerData::default();
    };
    PowerData {
        valid: MASK_VOLTS | MASK_WATTS | MASK_JOULES | MASK_PERCENT | MASK_CHARGING,
        volts: NOMINAL_VOLTS,
        percent: (state.joules / spec.capacity * FULL_PERCENT) as f32,
        joules: state.joules as f32,
        // Player's sign: negative is consuming.
        watts: -state.watts as f32,
        charging: NOT_CHARGING,
    }
}
