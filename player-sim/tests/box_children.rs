//! The models a plain model carries stand on it as Stage stacks them (fasr.world's charging
//! stations: a low base, two tall posts, a charging plate showing fiducial 2): a ranger above
//! the base meets the posts, a fiducial finder sees the plate, and a robot bumps into them.

mod support;

use player_sim::sim::{Command, Simulation, fiducials, ranger_scan};
use player_sim::world::{Pose, World};
use support::{run, write};

const STATION: &str = "\
define station model
(
  size [ 0.1 0.3 0.1 ]
  model( name \"post\" size [ 0.1 0.05 0.25 ] pose [ 0 0.1 0 0 ] )
  model( size [ 0.05 0.2 0.1 ] pose [ 0.01 0 0 0 ] fiducial_return 2 ranger( ) )
)
station( name \"s\" pose [ 2 0 0 180 ] )
position( name \"r\" pose [ 0 0.1 0 0 ] size [ 0.4 0.4 0.2 ]
  ranger( sensor( range [ 0 5 ] fov 0 samples 1 pose [ 0 0 0.1 0 ] ) )
  fiducial( range_max 5 )
)
";

#[test]
fn a_models_children_stand_on_it_are_sensed_and_stop_robots() {
    let dir = tempfile::tempdir().unwrap();
    let world = World::load(&write(dir.path(), "station.world", STATION)).unwrap();
    // The base, the named post and Stage's name for the unnamed plate.
    let names: Vec<&str> = world.obstacles.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["s", "post", "s.model:1"]);
    // The post, turned with the station, stands at (2, -0.1) from the floor to 0.35 m.
    let post = &world.obstacles[1];
    assert!((post.pose.x - 2.0).abs() < 1e-9 && (post.pose.y + 0.1).abs() < 1e-9);
    assert!((post.size[2] - 0.35).abs() < 1e-9, "{:?}", post.size);
    assert!(
        world
            .ignored
            .iter()
            .any(|n| n.contains("a ranger on a model"))
    );

    let mut sim = Simulation::new(world);
    // The ranger, 0.31 m up (above the base's 0.1 m), facing the station across y = -0.1:
    // it meets the post's near face at x = 1.95, within a cell of Stage's 2 cm raster (the
    // face's cell starts at 1.94).
    sim.robots[0].pose = Pose {
        x: 0.0,
        y: -0.1,
        a: 0.0,
    };
    let ranger = sim.world.robots[0].rangers[0].clone();
    let reading = ranger_scan(&sim, 0, &ranger)[0];
    assert!((reading - 1.95).abs() < 0.02, "{reading}");
    let finder = sim.world.robots[0].fiducials[0].clone();
    assert!(fiducials(&sim, 0, &finder).iter().any(|h| h.id == 2));

    sim.robots[0].command = Command::Velocity {
        vx: 0.5,
        vy: 0.0,
        va: 0.0,
    };
    run(&mut sim, 6.0);
    assert!(sim.robots[0].stall, "stopped by the station");
    assert!(sim.robots[0].pose.x < 1.8, "{:?}", sim.robots[0].pose);
}

#[test]
fn robots_drive_over_a_zone_that_is_no_obstacle() {
    let dir = tempfile::tempdir().unwrap();
    // Stage's map.inc zone: on the floor, no obstacle, transparent to rangers.
    let text = "\
        define zone model ( size [ 2 2 0.01 ] obstacle_return 0 ranger_return -1 )\n\
        zone( name \"source\" pose [ 1.5 0 0 0 ] )\n\
        model( name \"wall\" pose [ 4 0 0 0 ] size [ 0.2 2 0.5 ] )\n\
        position( name \"r\" size [ 0.4 0.4 0.2 ] )\n";
    let mut sim = Simulation::new(World::load(&write(dir.path(), "zone.world", text)).unwrap());
    assert!(!sim.world.obstacles[0].obstacle_return && sim.world.obstacles[1].obstacle_return);
    sim.robots[0].command = Command::Velocity {
        vx: 0.5,
        vy: 0.0,
        va: 0.0,
    };
    run(&mut sim, 10.0);
    // Across the zone, stopped by the wall behind it (its face at x = 3.9).
    assert!(sim.robots[0].stall);
    let x = sim.robots[0].pose.x;
    assert!(x > 3.6 && x < 3.71, "{x}");
}
