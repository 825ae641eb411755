//! Stage's `ctrl "wander"`: the wandering robot of navigation.world moves on its own, turns away
//! from walls and robots before it touches them, and does the same again for the same seed.

mod support;

use player_sim::sim::Simulation;
use player_sim::world::{Controller, Pose, World};

/// Simulated seconds the wanderer is watched for.
const WATCHED_SECONDS: f64 = 120.0;

fn navigation() -> Simulation {
    Simulation::new(World::load(&support::worlds().join("navigation.world")).unwrap())
}

/// The wanderer's pose after every step.
fn trajectory(mut sim: Simulation, wanderer: usize) -> Vec<(Pose, bool)> {
    let steps = (WATCHED_SECONDS / sim.world.interval).round() as usize;
    (0..steps)
        .map(|_| {
            sim.step();
            (sim.robots[wanderer].pose, sim.robots[wanderer].stall)
        })
        .collect()
}

#[test]
fn a_wanderer_moves_on_its_own_and_never_runs_into_anything() {
    let sim = navigation();
    let wanderer = sim.robot_index("r1").unwrap();
    assert!(matches!(
        sim.world.robots[wanderer].controller,
        Some(Controller::Wander { ranger: 0 })
    ));
    assert_eq!(sim.world.robots[0].controller, None);
    let start = sim.robots[wanderer].pose;
    let others_start = sim.robots[0].pose;
    let path = trajectory(sim.clone(), wanderer);
    let travelled: f64 = std::iter::once(&(start, false))
        .chain(&path)
        .zip(&path)
        .map(|((a, _), (b, _))| (b.x - a.x).hypot(b.y - a.y))
        .sum();
    assert!(
        travelled > 10.0,
        "only {travelled} m in {WATCHED_SECONDS} s"
    );
    let stalls = path.iter().filter(|(_, stall)| *stall).count();
    assert_eq!(stalls, 0, "it ran into something {stalls} times");
    // Turning away at least once: its heading changed.
    assert!(path.iter().any(|(p, _)| (p.a - start.a).abs() > 0.5));
    // Robots without a controller stay where they are.
    let mut still = sim;
    support::run(&mut still, 5.0);
    assert_eq!(still.robots[0].pose, others_start);
}

#[test]
fn the_same_seed_wanders_the_same_way() {
    let sim = navigation();
    let wanderer = sim.robot_index("r1").unwrap();
    let once = trajectory(sim.clone(), wanderer);
    let again = trajectory(sim.clone(), wanderer);
    assert_eq!(once, again);
}

#[test]
fn a_wanderer_without_a_scanning_ranger_is_an_error_at_its_ctrl() {
    let dir = tempfile::tempdir().unwrap();
    let path = support::write(
        dir.path(),
        "blind.world",
        "define sonar ranger ( sensor( range [ 0 5 ] fov 15 samples 1 ) )\n\
         position\n(\n  name \"r0\"\n  sonar( )\n  ctrl \"wander\"\n)\n\
         position ( name \"r1\" ctrl \"follow\" )\n",
    );
    let err = World::load(&path).unwrap_err().to_string();
    assert!(
        err.starts_with(&format!("{}:6:", path.display())) && err.contains("more than 8"),
        "{err}"
    );
    let fine = support::write(
        dir.path(),
        "other.world",
        "position ( name \"r1\" ctrl \"follow\" )\n",
    );
    let world = World::load(&fine).unwrap();
    assert_eq!(world.robots[0].controller, None);
    assert!(
        world.ignored.iter().any(|n| n.contains("ctrl \"follow\"")),
        "{:?}",
        world.ignored
    );
}
