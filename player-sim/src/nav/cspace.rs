//! The configuration space wavefront plans in: every cell of the map with its distance to the
//! nearest cell that is not free (occupied or unknown, as Player's planner counts them),
//! capped at `max_radius`. A cell nearer than the robot's radius plus `safety_dist` to one is
//! impassable; nearer than `max_radius`, it costs extra.
//!
//! Cells are Player's planner's: cell (i, j) stands for the point `origin + (i, j) · scale`
//! and a point belongs to the nearest such cell, so waypoints come out where wavefront puts
//! them.

use crate::mapfile::GridMap;

/// The planner's view of a map.
#[derive(Debug, Clone, PartialEq)]
pub struct CostSpace {
    pub width: usize,
    pub height: usize,
    pub scale: f64,
    pub origin: (f64, f64),
    /// Robot radius plus `safety_dist`: nearer to an obstacle is impassable.
    pub min_radius: f64,
    /// Beyond this distance from obstacles a cell costs nothing extra.
    pub max_radius: f64,
    /// Metres per cell (`dist_penalty`).
    pub dist_penalty: f64,
    /// Distance to the nearest cell that is not free, at most `max_radius`; row-major.
    occ_dist: Vec<f64>,
}

impl CostSpace {
    pub fn new(map: &GridMap, min_radius: f64, max_radius: f64, dist_penalty: f64) -> CostSpace {
        let (width, height) = (map.width as usize, map.height as usize);
        let scale = map.resolution;
        let mut occ_dist = vec![max_radius; width * height];
        let reach = (max_radius / scale).ceil() as i64;
        for j in 0..height {
            for i in 0..width {
                let free = map.cell(i as u32, j as u32).is_some_and(|c| c < 0);
                if free {
                    continue;
                }
                for dj in -reach..=reach {
                    for di in -reach..=reach {
                        let (ni, nj) = (i as i64 + di, j as i64 + dj);
                        if ni < 0 || nj < 0 || ni >= width as i64 || nj >= height as i64 {
                            continue;
                        }
                        let d = ((di * di + dj * dj) as f64).sqrt() * scale;
                        let k = nj as usize * width + ni as usize;
                        if d < occ_dist[k] {
                            occ_dist[k] = d;
                        }
                    }
                }
            }
        }
        CostSpace {
            width,
            height,
            scale,
            origin: map.origin,
            min_radius,
            max_radius,
            dist_penalty,
            occ_dist,
        }
    }

    /// The cell a world point belongs to, if it is on the map.
    pub fn cell_of(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        let i = ((x - self.origin.0) / self.scale + 0.5).floor();
        let j = ((y - self.origin.1) / self.scale + 0.5).floor();
        let inside = i >= 0.0 && j >= 0.0 && i < self.width as f64 && j < self.height as f64;
        inside.then_some((i as usize, j as usize))
    }

    /// The world point a cell stands for.
    pub fn point_of(&self, i: usize, j: usize) -> (f64, f64) {
        (
            self.origin.0 + i as f64 * self.scale,
            self.origin.1 + j as f64 * self.scale,
        )
    }

    pub fn index(&self, i: usize, j: usize) -> usize {
        j * self.width + i
    }

    /// The cell of an index.
    pub fn cell_at(&self, k: usize) -> (usize, usize) {
        (k % self.width, k / self.width)
    }

    pub fn occ_dist(&self, k: usize) -> f64 {
        self.occ_dist[k]
    }

    /// Whether the robot fits in cell `k`.
    pub fn passable(&self, k: usize) -> bool {
        self.occ_dist[k] >= self.min_radius
    }

    /// What entering cell `k` costs besides the distance: the nearer an obstacle, the more.
    pub fn proximity_cost(&self, k: usize) -> f64 {
        let d = self.occ_dist[k];
        if d < self.max_radius {
            self.dist_penalty * (self.max_radius - d)
        } else {
            0.0
        }
    }
}
