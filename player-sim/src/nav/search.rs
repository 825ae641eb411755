//! The wavefront: costs spread from the goal cell over the 8-connected grid (Dijkstra), each
//! step costing its length plus the cell's nearness to obstacles, impassable cells left out,
//! and the path read back from the start by following each cell's cheapest neighbour. The
//! start cell itself is always passable, as in Player, so that a robot standing too close to
//! a wall can still plan its way out.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::cspace::CostSpace;

/// The eight neighbours of a cell, and how far each lies in cells.
const NEIGHBOURS: [(i64, i64, f64); 8] = [
    (-1, -1, std::f64::consts::SQRT_2),
    (0, -1, 1.0),
    (1, -1, std::f64::consts::SQRT_2),
    (-1, 0, 1.0),
    (1, 0, 1.0),
    (-1, 1, std::f64::consts::SQRT_2),
    (0, 1, 1.0),
    (1, 1, std::f64::consts::SQRT_2),
];

/// The cells from `start` to `goal` (both included, as indices), or `None` when the goal
/// cannot be reached (off the map, walled in, or inside an obstacle).
pub fn find_path(
    space: &CostSpace,
    start: (usize, usize),
    goal: (usize, usize),
) -> Option<Vec<usize>> {
    let start_k = space.index(start.0, start.1);
    let goal_k = space.index(goal.0, goal.1);
    if start_k == goal_k {
        return Some(vec![start_k]);
    }
    let n = space.width * space.height;
    let mut cost = vec![f64::INFINITY; n];
    let mut next = vec![usize::MAX; n];
    let mut done = vec![false; n];
    let mut queue = BinaryHeap::new();
    cost[goal_k] = 0.0;
    // Non-negative costs order as their bits do; ties go to the lower index, deterministically.
    queue.push(Reverse((0f64.to_bits(), goal_k)));
    while let Some(Reverse((_, k))) = queue.pop() {
        if done[k] {
            continue;
        }
        done[k] = true;
        if k == start_k {
            break;
        }
        let (i, j) = space.cell_at(k);
        for (di, dj, cells) in NEIGHBOURS {
            let (ni, nj) = (i as i64 + di, j as i64 + dj);
            if ni < 0 || nj < 0 || ni >= space.width as i64 || nj >= space.height as i64 {
                continue;
            }
            let nk = space.index(ni as usize, nj as usize);
            if done[nk] || (nk != start_k && !space.passable(nk)) {
                continue;
            }
            let proximity = if nk == start_k {
                0.0
            } else {
                space.proximity_cost(nk)
            };
            let c = cost[k] + cells * space.scale + proximity;
            if c < cost[nk] {
                cost[nk] = c;
                next[nk] = k;
                queue.push(Reverse((c.to_bits(), nk)));
            }
        }
    }
    if next[start_k] == usize::MAX {
        return None;
    }
    let mut path = vec![start_k];
    let mut k = start_k;
    while k != goal_k {
        k = next[k];
        path.push(k);
    }
    Some(path)
}
