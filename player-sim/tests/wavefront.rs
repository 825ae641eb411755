//! wavefront's planning on small hand-drawn maps: obstacles grown by the robot's radius and
//! safety distance, walled-in goals, unknown cells counted as obstacles, the path thinned to
//! the cells in sight of each other, and a replan once the robot has strayed far enough.

use std::sync::Arc;

use player_sim::mapfile::GridMap;
use player_sim::nav::cspace::CostSpace;
use player_sim::nav::search::find_path;
use player_sim::nav::waypoints::{in_sight, thin};
use player_sim::nav::{Planner, PlannerSettings};
use player_sim::world::Pose;

const FREE: i8 = -1;
const UNKNOWN: i8 = 0;
const OCCUPIED: i8 = 1;
/// 0.1 m cells, the map's corner at the origin.
const SCALE: f64 = 0.1;

/// A `w` × `h` room walled round, with `wall` cells drawn in.
fn room(w: u32, h: u32, wall: impl Fn(u32, u32) -> bool) -> GridMap {
    let mut cells = Vec::new();
    for j in 0..h {
        for i in 0..w {
            let border = i == 0 || j == 0 || i == w - 1 || j == h - 1;
            cells.push(if border || wall(i, j) { OCCUPIED } else { FREE });
        }
    }
    GridMap::from_cells(w, h, SCALE, (0.0, 0.0), cells).unwrap()
}

/// 40 × 30 cells with a wall across x = 2 m from the bottom up to y = 2 m: a way round the top.
fn partition() -> CostSpace {
    CostSpace::new(&room(40, 30, |i, j| i == 20 && j < 20), 0.3, 0.6, 1.0)
}

fn plan(space: &CostSpace, from: (f64, f64), to: (f64, f64)) -> Option<Vec<usize>> {
    let a = space.cell_of(from.0, from.1)?;
    let b = space.cell_of(to.0, to.1)?;
    find_path(space, a, b)
}

#[test]
fn obstacles_grow_by_the_radius_and_unknown_is_an_obstacle() {
    let space = partition();
    let at = |x: f64, y: f64| {
        let (i, j) = space.cell_of(x, y).unwrap();
        space.index(i, j)
    };
    assert!(!space.passable(at(2.0, 1.0)), "the wall");
    assert!(!space.passable(at(1.8, 1.0)), "0.2 m from it");
    assert!(space.passable(at(1.6, 1.0)), "0.4 m from it");
    assert!(space.proximity_cost(at(1.6, 1.0)) > 0.0, "but near");
    assert_eq!(space.proximity_cost(at(1.0, 1.5)), 0.0, "a metre off");
    let mut cells = vec![FREE; 100];
    cells[55] = UNKNOWN;
    let fog = GridMap::from_cells(10, 10, SCALE, (0.0, 0.0), cells).unwrap();
    let fog = CostSpace::new(&fog, 0.15, 0.6, 1.0);
    assert!(!fog.passable(fog.index(5, 5)) && !fog.passable(fog.index(6, 5)));
    assert!(fog.passable(fog.index(8, 5)));
}

#[test]
fn the_path_goes_round_the_wall_and_its_waypoints_see_each_other() {
    let space = partition();
    let path = plan(&space, (1.0, 0.5), (3.0, 0.5)).expect("a way round");
    assert!(path.iter().all(|&k| space.passable(k)));
    let top = path.iter().map(|&k| space.cell_at(k).1).max().unwrap();
    assert!(top >= 23, "passes above the wall's grown end: row {top}");
    let waypoints = thin(&space, &path);
    assert_eq!(waypoints.first(), path.first());
    assert_eq!(waypoints.last(), path.last());
    assert!(
        waypoints.len() >= 3 && waypoints.len() < path.len() / 4,
        "{waypoints:?}"
    );
    for leg in waypoints.windows(2) {
        assert!(in_sight(&space, leg[0], leg[1]));
    }
    let (a, b) = (
        space.cell_of(1.0, 0.5).unwrap(),
        space.cell_of(3.0, 0.5).unwrap(),
    );
    assert!(!in_sight(
        &space,
        space.index(a.0, a.1),
        space.index(b.0, b.1)
    ));
}

#[test]
fn a_walled_in_goal_or_one_off_the_map_has_no_path() {
    // A closed box round (3, 2).
    let boxed = room(40, 30, |i, j| {
        (i == 25 || i == 35) && (10..=25).contains(&j)
            || (j == 10 || j == 25) && (25..=35).contains(&i)
    });
    let space = CostSpace::new(&boxed, 0.2, 0.6, 1.0);
    assert!(plan(&space, (1.0, 1.0), (3.0, 1.7)).is_none());
    assert!(space.cell_of(10.0, 1.0).is_none());
    // The start cell is never in the way: a robot against the wall plans out.
    assert!(plan(&space, (0.15, 0.15), (1.0, 1.0)).is_some());
}

fn settings(replan: f64) -> PlannerSettings {
    PlannerSettings {
        dist_eps: 0.3,
        ang_eps: 10f64.to_radians(),
        replan_dist: replan,
        replan_time: 0.0,
        rotational_waypoints: true,
    }
}

#[test]
fn a_robot_that_strays_gets_a_new_plan_from_where_it_is() {
    let space = Arc::new(partition());
    let mut planner = Planner::new(settings(1.0), space);
    let start = Pose {
        x: 1.0,
        y: 0.5,
        a: 0.0,
    };
    planner.set_goal(Pose {
        x: 3.0,
        y: 0.5,
        a: 0.0,
    });
    planner.step(0.0, start);
    let first = planner.waypoints().waypoints[0];
    assert!((first.px - 1.0).abs() < 1e-9 && (first.py - 0.5).abs() < 1e-9);
    // Pushed 1.2 m away: more than replan_dist_thresh from the last plan.
    let pushed = Pose {
        x: 1.0,
        y: 1.7,
        a: 0.0,
    };
    planner.step(0.1, pushed);
    let again = planner.waypoints().waypoints[0];
    assert!((again.px - 1.0).abs() < 1e-9 && (again.py - 1.7).abs() < 1e-9);
    // With replanning off, the old plan stays.
    let mut fixed = Planner::new(settings(-1.0), Arc::new(partition()));
    fixed.set_goal(Pose {
        x: 3.0,
        y: 0.5,
        a: 0.0,
    });
    fixed.step(0.0, start);
    fixed.step(0.1, pushed);
    assert!((fixed.waypoints().waypoints[0].py - 0.5).abs() < 1e-9);
}

#[test]
fn the_state_counts_waypoints_as_wavefront_does() {
    let mut planner = Planner::new(settings(-1.0), Arc::new(partition()));
    let before = planner.data();
    assert_eq!(
        (before.valid, before.done, before.waypoints_count),
        (0, 0, 0)
    );
    let start = Pose {
        x: 0.5,
        y: 0.5,
        a: 0.0,
    };
    planner.set_goal(Pose {
        x: 1.5,
        y: 0.5,
        a: 0.0,
    });
    // The first cycle takes waypoint 0 (the robot's own cell): the index after it is 1.
    planner.step(0.0, start);
    let first = planner.data();
    assert_eq!((first.valid, first.done), (1, 0));
    assert_eq!(first.waypoint_idx, 1);
    // Standing on it, the next cycle moves on to the goal's cell, index 2 of 2.
    planner.step(0.1, start);
    let second = planner.data();
    assert_eq!((second.waypoint_idx, second.waypoints_count), (2, 2));
    assert_eq!(
        second.waypoint.pa, 0.0,
        "a waypoint carries the goal's heading"
    );
}
