//! Reading Stage world files: our stage-worlds load; blocks, nested sensors, defines, colours
//! and origins are read as Stage reads them (faults in a world file: `world_errors.rs`).

mod support;

use player_sim::sim::{Command, Simulation, ranger_scan, ranger_scan_exhaustive};
use player_sim::world::{Pose, World};
use support::{run, worlds, write};

#[test]
fn every_example_world_loads_without_ignored_parts() {
    for (name, robots) in [
        ("simple.world", 1),
        ("multirobot.world", 5),
        ("classroom.world", 8),
        ("swarm.world", 256),
        ("blocks.world", 1),
    ] {
        let world = World::load(&worlds().join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(world.robots.len(), robots, "{name}");
        assert!(world.floor.is_some(), "{name}");
        assert!(world.ignored.is_empty(), "{name}: {:?}", world.ignored);
        assert!((world.interval - 0.1).abs() < 1e-12);
    }
    let multi = World::load(&worlds().join("multirobot.world")).unwrap();
    let r0 = &multi.robots[0];
    assert_eq!(r0.rangers.len(), 2);
    assert!(r0.rangers[0].is_laser_like() && r0.rangers[0].sensors[0].samples == 181);
    assert_eq!(r0.rangers[1].sensors.len(), 8, "the sonar ring");
    assert_eq!(
        (r0.fiducials.len(), r0.cameras.len(), r0.fiducial_id),
        (1, 1, Some(100))
    );
    assert_eq!(multi.obstacles.len(), 3);
}

#[test]
fn a_floorplan_drawn_with_blocks_stops_lasers_and_robots() {
    let world = World::load(&worlds().join("blocks.world")).unwrap();
    assert!(world.floorplan.is_none(), "no bitmap for a viewer");
    assert_eq!(world.floor_blocks.len(), 5);
    assert!((world.resolution - 0.02).abs() < 1e-12);
    assert!((world.floor_height - 0.8).abs() < 1e-12);
    // The robot's pointed block, stretched over 0.44 x 0.38 m: its tip at the front.
    let r0 = &world.robots[0];
    assert_eq!(r0.shape.len(), 1);
    assert!((r0.shape[0][2][0] - 0.22).abs() < 1e-12 && r0.shape[0][2][1].abs() < 1e-12);
    let crate_ = &world.obstacles[0];
    assert_eq!((crate_.name.as_str(), crate_.shape[0].len()), ("crate", 3));
    assert_eq!(crate_.shape[0][0], [-0.3, -0.3]);

    let mut sim = Simulation::new(world);
    let laser = sim.world.robots[0].rangers[0].clone();
    let scan = ranger_scan(&sim, 0, &laser);
    // From (0.1, 0) the east wall's face (x = 4.8) is 4.7 m ahead, the north one 3.8 m left.
    assert!((scan[90] - 4.7).abs() <= 0.03, "ahead: {}", scan[90]);
    assert!((scan[180] - 3.8).abs() <= 0.03, "left: {}", scan[180]);
    // Facing north under the L's bar (y = 1.0): 0.9 m from the laser.
    sim.robots[0].pose = Pose {
        x: -2.0,
        y: 0.0,
        a: std::f64::consts::FRAC_PI_2,
    };
    let scan = ranger_scan(&sim, 0, &laser);
    assert!(
        (scan[90] - 0.9).abs() <= 0.03,
        "the partition: {}",
        scan[90]
    );
    sim.robots[0].command = Command::Velocity {
        vx: 0.5,
        vy: 0.0,
        va: 0.0,
    };
    run(&mut sim, 2.0);
    assert!(sim.robots[0].stall, "drove into the partition");
    // The robot's front (0.22 m ahead of its centre) stops short of the bar's face.
    let y = sim.robots[0].pose.y;
    assert!(y > 0.6 && y < 1.0 - 0.19, "{y}");
}

#[test]
fn sensors_mounted_on_models_on_a_robot_compose_their_poses() {
    let dir = tempfile::tempdir().unwrap();
    let nested = write(
        dir.path(),
        "nested.world",
        "position( name \"r\" size [ 0.4 0.4 0.2 ]\n\
         model( name \"mast\" pose [ 0.1 0 0 90 ] size [ 0.1 0.1 0.5 ]\n\
         ranger( pose [ 0.2 0 0.05 0 ] sensor( range [ 0 4 ] fov 90 samples 9 ) )\n\
         model( pose [ 0 0 0 0 ] size [ 0.05 0.05 0.1 ] camera( pose [ 0 0 0.02 0 ] ) ) ) )\n",
    );
    let world = World::load(&nested).unwrap();
    let r = &world.robots[0];
    assert_eq!((r.rangers.len(), r.cameras.len()), (1, 1));
    let p = r.rangers[0].pose;
    // 0.2 m ahead of a mast turned 90° left and 0.1 m forward: (0.1, 0.2), facing left.
    assert!(
        (p.x - 0.1).abs() < 1e-12
            && (p.y - 0.2).abs() < 1e-12
            && (p.a - std::f64::consts::FRAC_PI_2).abs() < 1e-12,
        "{p:?}"
    );
    // The camera stands on the robot (0.2), the mast (0.5) and its own model (0.1).
    assert!(
        (r.cameras[0].height - 0.82).abs() < 1e-12,
        "{}",
        r.cameras[0].height
    );
    // The ranger's beams: on the robot (0.2), the mast (0.5), 0.05 up, half a sensor (0.01).
    let z = r.rangers[0].sensors[0].z;
    assert!((z - 0.76).abs() < 1e-12, "{z}");
    // The mast and the camera's model are solid, each between its underside and its top.
    let bodies: Vec<(f64, f64)> = r
        .mounted_bodies
        .iter()
        .map(|b| (b.bottom, b.bottom + b.size[2]))
        .collect();
    assert_eq!(bodies.len(), 2, "{bodies:?}");
    assert!((bodies[0].0 - 0.2).abs() < 1e-12 && (bodies[0].1 - 0.7).abs() < 1e-12);
    assert!((bodies[1].0 - 0.7).abs() < 1e-12 && (bodies[1].1 - 0.8).abs() < 1e-12);
}

#[test]
fn boxes_and_robots_drawn_with_blocks_are_solid_where_their_blocks_are() {
    let mut sim = Simulation::new(World::load(&worlds().join("blocks.world")).unwrap());
    // The crate at (2, -2) is the south-west half of its 0.6 m box: its slope is x + y = 0.
    // Facing south along x = 2 the laser (0.1 m ahead) meets the slope at y = -2, not the
    // box's north face at y = -1.7 (within a cell: rangers meet the slope's cells on Stage's
    // 2 cm raster; the robot a quarter cell east of x = 2, so that the beam does not run
    // along a border between cells, where the last bit of its direction picks the column).
    sim.robots[0].pose = Pose {
        x: 2.005,
        y: -0.5,
        a: -std::f64::consts::FRAC_PI_2,
    };
    let laser = sim.world.robots[0].rangers[0].clone();
    let scan = ranger_scan(&sim, 0, &laser);
    assert!((scan[90] - 1.4).abs() < 0.021, "{}", scan[90]);
    // As every box tested against every beam gives it (the scan's beam directions are
    // rotated, not each taken by its sine and cosine: equal to a micrometre's millionth).
    let exhaustive = ranger_scan_exhaustive(&sim, 0, &laser);
    assert_eq!(scan.len(), exhaustive.len());
    for (a, b) in scan.iter().zip(&exhaustive) {
        assert!((a - b).abs() < 1e-9, "{a} vs {b}");
    }
    // Driving south along x = 2, the robot's wedge meets the slope with its front corner
    // (x = 1.81, 0.11 m ahead of its centre) where the slope is at y = -1.81: later than its
    // box would meet the crate's box (centre at y = -1.48).
    sim.robots[0].pose.x = 2.0;
    sim.robots[0].command = Command::Velocity {
        vx: 0.5,
        vy: 0.0,
        va: 0.0,
    };
    run(&mut sim, 3.0);
    assert!(sim.robots[0].stall);
    let y = sim.robots[0].pose.y;
    assert!(y < -1.6 && y > -1.7, "{y}");
}

#[test]
fn sensors_defined_from_sensor_are_read_as_stage_pioneer_inc_writes_them() {
    let dir = tempfile::tempdir().unwrap();
    let world = write(
        dir.path(),
        "sonar.world",
        "define transducer sensor ( range [ 0 3 ] fov 15 samples 1 )\n\
         define nose transducer ( pose [ 0.2 0 0 0 ] )\n\
         define ring ranger ( transducer( pose [ 0 0.1 0 90 ] ) nose( view [ 1 2 30 ] ) )\n\
         position( name \"r\" ring( ) )\n",
    );
    let world = World::load(&world).unwrap();
    let sensors = &world.robots[0].rangers[0].sensors;
    assert_eq!(sensors.len(), 2);
    assert!(sensors.iter().all(|s| s.max_range == 3.0 && s.samples == 1));
    assert!((sensors[0].pose.a - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    assert!((sensors[1].pose.x - 0.2).abs() < 1e-12, "the define's pose");
    let notes = world.ignored.join("\n");
    assert!(
        notes.contains("ignored: sensor property view at") && notes.contains("sonar.world:3"),
        "{notes}"
    );
}

#[test]
fn random_colours_differ_per_model_and_stay_the_same_per_run() {
    let dir = tempfile::tempdir().unwrap();
    let world = write(
        dir.path(),
        "random.world",
        "define flocker position ( color \"random\" )\n\
         flocker( name \"a\" )\nflocker( name \"b\" )\nflocker( name \"c\" color \"gray90\" )\n",
    );
    let first = World::load(&world).unwrap();
    let colours: Vec<[u8; 3]> = first.robots.iter().map(|r| r.color).collect();
    assert_ne!(colours[0], colours[1]);
    assert_eq!(colours[2], [229, 229, 229]);
    let again = World::load(&world).unwrap();
    assert_eq!(again.robots[0].color, colours[0]);
}

#[test]
fn boundary_walls_keep_robots_on_the_floorplan() {
    let dir = tempfile::tempdir().unwrap();
    // A blank 6 x 4 m floorplan (1 cm pixels) centred on (1, 0): no walls but its boundary.
    image::GrayImage::from_pixel(600, 400, image::Luma([255]))
        .save(dir.path().join("blank.png"))
        .unwrap();
    let text = |boundary: u8| {
        format!(
            "floorplan( size [ 6 4 1 ] pose [ 1 0 0 0 ] bitmap \"blank.png\" boundary {boundary} )\n\
             position( name \"r\" ranger( pose [ 0.1 0 0 0 ] sensor( range [ 0 8 ] fov 180 samples 3 ) ) )\n"
        )
    };
    let walled = World::load(&write(dir.path(), "walled.world", &text(1))).unwrap();
    assert!(walled.ignored.is_empty(), "{:?}", walled.ignored);
    assert_eq!(walled.floor_blocks.len(), 4);
    let sim = Simulation::new(walled);
    let ranger = sim.world.robots[0].rangers[0].clone();
    let scan = ranger_scan(&sim, 0, &ranger);
    // East: the wall's inner face is 1 cm inside x = 4; south and north 1 cm inside y = ±2.
    assert!((scan[1] - 3.89).abs() <= 0.011, "{scan:?}");
    assert!(
        (scan[0] - 1.99).abs() <= 0.011 && (scan[2] - 1.99).abs() <= 0.011,
        "{scan:?}"
    );
    let open = World::load(&write(dir.path(), "open.world", &text(0))).unwrap();
    let sim = Simulation::new(open);
    assert_eq!(ranger_scan(&sim, 0, &ranger), vec![8.0, 8.0, 8.0]);
}

#[test]
fn a_low_block_is_reported_as_solid_at_every_height() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "curb.world",
        "floorplan( size [ 4 4 1 ]\n\
         block( points 4 point[0] [ 0 0 ] point[1] [ 4 0 ] point[2] [ 4 1 ] point[3] [ 0 1 ] z [ 0 1 ] )\n\
         block( points 4 point[0] [ 0 3 ] point[1] [ 4 3 ] point[2] [ 4 4 ] point[3] [ 0 4 ] z [ 0 0.1 ] ) )\n",
    );
    let world = World::load(&path).unwrap();
    assert_eq!(
        world.ignored,
        vec![format!(
            "ignored: a block not as tall as the rest of floorplan (solid at every height to collisions and cameras) at {}:3",
            path.display()
        )]
    );
    assert!(
        world.floor.unwrap().occupied_at(0.0, 1.8),
        "the curb is drawn"
    );
}

#[test]
fn a_body_shifted_by_origin_collides_where_it_is() {
    let dir = tempfile::tempdir().unwrap();
    // A room whose east wall's face is at x = 1.8; a 0.4 m robot whose body lies 0.1 m ahead
    // of the point it turns about (origin [ 0.1 0 0 0 ]).
    let path = write(
        dir.path(),
        "origin.world",
        "floorplan( size [ 4 4 1 ]\n\
         block( points 4 point[0] [ 3.8 0 ] point[1] [ 4 0 ] point[2] [ 4 4 ] point[3] [ 3.8 4 ] )\n\
         block( points 4 point[0] [ 0 0 ] point[1] [ 0.2 0 ] point[2] [ 0.2 4 ] point[3] [ 0 4 ] ) )\n\
         position( name \"r\" size [ 0.4 0.4 0.2 ] origin [ 0.1 0 0 0 ] )\n",
    );
    let world = World::load(&path).unwrap();
    assert!(world.ignored.is_empty(), "{:?}", world.ignored);
    let mut sim = Simulation::new(world);
    sim.robots[0].command = Command::Velocity {
        vx: 0.5,
        vy: 0.0,
        va: 0.0,
    };
    run(&mut sim, 4.0);
    assert!(sim.robots[0].stall);
    // The body's front is 0.3 m ahead of the pose: it stops 0.3 m short of the face.
    let x = sim.robots[0].pose.x;
    assert!(x <= 1.5 + 1e-9 && x > 1.4, "{x}");
}
