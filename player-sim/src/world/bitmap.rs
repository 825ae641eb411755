//! The floorplan as an occupancy grid read from a bitmap: dark pixels are walls. The bitmap
//! is stretched over the floorplan's `size` and centred on its pose, top row to the north.

use std::path::Path;

use super::cell_floor::floor_i64;
use super::wall_sums::WallSums;
use crate::image_file::{ImageFault, ImageFileError, Picture};

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
    /// Wall cells counted over rectangles, from `occupied`: reset whenever a cell changes.
    pub(super) wall_sums: WallSums,
}

/// The most pixels a floorplan bitmap may have (8192 x 8192): thirty times Stage's largest
/// stock map, and at most a few hundred megabytes while it is read.
pub const MAX_BITMAP_PIXELS: u64 = 1 << 26;

impl OccupancyGrid {
    /// Reads a PNG (or any format the `image` crate reads with our features) as Stage reads a
    /// floorplan bitmap: a pixel whose first channel is 127 or less is a wall (alpha is not
    /// looked at), and the walls' bounding box, not the whole image, is stretched over
    /// `size_x` by `size_y` centred on `(centre_x, centre_y)` (Stage scales a model's blocks
    /// so that together they fill its size; a white margin is not part of them).
    pub fn from_png(
        path: &Path,
        size_x: f64,
        size_y: f64,
        centre_x: f64,
        centre_y: f64,
    ) -> Result<OccupancyGrid, ImageFileError> {
        let cannot = |fault: ImageFault| ImageFileError {
            picture: Picture::Bitmap,
            path: path.to_path_buf(),
            fault,
        };
        let open = || {
            image::ImageReader::open(path)
                .and_then(|r| r.with_guessed_format())
                .map_err(|e| cannot(e.into()))
        };
        // The header's size first: a lying one is refused before anything is allocated.
        let (width, height) = open()?.into_dimensions().map_err(|e| cannot(e.into()))?;
        if width == 0 || height == 0 {
            return Err(cannot(ImageFault::Empty { width, height }));
        }
        if u64::from(width) * u64::from(height) > MAX_BITMAP_PIXELS {
            return Err(cannot(ImageFault::TooLarge {
                width,
                height,
                most: MAX_BITMAP_PIXELS,
            }));
        }
        let image = open()?.decode().map_err(|e| cannot(e.into()))?.to_rgba8();
        let (w, h) = (image.width() as usize, image.height() as usize);
        let mut occupied = vec![false; w * h];
        // The walls' bounding box, in columns and rows from the south.
        let (mut low, mut high) = ((w, h), (0, 0));
        for (x, y, p) in image.enumerate_pixels() {
            let (x, row) = (x as usize, h - 1 - y as usize);
            if p[0] <= 127 {
                occupied[row * w + x] = true;
                low = (low.0.min(x), low.1.min(row));
                high = (high.0.max(x), high.1.max(row));
            }
        }
        if low.0 > high.0 {
            // No wall at all: the whole image, as nothing is stretched.
            (low, high) = ((0, 0), (w.max(1) - 1, h.max(1) - 1));
        }
        let cell = (
            size_x / (high.0 - low.0 + 1) as f64,
            size_y / (high.1 - low.1 + 1) as f64,
        );
        Ok(OccupancyGrid {
            width: w,
            height: h,
            cell,
            origin: (
                centre_x - size_x / 2.0 - low.0 as f64 * cell.0,
                centre_y - size_y / 2.0 - low.1 as f64 * cell.1,
            ),
            occupied,
            wall_sums: WallSums::default(),
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
            wall_sums: WallSums::default(),
        }
    }

    fn cell_of(&self, x: f64, y: f64) -> (i64, i64) {
        (
            floor_i64((x - self.origin.0) / self.cell.0),
            floor_i64((y - self.origin.1) / self.cell.1),
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

    /// Could a ray from `(x, y)` meet a wall within `max`? No when no wall cell lies in the
    /// square of cells within `max` of the point (and a cell more, for rounding): then
    /// [`Self::raycast_along`] surely finds none, for any direction.
    pub fn walls_within(&self, x: f64, y: f64, max: f64) -> bool {
        self.walls_in((x - max, y - max), (x + max, y + max))
    }

    /// Is any wall cell in the rectangle from `low` to `high` (world coordinates), or a cell
    /// beyond its edges (a margin for rounding)? Yes for a rectangle that is not finite.
    fn walls_in(&self, low: (f64, f64), high: (f64, f64)) -> bool {
        if !(low.0.is_finite() && low.1.is_finite() && high.0.is_finite() && high.1.is_finite()) {
            return true;
        }
        self.cells_around(low, high).is_some_and(|(columns, rows)| {
            self.wall_sums
                .count(&self.occupied, self.width, columns, rows)
                > 0
        })
    }

    /// The columns and rows (ends exclusive) of the grid's cells in the rectangle from `low`
    /// to `high` (finite), and a cell beyond its edges; none when that is outside the grid.
    pub(super) fn cells_around(
        &self,
        low: (f64, f64),
        high: (f64, f64),
    ) -> Option<((usize, usize), (usize, usize))> {
        let (c0, r0) = self.cell_of(low.0, low.1);
        let (c1, r1) = self.cell_of(high.0, high.1);
        let within = |low: i64, high: i64, n: usize| {
            let n = n as i64;
            (
                (low - 1).clamp(0, n) as usize,
                (high + 2).clamp(0, n) as usize,
            )
        };
        let (columns, rows) = (within(c0, c1, self.width), within(r0, r1, self.height));
        (columns.0 < columns.1 && rows.0 < rows.1).then_some((columns, rows))
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
    /// A ray whose whole reach (the rectangle around it) holds no wall is not traversed.
    pub fn raycast_along(&self, x: f64, y: f64, dx: f64, dy: f64, max: f64) -> Option<(f64, Face)> {
        let (ex, ey) = (x + dx * max, y + dy * max);
        if !self.walls_in((x.min(ex), y.min(ey)), (x.max(ex), y.max(ey))) {
            return None;
        }
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
    fn a_sensor_with_no_wall_within_reach_finds_none_in_any_direction() {
        // 20 x 20 cells of 0.5 m, walls in one corner block and along the east edge.
        let mut rows = vec![String::from("..................##"); 20];
        rows[3] = String::from("...####...........##");
        let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
        let grid = OccupancyGrid::from_rows(&rows, 0.5, (-2.0, -3.0));
        let mut seen_clear = 0;
        for i in 0..400 {
            let (x, y) = (-4.0 + 0.037 * i as f64, -5.0 + 0.029 * (i * 7 % 400) as f64);
            for max in [0.2, 1.0, 2.5, 6.0] {
                if grid.walls_within(x, y, max) {
                    continue;
                }
                seen_clear += 1;
                for beam in 0..90 {
                    let angle = beam as f64 * std::f64::consts::TAU / 90.0;
                    assert_eq!(grid.raycast(x, y, angle, max), None, "({x}, {y}) {max}");
                }
            }
        }
        assert!(seen_clear > 100, "{seen_clear}");
        assert!(grid.walls_within(6.5, 1.0, 0.1), "on the east wall");
        assert!(
            !grid.walls_within(100.0, 100.0, 5.0),
            "far outside the grid"
        );
    }

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
