//! Rangers sense at their height, as Stage's do: a beam passes over what stands lower than the
//! sensor, and meets a table's legs below its top and its top at the top's height.

mod support;

use player_sim::sim::{Simulation, ranger_scan};
use support::write;

/// A robot 0.2 m tall facing east with a one-beam ranger `z` up on its top (beam at z + 0.2 +
/// 0.01), and `ahead` written 2 m east of it.
fn beam_to(ahead: &str, z: f64) -> f64 {
    let dir = tempfile::tempdir().unwrap();
    let world = write(
        dir.path(),
        "h.world",
        &format!(
            "position( name \"r\" pose [ 0 0 0 0 ] size [ 0.2 0.2 0.2 ]\n\
             ranger( pose [ 0 0 {z} 0 ] sensor( range [ 0 5 ] fov 0 samples 1 ) ) )\n{ahead}\n"
        ),
    );
    let sim = Simulation::new(player_sim::world::World::load(&world).unwrap());
    ranger_scan(&sim, 0, &sim.world.robots[0].rangers[0].clone())[0]
}

#[test]
fn a_beam_passes_over_a_box_lower_than_the_sensor() {
    let low = "model( name \"low\" pose [ 2 0 0 0 ] size [ 0.4 0.4 0.15 ] )";
    let tall = "model( name \"tall\" pose [ 2 0 0 0 ] size [ 0.4 0.4 0.5 ] )";
    assert_eq!(beam_to(low, 0.0), 5.0, "over the low box");
    assert!(
        (beam_to(tall, 0.0) - 1.8).abs() < 1e-9,
        "the tall box's face"
    );
}

#[test]
fn a_table_is_met_by_its_legs_below_its_top_and_by_its_top_above() {
    // 1 m square, 0.8 m tall: a top from 0.75 m, four legs 10 cm square at its corners; the
    // beam runs between the legs.
    let table = "model( name \"table\" pose [ 2.5 0 0 0 ] size [ 1 1 0.8 ]\n\
        block( points 4 point[0] [ 0 0 ] point[1] [ 10 0 ] point[2] [ 10 10 ] point[3] [ 0 10 ] z [ 7.5 8 ] )\n\
        block( points 4 point[0] [ 0 0 ] point[1] [ 1 0 ] point[2] [ 1 1 ] point[3] [ 0 1 ] z [ 0 7.5 ] )\n\
        block( points 4 point[0] [ 9 0 ] point[1] [ 10 0 ] point[2] [ 10 1 ] point[3] [ 9 1 ] z [ 0 7.5 ] )\n\
        block( points 4 point[0] [ 0 9 ] point[1] [ 1 9 ] point[2] [ 1 10 ] point[3] [ 0 10 ] z [ 0 7.5 ] )\n\
        block( points 4 point[0] [ 9 9 ] point[1] [ 10 9 ] point[2] [ 10 10 ] point[3] [ 9 10 ] z [ 0 7.5 ] ) )";
    assert_eq!(beam_to(table, 0.0), 5.0, "between the legs, under the top");
    let top = beam_to(table, 0.57);
    assert!((top - 2.0).abs() < 1e-9, "the top's edge: {top}");
}
