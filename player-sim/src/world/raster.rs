//! Block polygons drawn into the occupancy grid, so that floorplans drawn with Stage `block`s
//! stop rays and robots exactly as bitmap walls do. A polygon fills every cell whose centre it
//! holds, and its edges mark every cell they pass through, so that walls thinner than a cell
//! still stop rays.

use super::bitmap::OccupancyGrid;

/// The most cells a grid may have (16 Mi cells, 16 MiB): larger extents get coarser cells.
pub const MAX_CELLS: f64 = 16.0 * 1024.0 * 1024.0;

impl OccupancyGrid {
    /// An empty grid over `min`..`max` (one spare cell around), with square cells of
    /// `resolution` metres, or larger ones when that many would exceed [`MAX_CELLS`].
    pub fn covering(min: [f64; 2], max: [f64; 2], resolution: f64) -> OccupancyGrid {
        let span = [max[0] - min[0], max[1] - min[1]];
        let mut cell = resolution;
        let cells = |cell: f64| (span[0] / cell + 3.0) * (span[1] / cell + 3.0);
        if cells(cell) > MAX_CELLS {
            cell = (span[0] * span[1] / MAX_CELLS)
                .sqrt()
                .max(span[0].max(span[1]) / 4096.0);
            while cells(cell) > MAX_CELLS {
                cell *= 1.1;
            }
        }
        let width = (span[0] / cell).ceil() as usize + 2;
        let height = (span[1] / cell).ceil() as usize + 2;
        OccupancyGrid {
            width,
            height,
            cell: (cell, cell),
            origin: (min[0] - cell, min[1] - cell),
            occupied: vec![false; width * height],
            wall_sums: Default::default(),
        }
    }

    /// This grid grown to cover `min`..`max` too, with the same cells (so walls already drawn
    /// stay exactly where they were), or `None` when that would exceed [`MAX_CELLS`].
    pub fn grown_to(&self, min: [f64; 2], max: [f64; 2]) -> Option<OccupancyGrid> {
        let (cx, cy) = self.cell;
        let extra = |low: f64, high: f64, origin: f64, size: f64, n: usize| {
            let before = ((origin - low) / size).ceil().max(0.0) + 1.0;
            let after = ((high - (origin + n as f64 * size)) / size).ceil().max(0.0) + 1.0;
            (before, after)
        };
        let (left, right) = extra(min[0], max[0], self.origin.0, cx, self.width);
        let (below, above) = extra(min[1], max[1], self.origin.1, cy, self.height);
        let (w, h) = (
            self.width as f64 + left + right,
            self.height as f64 + below + above,
        );
        if !(w * h).is_finite() || w * h > MAX_CELLS {
            return None;
        }
        let (width, height) = (w as usize, h as usize);
        let mut occupied = vec![false; width * height];
        for row in 0..self.height {
            let to = (row + below as usize) * width + left as usize;
            occupied[to..to + self.width]
                .copy_from_slice(&self.occupied[row * self.width..(row + 1) * self.width]);
        }
        Some(OccupancyGrid {
            width,
            height,
            cell: self.cell,
            origin: (self.origin.0 - left * cx, self.origin.1 - below * cy),
            occupied,
            wall_sums: Default::default(),
        })
    }

    /// Marks the cells `polygon` (world coordinates, either winding) covers.
    pub fn draw_polygon(&mut self, polygon: &[[f64; 2]]) {
        self.fill(polygon);
        // Edges lying exactly on cell boundaries belong to the cells inside the polygon: each
        // edge is drawn a hair towards the inside (to the left of a counter-clockwise edge).
        let twice_area: f64 = (0..polygon.len())
            .map(|i| {
                let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum();
        let inward = 1e-6 * self.cell.0.min(self.cell.1) * twice_area.signum();
        for (i, &a) in polygon.iter().enumerate() {
            let b = polygon[(i + 1) % polygon.len()];
            let length = (b[0] - a[0]).hypot(b[1] - a[1]).max(f64::MIN_POSITIVE);
            let shift = [
                -(b[1] - a[1]) / length * inward,
                (b[0] - a[0]) / length * inward,
            ];
            let nudged = |p: [f64; 2]| [p[0] + shift[0], p[1] + shift[1]];
            self.draw_edge(nudged(a), nudged(b));
        }
    }

    fn set(&mut self, cx: i64, cy: i64) {
        if cx >= 0 && cy >= 0 && (cx as usize) < self.width && (cy as usize) < self.height {
            self.occupied[cy as usize * self.width + cx as usize] = true;
            self.wall_sums = Default::default();
        }
    }

    /// Even-odd scanlines through the cell centres.
    fn fill(&mut self, polygon: &[[f64; 2]]) {
        let (lo, hi) = polygon
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[1]), hi.max(p[1]))
            });
        let row_of =
            |y: f64| ((y - self.origin.1) / self.cell.1 - 0.5).clamp(-1.0, self.height as f64);
        let (first, last) = (row_of(lo).ceil() as i64, row_of(hi).floor() as i64);
        let mut crossings = Vec::with_capacity(polygon.len());
        for row in first.max(0)..=last.min(self.height as i64 - 1) {
            let y = self.origin.1 + (row as f64 + 0.5) * self.cell.1;
            crossings.clear();
            for (i, a) in polygon.iter().enumerate() {
                let b = polygon[(i + 1) % polygon.len()];
                if (a[1] <= y) != (b[1] <= y) {
                    crossings.push(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
                }
            }
            crossings.sort_by(f64::total_cmp);
            for pair in crossings.chunks_exact(2) {
                let column = |x: f64| (x - self.origin.0) / self.cell.0 - 0.5;
                let from = column(pair[0]).ceil().max(0.0) as i64;
                let to = column(pair[1]).floor().min(self.width as f64 - 1.0) as i64;
                for cx in from..=to {
                    self.set(cx, row);
                }
            }
        }
    }

    /// Every cell the segment passes through: samples a quarter cell apart, and both cells
    /// beside a diagonal step, so that no ray slips between two marked corners.
    fn draw_edge(&mut self, a: [f64; 2], b: [f64; 2]) {
        let (origin, cell) = (self.origin, self.cell);
        let cell_at = |p: [f64; 2]| {
            (
                ((p[0] - origin.0) / cell.0).floor() as i64,
                ((p[1] - origin.1) / cell.1).floor() as i64,
            )
        };
        let length = (b[0] - a[0]).hypot(b[1] - a[1]);
        let steps = (4.0 * length / self.cell.0.min(self.cell.1))
            .ceil()
            .max(1.0) as usize;
        let mut previous = cell_at(a);
        self.set(previous.0, previous.1);
        for i in 1..=steps {
            let t = i as f64 / steps as f64;
            let here = cell_at([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
            if here.0 != previous.0 && here.1 != previous.1 {
                self.set(here.0, previous.1);
                self.set(previous.0, here.1);
            }
            self.set(here.0, here.1);
            previous = here;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drawn_wall_stops_rays_at_its_face() {
        let mut grid = OccupancyGrid::covering([-5.0, -4.0], [5.0, 4.0], 0.05);
        // The east wall: x from 4.8 to 5, full height.
        grid.draw_polygon(&[[4.8, -4.0], [5.0, -4.0], [5.0, 4.0], [4.8, 4.0]]);
        let hit = grid.raycast(0.0, 0.3, 0.0, 10.0).unwrap();
        assert!((hit - 4.8).abs() <= 0.05, "{hit}");
        assert!(grid.occupied_at(4.9, 0.0) && !grid.occupied_at(4.7, 0.0));
        assert_eq!(grid.raycast(0.0, 0.3, std::f64::consts::PI, 10.0), None);
    }

    #[test]
    fn thin_diagonal_walls_let_no_ray_through() {
        let mut grid = OccupancyGrid::covering([0.0, 0.0], [4.0, 4.0], 0.1);
        grid.draw_polygon(&[[0.0, 0.0], [4.0, 4.0], [4.0, 4.0001]]);
        for k in 0..50 {
            let y = 0.5 + k as f64 * 0.05;
            let angle = -0.3 + k as f64 * 0.01;
            assert!(grid.raycast(0.05, y, angle, 10.0).is_some(), "{y} {angle}");
        }
    }

    #[test]
    fn huge_extents_get_coarser_cells_and_growing_keeps_walls() {
        let grid = OccupancyGrid::covering([-1e6, -1e6], [1e6, 1e6], 0.02);
        assert!((grid.width * grid.height) as f64 <= MAX_CELLS);
        let small = OccupancyGrid::from_rows(&["#.", ".."], 1.0, (0.0, 0.0));
        let grown = small.grown_to([-3.0, -3.0], [1.0, 1.0]).unwrap();
        assert!(grown.occupied_at(0.5, 1.5) && !grown.occupied_at(1.5, 1.5));
        assert!(!grown.occupied_at(-2.5, -2.5));
        assert!(grown.origin.0 <= -3.0 && grown.origin.1 <= -3.0);
        assert!(small.grown_to([-1e9, 0.0], [0.0, 0.0]).is_none());
    }
}
