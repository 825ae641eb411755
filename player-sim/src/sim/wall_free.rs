//! Whether a sensor's whole reach is free of walls, asked of the raster once per scan: in a
//! large hall (the 1 024-robot swarm's, 128 m across) most robots stand farther than their
//! laser's 8 m from any wall, and every one of their beams still walked the raster in jumps of
//! at most [`MAX_CLEARANCE`](super::wall_raster) cells — two or three reads of a 41-million-cell
//! raster a beam, each likely a cache miss, half of such a step. A scan that knows no wall
//! cell lies within its reach skips the walk: every beam would have found none.
//!
//! The test covers the square around the sensor with the cells' own clearances (a cell `c`
//! cells from the nearest wall frees the square of side `2c - 1` around it): the centre's
//! clearance, and if that falls short, the four quarters' in turn, a few levels deep. It
//! answers "free" only when the squares it read cover the whole reach; otherwise the scan
//! walks as before. Readings cannot change.

use super::wall_raster::WallRaster;
use crate::world::floor_i64;

/// Cells past the reach that a ray's walk may look into: the cell a point lies in, and the
/// cell beside it that Stage's rays look into west and south of the origin, with a hair more.
const MARGIN: i64 = 3;

/// How many times the square is split in quarters before the test gives up (answers "walls
/// may be near"): at most 1 + 4 + 16 + 64 clearances read.
const DEPTH: u32 = 3;

/// Reaches of more cells than this are not tested (the walk is cheap next to the test there).
const MOST_CELLS: f64 = 1e6;

impl WallRaster {
    /// Is there surely no wall cell within `max` metres of `(x, y)` (so that every ray from
    /// there up to `max` long meets none)? `false` when unsure.
    pub(super) fn free_within(&self, x: f64, y: f64, max: f64) -> bool {
        let (gx, gy) = (x * self.per_metre, y * self.per_metre);
        let reach = (max * self.per_metre).ceil();
        if !(gx.is_finite() && gy.is_finite() && (0.0..=MOST_CELLS).contains(&reach)) {
            return false;
        }
        let r = reach as i64 + MARGIN;
        let (cx, cy) = (floor_i64(gx), floor_i64(gy));
        self.square_free((cx - r, cy - r), (cx + r, cy + r), DEPTH)
    }

    /// Is no cell of the rectangle from `low` to `high` (inclusive) a wall, as far as `depth`
    /// more splits can tell?
    fn square_free(&self, low: (i64, i64), high: (i64, i64), depth: u32) -> bool {
        let mid = (low.0 + (high.0 - low.0) / 2, low.1 + (high.1 - low.1) / 2);
        // The Chebyshev distance from the middle cell to the rectangle's farthest cell.
        let spread = (mid.0 - low.0)
            .max(high.0 - mid.0)
            .max(mid.1 - low.1)
            .max(high.1 - mid.1);
        let clear = i64::from(self.clearance(mid.0, mid.1));
        // Every cell nearer than the clearance is free.
        if clear > spread {
            return true;
        }
        if clear == 0 || depth == 0 {
            return false;
        }
        let quarters = [
            (low, mid),
            ((mid.0 + 1, low.1), (high.0, mid.1)),
            ((low.0, mid.1 + 1), (mid.0, high.1)),
            ((mid.0 + 1, mid.1 + 1), high),
        ];
        quarters
            .into_iter()
            .filter(|(a, b)| a.0 <= b.0 && a.1 <= b.1)
            .all(|(a, b)| self.square_free(a, b, depth - 1))
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::test_randoms::randoms;
    use crate::world::{Floorplan, OccupancyGrid, World};

    use super::*;

    #[test]
    fn a_free_reach_holds_no_wall_cell_and_open_space_is_found_free() {
        // A 40 x 40 m hall of 0.5 m pixels with a pillar (x 5..7 m, y 3..5 m: rows run from the
        // north), on a 0.05 m raster.
        let mut rows = vec![String::from(&"#".repeat(80))];
        for r in 1..79 {
            let mut row = vec![b'.'; 80];
            (row[0], row[79]) = (b'#', b'#');
            if (30..34).contains(&r) {
                row[50..54].fill(b'#');
            }
            rows.push(String::from_utf8(row).unwrap());
        }
        rows.push(rows[0].clone());
        let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
        let mut world = World::default();
        world.resolution = 0.05;
        world.floor = Some(OccupancyGrid::from_rows(&rows, 0.5, (-20.0, -20.0)));
        world.floorplan = Some(Floorplan {
            bitmap: Default::default(),
            size: [40.0, 40.0],
            centre: [0.0, 0.0],
            height: 1.0,
            color: [0, 0, 0],
        });
        let raster = WallRaster::of(&world).expect("walls");
        let mut next = randoms(0xF4EE);
        let mut free = 0;
        for k in 0..3000 {
            let (x, y) = (48.0 * next() - 24.0, 48.0 * next() - 24.0);
            let max = [0.5, 2.0, 5.0, 8.0][k % 4];
            if !raster.free_within(x, y, max) {
                continue;
            }
            free += 1;
            // No wall cell within the reach, nor on any ray's walk.
            let r = (max * 20.0).ceil() as i64 + 2;
            let (cx, cy) = (floor_i64(x * 20.0), floor_i64(y * 20.0));
            for wy in cy - r..=cy + r {
                for wx in cx - r..=cx + r {
                    assert!(!raster.is_wall(wx, wy), "({wx}, {wy}) from ({x}, {y})");
                }
            }
            for beam in 0..90 {
                let (dy, dx) = (beam as f64 * 4f64.to_radians()).sin_cos();
                assert_eq!(raster.cast(x, y, dx, dy, max), None, "from ({x}, {y})");
            }
        }
        assert!(free > 600, "{free}");
        // The middle of the hall is free for 8 m; beside the pillar it is not.
        assert!(raster.free_within(-8.0, -8.0, 8.0));
        assert!(!raster.free_within(6.0, 4.0, 2.0));
    }
}
