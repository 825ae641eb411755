//! A path of cells thinned to waypoints as Player's wavefront thins it: from each waypoint,
//! walk along the path and keep going while the next cell is in sight (a straight line
//! through passable cells only); the last cell in sight is the next waypoint. Cells less than
//! half a metre along are taken without looking, so waypoints are never closer than that
//! unless the path ends.

use super::cspace::CostSpace;

/// Path length walked before line of sight is tested (Player's fixed half metre).
const LOOK_AHEAD: f64 = 0.5;

/// The waypoints (cell indices) of a path from the start cell to the goal cell.
pub fn thin(space: &CostSpace, path: &[usize]) -> Vec<usize> {
    let Some(&first) = path.first() else {
        return Vec::new();
    };
    let last = path.len() - 1;
    let mut waypoints = vec![first];
    let mut at = 0;
    while at < last {
        let mut walked = 0.0;
        let mut reach = at;
        while reach < last {
            if walked > LOOK_AHEAD && !in_sight(space, path[at], path[reach + 1]) {
                break;
            }
            walked += space.scale;
            reach += 1;
        }
        if reach == at {
            break;
        }
        at = reach;
        waypoints.push(path[at]);
    }
    waypoints
}

/// Whether the straight line between two cells crosses only passable cells: a walk in steps
/// of at most one cell along each axis, every cell it enters tested.
pub fn in_sight(space: &CostSpace, from: usize, to: usize) -> bool {
    let (ai, aj) = space.cell_at(from);
    let (bi, bj) = space.cell_at(to);
    let (bi, bj) = (bi as i64, bj as i64);
    let theta = (bj as f64 - aj as f64).atan2(bi as f64 - ai as f64);
    let (sin, cos) = theta.sin_cos();
    let (mut i, mut j) = (ai as f64, aj as f64);
    let (mut last_i, mut last_j) = (-1i64, -1i64);
    // Each step enters a new cell or moves towards one; this bounds a walk that float
    // rounding would keep from landing exactly.
    let limit = 4 * ((bi - ai as i64).abs() + (bj - aj as i64).abs()) + 4;
    for _ in 0..limit {
        if last_i == bi && last_j == bj {
            return true;
        }
        let (ci, cj) = (i.floor() as i64, j.floor() as i64);
        if (ci, cj) != (last_i, last_j) {
            (last_i, last_j) = (ci, cj);
            if ci < 0 || cj < 0 || ci >= space.width as i64 || cj >= space.height as i64 {
                return false;
            }
            if !space.passable(space.index(ci as usize, cj as usize)) {
                return false;
            }
        }
        if last_i != bi {
            i += cos;
        }
        if last_j != bj {
            j += sin;
        }
    }
    last_i == bi && last_j == bj
}
