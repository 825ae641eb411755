//! The simulation behaves as the issue asks: motion from velocity and position commands,
//! collisions that stall, lasers that read the distance to a wall, fiducials with ids and
//! bearings, and the same commands giving the same run.

mod support;

use player_sim::sim::{Command, Simulation, fiducials, ranger_returns, ranger_scan};
use player_sim::world::{Pose, World};
use support::{run, worlds, write};

fn simple() -> Simulation {
    Simulation::new(World::load(&worlds().join("simple.world")).unwrap())
}

#[test]
fn half_a_metre_per_second_for_two_seconds_is_one_metre() {
    let mut sim = simple();
    sim.robots[0].command = Command::Velocity {
        vx: 0.5,
        vy: 0.0,
        va: 0.0,
    };
    run(&mut sim, 2.0);
    let p = sim.robots[0].pose;
    assert!((p.x - (-1.0)).abs() < 0.01 && p.y.abs() < 1e-9, "{p:?}");
    assert!(!sim.robots[0].stall);
}

#[test]
fn a_laser_two_metres_from_a_wall_reads_two_metres() {
    let mut sim = simple();
    // The room's east wall face is at x = 4.8; the laser sits 0.1 m ahead of the robot.
    sim.robots[0].pose = Pose {
        x: 2.7,
        y: 0.0,
        a: 0.0,
    };
    let laser = sim.world.robots[0].rangers[0].clone();
    let scan = ranger_scan(&sim, 0, &laser);
    assert_eq!(scan.len(), 181);
    assert!(
        (scan[90] - 2.0).abs() < 0.02,
        "straight ahead: {}",
        scan[90]
    );
    // 45° to the left the wall is 2/cos(45°) away.
    assert!(
        (scan[135] - 2.0 * std::f64::consts::SQRT_2).abs() < 0.05,
        "{}",
        scan[135]
    );
}

#[test]
fn driving_into_a_wall_stalls() {
    let mut sim = simple();
    sim.robots[0].pose = Pose {
        x: 4.0,
        y: 0.0,
        a: 0.0,
    };
    sim.robots[0].command = Command::Velocity {
        vx: 0.5,
        vy: 0.0,
        va: 0.0,
    };
    run(&mut sim, 3.0);
    assert!(sim.robots[0].stall);
    assert!(
        sim.robots[0].pose.x < 4.8 - 0.2,
        "stopped before the wall: {:?}",
        sim.robots[0].pose
    );
}

#[test]
fn omni_drive_goes_sideways_and_go_to_arrives() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "omni.world",
        "position( name \"o\" drive \"omni\" size [ 0.3 0.3 0.2 ] )\n",
    );
    let mut sim = Simulation::new(World::load(&path).unwrap());
    sim.robots[0].command = Command::Velocity {
        vx: 0.0,
        vy: 0.4,
        va: 0.0,
    };
    run(&mut sim, 1.0);
    assert!((sim.robots[0].pose.y - 0.4).abs() < 1e-9 && sim.robots[0].pose.x.abs() < 1e-9);

    let target = Pose {
        x: 2.0,
        y: -1.0,
        a: 1.0,
    };
    sim.robots[0].command = Command::GoTo { target };
    run(&mut sim, 20.0);
    let p = sim.robots[0].pose;
    assert!(
        (p.x - 2.0).abs() < 0.05 && (p.y + 1.0).abs() < 0.05 && (p.a - 1.0).abs() < 0.05,
        "{p:?}"
    );
}

#[test]
fn fiducials_report_ids_and_bearings() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "fid.world",
        "define finder fiducial ( range_max 8 range_max_id 5 fov 180 )\n\
         position( name \"r\" finder( ) )\n\
         model( name \"a\" pose [ 3 0 0 0 ] size [ 0.3 0.3 0.5 ] fiducial_return 7 )\n\
         model( name \"b\" pose [ 2 2 0 0 ] size [ 0.3 0.3 0.5 ] fiducial_return 8 )\n\
         model( name \"c\" pose [ -3 0 0 0 ] size [ 0.3 0.3 0.5 ] fiducial_return 9 )\n\
         model( name \"d\" pose [ 0 6 0 0 ] size [ 0.3 0.3 0.5 ] fiducial_return 10 )\n",
    );
    let sim = Simulation::new(World::load(&path).unwrap());
    let finder = sim.world.robots[0].fiducials[0].clone();
    let mut hits = fiducials(&sim, 0, &finder);
    hits.sort_by_key(|h| h.id);
    let seen: Vec<(i32, i64)> = hits
        .iter()
        .map(|h| (h.id, h.bearing().to_degrees().round() as i64))
        .collect();
    assert_eq!(
        seen,
        [(0, 90), (7, 0), (8, 45)],
        "9 is behind; 10 is beyond the id range, so id 0"
    );
    assert!((hits[1].range() - 3.0).abs() < 1e-9);
}

#[test]
fn the_same_commands_give_the_same_trajectory() {
    let trajectory = || {
        let mut sim = Simulation::new(World::load(&worlds().join("multirobot.world")).unwrap());
        for (i, r) in sim.robots.iter_mut().enumerate() {
            r.command = Command::Velocity {
                vx: 0.3,
                vy: 0.0,
                va: 0.2 * i as f64,
            };
        }
        run(&mut sim, 5.0);
        sim.robots
            .iter()
            .map(|r| (r.pose.x, r.pose.y, r.pose.a))
            .collect::<Vec<_>>()
    };
    assert_eq!(trajectory(), trajectory());
}

#[test]
fn rangers_report_the_ranger_return_of_what_they_hit_and_see_through_negative_ones() {
    let dir = tempfile::tempdir().unwrap();
    image::GrayImage::from_pixel(800, 800, image::Luma([255]))
        .save(dir.path().join("blank.png"))
        .unwrap();
    // Looking east, north and west (three samples over 180°, first at -90°: south, east,
    // north): a reflector to the east, a glass pane to the north (invisible to rangers),
    // the boundary walls elsewhere.
    let path = write(
        dir.path(),
        "returns.world",
        "floorplan( size [ 8 8 1 ] bitmap \"blank.png\" boundary 1 ranger_return 0.5 )\n\
         model( name \"reflector\" pose [ 2 0 0 0 ] size [ 0.2 1 0.5 ] ranger_return 2 )\n\
         model( name \"glass\" pose [ 0 2 0 0 ] size [ 1 0.2 0.5 ] ranger_return -1 )\n\
         position( name \"r\" pose [ 0 0 0 0 ] ranger( sensor( range [ 0 8 ] fov 180 samples 3 ) ) )\n",
    );
    let world = World::load(&path).unwrap();
    assert!(world.ignored.is_empty(), "{:?}", world.ignored);
    let sim = Simulation::new(world);
    let ranger = sim.world.robots[0].rangers[0].clone();
    let seen = ranger_returns(&sim, 0, &ranger);
    assert_eq!(seen.intensities, vec![0.5, 2.0, 0.5], "{seen:?}");
    assert!(
        (seen.ranges[1] - 1.9).abs() < 0.02,
        "the reflector's face: {seen:?}"
    );
    assert!(
        seen.ranges[2] > 3.9,
        "north sees through the glass to the wall: {seen:?}"
    );
    // The glass still stops robots and shows to cameras: only rangers see through it.
    assert_eq!(sim.world.obstacles.len(), 2);
}
