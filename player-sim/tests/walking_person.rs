//! `person( … )`: people walk their path (or wander), their two legs swing, and a robot's
//! laser sees two leg-sized blobs where they are.

mod support;

use player_sim::sim::{Simulation, ranger_scan};
use player_sim::world::{Walk, World};

fn people() -> Simulation {
    Simulation::new(World::load(&support::worlds().join("people.world")).unwrap())
}

#[test]
fn a_person_walks_the_loop_of_their_path() {
    let mut sim = people();
    assert_eq!(sim.world.people.len(), 2);
    let visitor = &sim.world.people[0];
    assert_eq!(visitor.name, "visitor");
    assert!(matches!(&visitor.walk, Walk::Path(p) if p.len() == 4));
    assert!(
        sim.world.ignored.iter().all(|i| !i.contains("person")),
        "{:?}",
        sim.world.ignored
    );
    let start = (sim.walkers[0].x, sim.walkers[0].y);
    // 5 m up the first leg of the path at 0.5 m/s: 10 s.
    support::run(&mut sim, 10.0);
    let (x, y) = (sim.walkers[0].x, sim.walkers[0].y);
    assert!(
        (x - 0.0).abs() < 0.05 && (y - 2.5).abs() < 0.1,
        "at ({x}, {y}) from {start:?}"
    );
    // The whole loop (5 + 1.5 + 5 + 1.5 m) brings them back (a step is spent on reaching
    // each way-point, so they are a little behind).
    support::run(&mut sim, 16.0);
    let (x, y) = (sim.walkers[0].x, sim.walkers[0].y);
    assert!(
        (x - start.0).hypot(y - start.1) < 0.25,
        "back at ({x}, {y})"
    );
}

#[test]
fn the_legs_swing_about_the_body_and_part_and_meet() {
    let mut sim = people();
    let [left, right] = sim.world.people[0].legs;
    let mut apart = Vec::new();
    for _ in 0..30 {
        sim.step();
        let (a, b) = (
            sim.world.obstacles[left].pose,
            sim.world.obstacles[right].pose,
        );
        apart.push((a.x - b.x).hypot(a.y - b.y));
        let w = &sim.walkers[0];
        let mid = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
        assert!(
            (mid.0 - w.x).hypot(mid.1 - w.y) < 1e-9,
            "the body between its legs"
        );
    }
    let (least, most) = apart
        .iter()
        .fold((f64::MAX, 0.0f64), |(l, m), &d| (l.min(d), m.max(d)));
    assert!(
        least < 0.21 && most > 0.3,
        "legs together {least} and apart {most}"
    );
}

#[test]
fn a_wanderer_stays_near_where_they_started() {
    let mut sim = people();
    let start = sim.world.people[1].start;
    let mut moved = 0.0f64;
    for _ in 0..600 {
        sim.step();
        let w = &sim.walkers[1];
        let from_start = (w.x - start.x).hypot(w.y - start.y);
        assert!(from_start <= 1.0 + 1e-9, "{from_start} m from the start");
        moved = moved.max(from_start);
    }
    assert!(moved > 0.3, "wandered only {moved} m");
}

#[test]
fn the_robots_laser_sees_the_legs() {
    let sim = people();
    let robot = sim.robot_index("r0").unwrap();
    let ranger = sim.world.robots[robot].rangers[0].clone();
    let scan = ranger_scan(&sim, robot, &ranger);
    // The visitor stands at (0, -2.5), 3 m ahead and to the right of r0 at (-3, 0): the
    // beams towards them stop short of the wall behind.
    let toward = (-2.5f64).atan2(3.0);
    let n = scan.len();
    let fov = ranger.sensors[0].fov;
    let index = ((toward + fov / 2.0) / fov * (n - 1) as f64).round() as usize;
    let nearest = scan[index.saturating_sub(3)..(index + 4).min(n)]
        .iter()
        .copied()
        .fold(f64::MAX, f64::min);
    let expected = 3.0f64.hypot(2.5) - 0.1;
    assert!(
        (nearest - expected).abs() < 0.25,
        "nearest {nearest} m, a leg at about {expected}"
    );
}
