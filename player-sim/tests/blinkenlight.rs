//! A blinkenlight on a robot is a body, as in Stage 4.3 (`src/world/blinkenlight.rs`): its
//! 2 cm box stands on the robot, and other robots' rangers at its height meet it.

mod support;

use player_sim::sim::{Simulation, ranger_scan};
use player_sim::world::World;
use support::write;

#[test]
fn a_blinkenlight_is_a_small_box_other_robots_rangers_meet() {
    // As in Stage: every model starts with a box for a block, and the blinkenlight keeps its
    // 2 cm one, standing on the robot's top (0.2 m).
    let dir = tempfile::tempdir().unwrap();
    let lit = write(
        dir.path(),
        "lit.world",
        "position( name \"lit\" pose [ 0 0 0 0 ] size [ 0.4 0.4 0.2 ] blinkenlight( ) )\n\
         position( name \"looker\" pose [ -2 0 0 0 ] size [ 0.4 0.4 0.1 ]\n\
         ranger( pose [ 0 0 0.105 0 ] sensor( range [ 0 5 ] samples 1 ) ) )\n",
    );
    let world = World::load(&lit).unwrap();
    let light = &world.robots[0].mounted_bodies;
    assert_eq!(light.len(), 1);
    assert_eq!((light[0].size, light[0].bottom), ([0.02; 3], 0.2));
    // The looker's beam, at 0.215 m, passes over the lit robot's body and meets the light
    // 1 cm before its centre (within a 2 cm cell).
    let sim = Simulation::new(world);
    let ranger = sim.world.robots[1].rangers[0].clone();
    assert!((ranger.sensors[0].z - 0.215).abs() < 1e-12);
    let d = ranger_scan(&sim, 1, &ranger)[0];
    assert!((d - 1.99).abs() <= 0.02, "{d}");
}
