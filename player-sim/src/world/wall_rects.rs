//! The walls near a point as a few rectangles: each row's runs of wall cells, merged with the
//! same run in the rows below. A sensor near a wall sees it over part of its beams only; from
//! the rectangles it can tell which beams may meet a wall (the directions of a rectangle's
//! corners bound them) and cast only those through the grid.

use super::bitmap::OccupancyGrid;

/// An axis-aligned block of wall cells, in world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WallRect {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

/// More cells than this in the square asked about and the rectangles are not worth finding:
/// [`OccupancyGrid::wall_rects_within`] answers `false` (a sensor with a very long reach over
/// a large map).
const MOST_CELLS: usize = 1 << 16;

impl OccupancyGrid {
    /// The wall cells of the square of cells within `reach` of `(x, y)`, and a cell more
    /// around it (as [`OccupancyGrid::walls_within`] asks), as rectangles in `out` (cleared
    /// first): every wall cell a ray from `(x, y)` can enter within `reach` is in one. `false`,
    /// with `out` empty, when the square is not finite or too large to be worth it.
    pub fn wall_rects_within(&self, x: f64, y: f64, reach: f64, out: &mut Vec<WallRect>) -> bool {
        out.clear();
        let (low, high) = ((x - reach, y - reach), (x + reach, y + reach));
        if !(low.0.is_finite() && low.1.is_finite() && high.0.is_finite() && high.1.is_finite()) {
            return false;
        }
        let Some((columns, rows)) = self.cells_around(low, high) else {
            return true;
        };
        if (columns.1 - columns.0) * (rows.1 - rows.0) > MOST_CELLS {
            return false;
        }
        // Rectangles still growing upwards: (first column, end column, first row).
        let mut open: Vec<(usize, usize, usize)> = Vec::new();
        let mut runs: Vec<(usize, usize)> = Vec::new();
        for row in rows.0..rows.1 {
            runs.clear();
            if self
                .wall_sums
                .count(&self.occupied, self.width, columns, (row, row + 1))
                > 0
            {
                let cells = &self.occupied[row * self.width..(row + 1) * self.width];
                let mut c = columns.0;
                while c < columns.1 {
                    if cells[c] {
                        let start = c;
                        while c < columns.1 && cells[c] {
                            c += 1;
                        }
                        runs.push((start, c));
                    } else {
                        c += 1;
                    }
                }
            }
            // A rectangle whose run does not go on in this row is finished.
            open.retain(|&(c0, c1, r0)| {
                let goes_on = runs.contains(&(c0, c1));
                if !goes_on {
                    out.push(self.rect(c0, c1, r0, row));
                }
                goes_on
            });
            for &(c0, c1) in &runs {
                if !open.iter().any(|&(a, b, _)| (a, b) == (c0, c1)) {
                    open.push((c0, c1, row));
                }
            }
        }
        for (c0, c1, r0) in open {
            out.push(self.rect(c0, c1, r0, rows.1));
        }
        true
    }

    /// Columns `c0..c1` of rows `r0..r1`, in world coordinates.
    fn rect(&self, c0: usize, c1: usize, r0: usize, r1: usize) -> WallRect {
        let (ox, oy) = self.origin;
        let (w, h) = self.cell;
        WallRect {
            x0: ox + c0 as f64 * w,
            y0: oy + r0 as f64 * h,
            x1: ox + c1 as f64 * w,
            y1: oy + r1 as f64 * h,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn walls_become_few_rectangles_covering_every_wall_cell() {
        // 12 x 8 cells of 0.5 m from (0, 0): a wall along the north, a pillar, a lone cell.
        let rows = [
            "############",
            "............",
            "...##.......",
            "...##.......",
            "..........#.",
            "............",
            "............",
            "............",
        ];
        let grid = OccupancyGrid::from_rows(&rows, 0.5, (0.0, 0.0));
        let mut rects = Vec::new();
        assert!(grid.wall_rects_within(3.0, 2.0, 10.0, &mut rects));
        assert_eq!(rects.len(), 3, "{rects:?}");
        assert!(rects.contains(&WallRect {
            x0: 1.5,
            y0: 2.0,
            x1: 2.5,
            y1: 3.0
        }));
        assert!(rects.contains(&WallRect {
            x0: 0.0,
            y0: 3.5,
            x1: 6.0,
            y1: 4.0
        }));
        // Every wall cell's centre lies in a rectangle.
        for row in 0..8 {
            for column in 0..12 {
                let (cx, cy) = (0.25 + column as f64 * 0.5, 0.25 + row as f64 * 0.5);
                let inside = rects
                    .iter()
                    .any(|r| r.x0 < cx && cx < r.x1 && r.y0 < cy && cy < r.y1);
                assert_eq!(inside, grid.occupied_at(cx, cy), "cell {column}, {row}");
            }
        }
        // Near the south-east corner with a short reach: only the lone cell.
        assert!(grid.wall_rects_within(5.5, 0.5, 1.0, &mut rects));
        assert_eq!(rects.len(), 1);
        // Nothing finite to look at, and nothing near.
        assert!(!grid.wall_rects_within(f64::NAN, 0.5, 1.0, &mut rects));
        assert!(grid.wall_rects_within(50.0, 50.0, 1.0, &mut rects));
        assert!(rects.is_empty());
    }
}
