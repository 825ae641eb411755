//! The navigation half of navigation.world driving r0, stepped without a server: wavefront's
//! plan keeps clear of the inflated walls, the robot follows it to the goal, an unreachable
//! goal leaves no plan, a disabled planner does not drive, and a replan follows a new goal.

mod support;

use player_proto::interfaces::planner::PlannerData;
use player_sim::nav::NavDriver;
use player_sim::served::{ServedDevice, Source, attach_navigation, from_cfgs};
use player_sim::sim::Simulation;
use player_sim::world::{Pose, World};

/// r0's planner and localizer, and the simulation running them.
struct Nav {
    sim: Simulation,
    planner: usize,
}

fn navigation() -> (Nav, Vec<ServedDevice>) {
    let dir = support::worlds();
    let world = World::load(&dir.join("navigation.world")).unwrap();
    let (stage, nav) = (dir.join("navigation.cfg"), dir.join("navigation-nav.cfg"));
    let devices = from_cfgs(&[&stage, &nav], &world, &mut Vec::new()).unwrap();
    let mut sim = Simulation::new(world);
    attach_navigation(&mut sim, &devices);
    let planner = devices
        .iter()
        .find_map(|d| match &d.source {
            Source::Planner(NavDriver { id, .. }) => Some(*id),
            _ => None,
        })
        .expect("a planner");
    (Nav { sim, planner }, devices)
}

impl Nav {
    fn goal(&mut self, x: f64, y: f64, a: f64) {
        let planner = self.sim.nav_mut().planner_mut(self.planner).unwrap();
        planner.set_goal(Pose { x, y, a });
    }

    fn state(&self) -> PlannerData {
        self.sim.nav().planner(self.planner).unwrap().data()
    }

    /// Steps until the planner is done, at most `seconds`; the simulated time it took.
    fn run_until_done(&mut self, seconds: f64) -> Option<f64> {
        let start = self.sim.time;
        while self.sim.time - start < seconds {
            self.sim.step();
            if self.state().is_done() {
                return Some(self.sim.time - start);
            }
        }
        None
    }
}

/// In the far room, beyond the doorway and round the end of its wall, facing up; clear of
/// the pucks, which the map does not show.
const GOAL: (f64, f64, f64) = (3.5, 4.5, std::f64::consts::FRAC_PI_2);

#[test]
fn a_goal_across_the_floor_gives_a_clear_path_that_the_robot_follows() {
    let (mut nav, _) = navigation();
    nav.goal(GOAL.0, GOAL.1, GOAL.2);
    nav.sim.step();
    let state = nav.state();
    assert!(state.is_valid() && !state.is_done(), "{state:?}");
    let planner = nav.sim.nav().planner(nav.planner).unwrap();
    let plan = planner.waypoints();
    let space = planner.space.clone();
    assert!(plan.waypoints.len() >= 3, "{plan:?}");
    let first = plan.waypoints[0];
    let last = plan.waypoints.last().unwrap();
    // Wavefront's first waypoint is the robot's own cell, its last the goal's.
    assert!(
        (first.px + 6.5).abs() <= 0.05 && (first.py + 4.5).abs() <= 0.05,
        "{first:?}"
    );
    assert!(
        (last.px - GOAL.0).abs() <= 0.05 && (last.py - GOAL.1).abs() <= 0.05,
        "{last:?}"
    );
    // Every leg keeps the robot's radius plus the safety distance from every wall: sample it.
    for leg in plan.waypoints.windows(2) {
        let length = (leg[1].px - leg[0].px).hypot(leg[1].py - leg[0].py);
        let samples = (length / 0.02).ceil() as usize;
        for s in 0..=samples {
            let f = s as f64 / samples.max(1) as f64;
            let (x, y) = (
                leg[0].px + f * (leg[1].px - leg[0].px),
                leg[0].py + f * (leg[1].py - leg[0].py),
            );
            let (i, j) = space.cell_of(x, y).expect("on the map");
            assert!(
                space.passable(space.index(i, j)),
                "({x:.2}, {y:.2}) too near a wall"
            );
        }
    }
    let sum: f64 = plan
        .waypoints
        .windows(2)
        .map(|w| (w[1].px - w[0].px).hypot(w[1].py - w[0].py))
        .sum();
    assert!((plan.waypoints_distance - sum).abs() < 1e-9);
    assert!(plan.waypoints.iter().all(|w| w.pa == 0.0));

    let took = nav.run_until_done(120.0).expect("the robot arrives");
    let r0 = nav.sim.robots[0].pose;
    assert!(
        (r0.x - GOAL.0).hypot(r0.y - GOAL.1) < 0.5,
        "{r0:?} after {took} s"
    );
    assert!(player_sim::sim::wrap(r0.a - GOAL.2).abs() < 10f64.to_radians());
    assert!(!nav.sim.robots[0].stall);
    // Done: the goal stays, the waypoint and the count go; the plan is still there.
    let done = nav.state();
    assert_eq!((done.valid, done.done), (1, 1));
    assert_eq!((done.waypoint_idx, done.waypoints_count), (0, 0));
    assert_eq!((done.goal.px, done.goal.py), (GOAL.0, GOAL.1));
    let after = nav.sim.nav().planner(nav.planner).unwrap().waypoints();
    assert_eq!(after, plan);
    // And the robot stays put.
    let here = nav.sim.robots[0].pose;
    support::run(&mut nav.sim, 2.0);
    assert_eq!(nav.sim.robots[0].pose, here);
}

#[test]
fn a_goal_inside_a_wall_is_not_valid_and_the_robot_stays() {
    let (mut nav, _) = navigation();
    // The outer wall, and a point beyond the map.
    for (x, y) in [(-7.95, 0.0), (20.0, 0.0)] {
        nav.goal(x, y, 0.0);
        let start = nav.sim.robots[0].pose;
        support::run(&mut nav.sim, 1.0);
        let state = nav.state();
        assert_eq!((state.valid, state.done), (0, 0), "{state:?}");
        assert_eq!((state.goal.px, state.goal.py), (x, y));
        assert_eq!(nav.sim.robots[0].pose, start);
        let plan = nav.sim.nav().planner(nav.planner).unwrap().waypoints();
        assert!(plan.waypoints.is_empty());
    }
}

#[test]
fn a_disabled_planner_does_not_drive_until_enabled() {
    let (mut nav, _) = navigation();
    nav.sim.nav_mut().planner_mut(nav.planner).unwrap().enabled = false;
    nav.goal(-5.0, -3.0, 0.0);
    let start = nav.sim.robots[0].pose;
    support::run(&mut nav.sim, 3.0);
    assert_eq!(nav.sim.robots[0].pose, start);
    assert!(!nav.state().is_valid(), "not planned while disabled");
    nav.sim.nav_mut().planner_mut(nav.planner).unwrap().enabled = true;
    assert!(nav.run_until_done(60.0).is_some());
}

#[test]
fn a_new_goal_on_the_way_is_planned_afresh() {
    let (mut nav, _) = navigation();
    nav.goal(GOAL.0, GOAL.1, GOAL.2);
    support::run(&mut nav.sim, 3.0);
    let moved = nav.sim.robots[0].pose;
    assert!((moved.x + 6.5).hypot(moved.y + 4.5) > 0.3, "{moved:?}");
    nav.goal(-6.5, -4.5, 0.0);
    nav.sim.step();
    let plan = nav.sim.nav().planner(nav.planner).unwrap().waypoints();
    let last = plan.waypoints.last().unwrap();
    assert!((last.px + 6.5).abs() <= 0.05 && (last.py + 4.5).abs() <= 0.05);
    assert!(nav.run_until_done(60.0).is_some());
    let r0 = nav.sim.robots[0].pose;
    assert!((r0.x + 6.5).hypot(r0.y + 4.5) < 0.5);
}
