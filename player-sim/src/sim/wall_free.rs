//! Which parts of a sensor's reach may hold a wall, asked of the raster once per scan: in a
//! large hall (the 1 024-robot swarm's, 128 m across) most robots stand farther than their
//! laser's 8 m from any wall, or near one wall on one side, and every one of their beams still
//! walked the raster in jumps of at most 255 cells — two or three reads of a 41-million-cell
//! raster a beam, each likely a cache miss, half of such a step. A scan that knows no wall cell
//! lies within its reach walks no beam (every beam would have found none); one that knows
//! where the walls may be walks only the beams towards those parts.
//!
//! The test covers the square around the sensor with the cells' own clearances (a cell `c`
//! cells from the nearest wall frees the square of side `2c - 1` around it): the centre's
//! clearance, and if that falls short, the four quarters' in turn, three levels deep; the
//! quarters of the last level not proven free are the parts that may hold walls. A beam is
//! left unwalked only when it passes none of them. Readings cannot change.

use super::beams::{Fan, beams_towards};
use super::wall_raster::WallRaster;
use crate::world::floor_i64;

/// Cells past the reach that a ray's walk may look into: the cell a point lies in, the cell
/// beside it that Stage's rays look into west and south of the origin, and the cells Stage's
/// stepped path strays from the line (`PATH_SLACK`).
const MARGIN: i64 = 2 + PATH_SLACK;

/// How many cells Stage's stepped path may stray from a ray's line, rounded up
/// (`sim/raster_walk.rs`): the start cell's middle is up to 0.71 cells off the start, the steps
/// half a cell off their line, and the steps' slope, from whole cells of the range, up to a cell
/// off at the range's end.
pub(super) const PATH_SLACK: i64 = 3;

/// How many times the square is split in quarters: at most 1 + 4 + 16 + 64 clearances read.
const DEPTH: u32 = 3;

/// Reaches of more cells than this are not tested (the walk is cheap next to the test there).
const MOST_CELLS: f64 = 1e6;

/// More parts than this not known free and every beam walks: sorting the beams by part would
/// cost more than the walks it saves (a sensor among a cave's walls).
const MOST_PARTS: usize = 24;

/// A sensor whose nearest wall cell is nearer than its reach over this is not tested.
const NEAR: i64 = 4;

/// A part of a sensor's reach that may hold a wall cell: a circle in metres, `(x, y, radius)`.
pub(super) type Part = (f64, f64, f64);

impl WallRaster {
    /// Is there surely no wall cell within `max` metres of `(x, y)` (so that every ray from
    /// there up to `max` long meets none)? `false` when unsure.
    #[cfg(test)]
    pub(super) fn free_within(&self, x: f64, y: f64, max: f64) -> bool {
        let mut parts = Vec::new();
        self.walled_parts(x, y, max, &mut parts) && parts.is_empty()
    }

    /// The parts of the square within `max` metres of `(x, y)` that may hold a wall cell, into
    /// `parts` (each a circle around a cell more than the cells it covers: the walk looks into
    /// the cell beside a ray's west and south of the origin); none when the whole reach is
    /// free. `false` when the reach is not tested or too many parts are left (any beam may
    /// meet a wall).
    pub(super) fn walled_parts(&self, x: f64, y: f64, max: f64, parts: &mut Vec<Part>) -> bool {
        parts.clear();
        let (gx, gy) = (x * self.per_metre, y * self.per_metre);
        let reach = (max * self.per_metre).ceil();
        if !(gx.is_finite() && gy.is_finite() && (0.0..=MOST_CELLS).contains(&reach)) {
            return false;
        }
        let r = reach as i64 + MARGIN;
        let (cx, cy) = (floor_i64(gx), floor_i64(gy));
        // A wall within a quarter of the reach: too many parts would be left (a sensor in a
        // cave, where the test cost 8 % of a step's instructions and spared no beam).
        if i64::from(self.clearance(cx, cy)) * NEAR < r {
            return false;
        }
        self.unproven((cx - r, cy - r), (cx + r, cy + r), DEPTH, parts)
    }

    /// Adds to `parts` the pieces of the rectangle from `low` to `high` (cells, inclusive) that
    /// the clearances read, `depth` splits deep, do not prove free; `false` once there are more
    /// than [`MOST_PARTS`].
    fn unproven(
        &self,
        low: (i64, i64),
        high: (i64, i64),
        depth: u32,
        parts: &mut Vec<Part>,
    ) -> bool {
        let mid = (low.0 + (high.0 - low.0) / 2, low.1 + (high.1 - low.1) / 2);
        // The Chebyshev distance from the middle cell to the rectangle's farthest cell.
        let spread = (mid.0 - low.0)
            .max(high.0 - mid.0)
            .max(mid.1 - low.1)
            .max(high.1 - mid.1);
        // Every cell nearer than the middle's clearance is free.
        if i64::from(self.clearance(mid.0, mid.1)) > spread {
            return true;
        }
        if depth == 0 {
            // The cells from `low` to `high`, and as far all round as a path may stray, within
            // this circle.
            let (x0, y0) = ((low.0 - PATH_SLACK) as f64, (low.1 - PATH_SLACK) as f64);
            let (x1, y1) = (
                (high.0 + 1 + PATH_SLACK) as f64,
                (high.1 + 1 + PATH_SLACK) as f64,
            );
            let radius = (x1 - x0).hypot(y1 - y0) / 2.0;
            parts.push((
                (x0 + x1) / 2.0 * self.resolution,
                (y0 + y1) / 2.0 * self.resolution,
                radius * self.resolution * (1.0 + 1e-9),
            ));
            return parts.len() <= MOST_PARTS;
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
            .all(|(a, b)| self.unproven(a, b, depth - 1, parts))
    }
}

/// Which beams of `fan` from `(x, y)` may enter any of `parts` (the beams through a part's
/// circle, widened by a beam each side as the boxes' are): the others meet no wall.
pub(super) fn beams_meeting(parts: &[Part], x: f64, y: f64, fan: Fan) -> Vec<bool> {
    let mut may_meet = vec![false; fan.count];
    for &(cx, cy, radius) in parts {
        for (lo, hi) in beams_towards(fan, cx - x, cy - y, radius) {
            may_meet[lo..hi].fill(true);
        }
    }
    may_meet
}

#[cfg(test)]
mod tests {
    use crate::sim::test_halls::{bordered, walled};
    use crate::sim::test_randoms::randoms;

    use super::*;

    #[test]
    fn a_free_reach_holds_no_wall_cell_and_open_space_is_found_free() {
        // A 40 x 40 m hall of 0.5 m pixels with a pillar (x 5..7 m, y 3..5 m: rows run from the
        // north), on a 0.05 m raster.
        let rows = bordered(80, 80, |r, c| {
            (30..34).contains(&r) && (50..54).contains(&c)
        });
        let world = walled(&rows, 0.5, 0.05);
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
        // A beam towards none of the parts that may hold walls meets none.
        let (mut skipped, mut walked) = (0, 0);
        for k in 0..3000 {
            let (x, y) = (48.0 * next() - 24.0, 48.0 * next() - 24.0);
            let max = [2.0, 5.0, 8.0][k % 3];
            let fan = Fan {
                first: 6.0 * next(),
                step: std::f64::consts::PI / 180.0,
                count: 181,
            };
            let mut parts = Vec::new();
            if !raster.walled_parts(x, y, max, &mut parts) {
                continue;
            }
            let may_meet = beams_meeting(&parts, x, y, fan);
            for (i, &may) in may_meet.iter().enumerate() {
                let (dy, dx) = (fan.first + i as f64 * fan.step).sin_cos();
                let hit = raster.cast(x, y, dx, dy, max);
                if may {
                    walked += 1;
                } else {
                    skipped += 1;
                    assert_eq!(hit, None, "beam {i} from ({x}, {y}) reaching {max}");
                }
            }
        }
        assert!(skipped > 100_000 && walked > 20_000, "{skipped} {walked}");
        // The middle of the hall is free for 8 m; beside the pillar it is not.
        assert!(raster.free_within(-8.0, -8.0, 8.0));
        assert!(!raster.free_within(6.0, 4.0, 2.0));
    }
}
