//! The floorplan as an occupancy grid read from a bitmap: dark pixels are walls. The bitmap
//! is stretched over the floorplan's `size` and centred on its pose, top row to the north.

use std::path::Path;

/// Which way a wall face looks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Face {
    /// Faces east or west (a vertical edge between cells).
    EastWest,
    /// Faces north or south.
    NorthSouth,
}

/// Walls on a regular grid, with fast ray casting.
#[derive(Debug, Clone, PartialEq)]
pub struct OccupancyGrid {
    pub width: usize,
    pub height: usize,
    /// Metres per cell along x and y.
    pub cell: (f64, f64),
    /// World position of the grid's south-west corner.
    pub origin: (f64, f64),
    /// Row-major from the south row up.
    pub(super) occupied: Vec<bool>,
}

impl OccupancyGrid {
    /// Reads a PNG (or any format the `image` crate reads with our features).
    pub fn from_png(
        path: &Path,
        size_x: f64,
        size_y: f64,
        centre_x: f64,
        centre_y: f64,
    ) -> Result<OccupancyGrid, String> {
        let image = image::open(path)
            .map_err(|e| format!("cannot read bitmap {}: {e}", path.display()))?
            .to_luma_alpha8();
        let (w, h) = (image.width() as usize, image.height() as usize);
        let mut occupied = vec![false; w * h];
        for (x, y, p) in image.enumerate_pixels() {
            let row_from_south = h - 1 - y as usize;
            occupied[row_from_south * w + x as usize] = p[1] > 127 && p[0] < 128;
        }
        Ok(OccupancyGrid {
            width: w,
            height: h,
            cell: (size_x / w as f64, size_y / h as f64),
            origin: (centre_x - size_x / 2.0, centre_y - size_y / 2.0),
            occupied,
        })
    }

    /// A grid from rows given north first (`#` = wall), for tests.
    pub fn from_rows(rows: &[&str], cell: f64, origin: (f64, f64)) -> OccupancyGrid {
        let (h, w) = (rows.len(), rows.first().map_or(0, |r| r.len()));
        let mut occupied = vec![false; w * h];
        for (y, row) in rows.iter().enumerate() {
            for (x, c) in row.bytes().enumerate() {
                occupied[(h - 1 - y) * w + x] = c == b'#';
            }
        }
        OccupancyGrid {
            width: w,
            height: h,
            cell: (cell, cell),
            origin,
            occupied,
        }
    }

    fn cell_of(&self, x: f64, y: f64) -> (i64, i64) {
        (
            ((x - self.origin.0) / self.cell.0).floor() as i64,
            ((y - self.origin.1) / self.cell.1).floor() as i64,
        )
    }

    fn is_wall(&self, cx: i64, cy: i64) -> bool {
        if cx < 0 || cy < 0 || cx >= self.width as i64 || cy >= self.height as i64 {
            return false;
        }
        self.occupied[cy as usize * self.width + cx as usize]
    }

    pub fn occupied_at(&self, x: f64, y: f64) -> bool {
        let (cx, cy) = self.cell_of(x, y);
        self.is_wall(cx, cy)
    }

    /// Distance from `(x, y)` along `angle` to the first wall, if within `max` (grid traversal
    /// cell by cell: cost grows with distance in cells, not with the grid's size).
    pub fn raycast(&self, x: f64, y: f64, angle: f64, max: f64) -> Option<f64> {
        self.raycast_face(x, y, angle, max).map(|(t, _)| t)
    }

    /// [`Self::raycast`], also telling which way the wall face hit looks: [`Face::EastWest`]
    /// when the ray crossed a vertical cell edge, [`Face::NorthSouth`] a horizontal one (the
    /// camera shades them apart, so that corners show).
    pub fn raycast_face(&self, x: f64, y: f64, angle: f64, max: f64) -> Option<(f64, Face)> {
        let (dy, dx) = angle.sin_cos();
        self.raycast_along(x, y, dx, dy, max)
    }

    /// [`Self::raycast_face`] along the unit direction `(dx, dy)`: a caster that also tests
    /// boxes along the same beam computes its sine and cosine once.
    pub fn raycast_along(&self, x: f64, y: f64, dx: f64, dy: f64, max: f64) -> Option<(f64, Face)> {
        let (mut cx, mut cy) = self.cell_of(x, y);
        if self.is_wall(cx, cy) {
            return Some((0.0, Face::EastWest));
        }
        let step_x = if dx > 0.0 { 1 } else { -1 };
        let step_y = if dy > 0.0 { 1 } else { -1 };
        let next_boundary = |c: i64, step: i64, origin: f64, size: f64| {
            origin + (c + i64::from(step > 0)) as f64 * size
        };
        let mut t_x = if dx.abs() < 1e-12 {
            f64::INFINITY
        } else {
            (next_boundary(cx, step_x, self.origin.0, self.cell.0) - x) / dx
        };
        let mut t_y = if dy.abs() < 1e-12 {
            f64::INFINITY
        } else {
            (next_boundary(cy, step_y, self.origin.1, self.cell.1) - y) / dy
        };
        let delta_x = if dx.abs() < 1e-12 {
            f64::INFINITY
        } else {
            self.cell.0 / dx.abs()
        };
        let delta_y = if dy.abs() < 1e-12 {
            f64::INFINITY
        } else {
            self.cell.1 / dy.abs()
        };
        loop {
            let (t, face) = if t_x < t_y {
                cx += step_x;
                let t = t_x;
                t_x += delta_x;
                (t, Face::EastWest)
            } else {
                cy += step_y;
                let t = t_y;
                t_y += delta_y;
                (t, Face::NorthSouth)
            };
            if t > max {
                return None;
            }
            if self.is_wall(cx, cy) {
                return Some((t, face));
            }
            if (cx < -1 && step_x < 0)
                || (cy < -1 && step_y < 0)
                || (cx > self.width as i64 && step_x > 0)
                || (cy > self.height as i64 && step_y > 0)
            {
                return None;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rays_stop_at_the_first_wall_cell() {
        // 10 cells of 0.5 m: a wall in column 8 (x from 4.0 to 4.5 m).
        let grid =
            OccupancyGrid::from_rows(&["........#.", "........#.", "........#."], 0.5, (0.0, 0.0));
        let hit = grid.raycast(1.0, 0.75, 0.0, 10.0).unwrap();
        assert!((hit - 3.0).abs() < 1e-9, "{hit}");
        assert_eq!(grid.raycast(1.0, 0.75, std::f64::consts::PI, 10.0), None);
        assert_eq!(grid.raycast(1.0, 0.75, 0.0, 2.0), None, "beyond max range");
        let diagonal = grid.raycast(3.0, 0.25, 0.4, 10.0).unwrap();
        assert!(
            (diagonal * 0.4f64.cos() + 3.0 - 4.0).abs() < 1e-9,
            "{diagonal}"
        );
        assert!(grid.occupied_at(4.2, 1.0) && !grid.occupied_at(3.9, 1.0));
        assert_eq!(
            grid.raycast_face(1.0, 0.75, 0.0, 10.0).unwrap().1,
            Face::EastWest
        );
        let up = OccupancyGrid::from_rows(&["####", "....", "...."], 0.5, (0.0, 0.0));
        assert_eq!(
            up.raycast_face(1.0, 0.2, 1.2, 10.0).unwrap().1,
            Face::NorthSouth
        );
    }
}
