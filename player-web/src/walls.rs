//! The world's walls, as the page draws them under the robots: what a relay that simulates
//! the world itself (`player-relay --world`, `--demo`) knows of it, sent once to every page.
//! A robot's map device needs none of this: its tiles travel as the robot sends them.
//!
//! A floorplan arrives as a grid of wall cells (thousands a side at Stage's 2 cm), too many to
//! send cell by cell; each row's runs of wall, merged with the same run in the rows above,
//! make a few hundred rectangles for a building.

use serde::Serialize;

/// Walls and obstacles in world coordinates, metres.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Walls {
    /// Axis-aligned blocks of wall: `[x0, y0, x1, y1]`, `x0 < x1`, `y0 < y1`.
    pub rects: Vec<[f64; 4]>,
    /// Other things that stop robots (a box turned on the floor), each a polygon's corners.
    pub polygons: Vec<Vec<[f64; 2]>>,
}

/// A grid of cells, `wall(column, row)` telling which are wall, row 0 the southernmost.
pub struct Grid<F: Fn(usize, usize) -> bool> {
    pub width: usize,
    pub height: usize,
    /// Metres per cell along x and y.
    pub cell: (f64, f64),
    /// The south-west corner of cell (0, 0).
    pub origin: (f64, f64),
    pub wall: F,
}

impl Walls {
    pub fn is_empty(&self) -> bool {
        self.rects.is_empty() && self.polygons.is_empty()
    }

    /// Adds the wall cells of `grid` as rectangles: every wall cell is in exactly one.
    pub fn add_grid<F: Fn(usize, usize) -> bool>(&mut self, grid: &Grid<F>) {
        // Runs still growing upwards: (first column, past the last column) -> first row.
        let mut open: Vec<((usize, usize), usize)> = Vec::new();
        for row in 0..=grid.height {
            let runs = match row < grid.height {
                true => runs_of(grid.width, |col| (grid.wall)(col, row)),
                false => Vec::new(),
            };
            let mut still = Vec::new();
            for (run, first_row) in open.drain(..) {
                match runs.contains(&run) {
                    true => still.push((run, first_row)),
                    false => self.rects.push(grid.rect(run, first_row, row)),
                }
            }
            for run in runs {
                if !still.iter().any(|(r, _)| *r == run) {
                    still.push((run, row));
                }
            }
            open = still;
        }
    }
}

impl<F: Fn(usize, usize) -> bool> Grid<F> {
    /// Columns `cols`, rows from `first_row` up to (not including) `past_row`, in metres.
    fn rect(&self, cols: (usize, usize), first_row: usize, past_row: usize) -> [f64; 4] {
        let x = |col: usize| self.origin.0 + col as f64 * self.cell.0;
        let y = |row: usize| self.origin.1 + row as f64 * self.cell.1;
        [x(cols.0), y(first_row), x(cols.1), y(past_row)]
    }
}

/// The runs of wall in one row: (first column, past the last).
fn runs_of(width: usize, wall: impl Fn(usize) -> bool) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut start = None;
    for col in 0..=width {
        match (start, col < width && wall(col)) {
            (None, true) => start = Some(col),
            (Some(first), false) => {
                runs.push((first, col));
                start = None;
            }
            _ => {}
        }
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `rows` written north first, as a map is read; `#` is wall.
    fn walls_of(rows: &[&str]) -> Walls {
        let cells: Vec<Vec<bool>> = rows
            .iter()
            .rev()
            .map(|r| r.chars().map(|c| c == '#').collect())
            .collect();
        let mut walls = Walls::default();
        walls.add_grid(&Grid {
            width: cells[0].len(),
            height: cells.len(),
            cell: (0.5, 0.5),
            origin: (-1.0, -1.0),
            wall: |col, row| cells[row][col],
        });
        walls
    }

    #[test]
    fn a_room_is_four_rectangles_and_every_wall_cell_is_covered_once() {
        let rows = ["#####", "#...#", "#...#", "#####"];
        let walls = walls_of(&rows);
        // The bottom and top rows, and the two sides between them.
        assert_eq!(walls.rects.len(), 4, "{:?}", walls.rects);
        let area: f64 = walls
            .rects
            .iter()
            .map(|r| (r[2] - r[0]) * (r[3] - r[1]))
            .sum();
        let cells = rows.concat().chars().filter(|&c| c == '#').count();
        assert!((area - cells as f64 * 0.25).abs() < 1e-9);
        assert!(
            walls.rects.contains(&[-1.0, -1.0, 1.5, -0.5]),
            "the south wall"
        );
        assert!(
            walls.rects.contains(&[-1.0, -0.5, -0.5, 0.5]),
            "the west wall"
        );
    }

    #[test]
    fn a_run_that_changes_starts_a_new_rectangle() {
        let walls = walls_of(&["##.", "###", "..."]);
        assert_eq!(walls.rects.len(), 2, "{:?}", walls.rects);
        assert!(walls_of(&["...", "..."]).is_empty());
    }
}
