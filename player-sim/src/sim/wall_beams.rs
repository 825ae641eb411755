//! Which beams of a scan may meet a wall. A sensor near a wall sees it over part of its fan:
//! a laser 4 m from a wall, a third of its beams. Each beam used to walk the grid (and first
//! take its sine and cosine) whenever any wall was within reach; now the walls near the sensor
//! are taken as a few rectangles ([`OccupancyGrid::wall_rects_within`]), each rectangle's
//! corners bound the directions that enter it, and only the beams within those directions
//! (widened by a beam each side, as the boxes' are) walk the grid. A beam left out could not
//! have met a wall, so every reading is what it was.

use super::beams::{Fan, beams_spanning};
use super::wrap;
use crate::world::{OccupancyGrid, WallRect};

/// For each beam of a fan, whether it may meet a wall.
#[derive(Debug, Clone)]
pub struct WallBeams {
    may_meet: Vec<bool>,
}

impl WallBeams {
    /// The beams of `fan`, from `(x, y)` reaching `reach`, that may meet a wall of `grid`.
    pub fn new(grid: &OccupancyGrid, x: f64, y: f64, reach: f64, fan: Fan) -> WallBeams {
        let mut rects = Vec::new();
        if !grid.wall_rects_within(x, y, reach, &mut rects) {
            return WallBeams {
                may_meet: vec![true; fan.count],
            };
        }
        let mut may_meet = vec![false; fan.count];
        for rect in &rects {
            for (lo, hi) in beams_into(fan, x, y, rect) {
                may_meet[lo..hi].fill(true);
            }
        }
        WallBeams { may_meet }
    }

    /// May beam `i` meet a wall?
    pub fn may_meet(&self, i: usize) -> bool {
        self.may_meet[i]
    }
}

/// The beams of `fan` from `(x, y)` that may enter `rect`: every beam from on or in it (a
/// hair around it included, for the grid walk's rounding); from outside, those within the
/// directions of its corners.
fn beams_into(fan: Fan, x: f64, y: f64, rect: &WallRect) -> [(usize, usize); 2] {
    const HAIR: f64 = 1e-6;
    let on_or_in =
        x >= rect.x0 - HAIR && x <= rect.x1 + HAIR && y >= rect.y0 - HAIR && y <= rect.y1 + HAIR;
    if on_or_in {
        return [(0, fan.count), (0, 0)];
    }
    // Seen from outside, a rectangle lies within less than half a turn of directions: the
    // corners' directions about its centre's span them all.
    let centre = ((rect.y0 + rect.y1) / 2.0 - y).atan2((rect.x0 + rect.x1) / 2.0 - x);
    let (mut low, mut high) = (0.0f64, 0.0f64);
    for (cx, cy) in [
        (rect.x0, rect.y0),
        (rect.x1, rect.y0),
        (rect.x0, rect.y1),
        (rect.x1, rect.y1),
    ] {
        let off = wrap((cy - y).atan2(cx - x) - centre);
        (low, high) = (low.min(off), high.max(off));
    }
    beams_spanning(fan, centre + (low + high) / 2.0, (high - low) / 2.0)
}

#[cfg(test)]
mod tests {
    use crate::sim::test_randoms::randoms;
    use std::f64::consts::PI;

    use super::*;

    #[test]
    fn a_beam_left_out_meets_no_wall() {
        // 40 x 40 cells of 0.5 m: a border, a wall, a pillar and lone cells.
        let mut rows = vec![String::from("########################################")];
        for r in 1..39 {
            let mut row: Vec<u8> = b"#......................................#".to_vec();
            if (8..30).contains(&r) {
                row[20] = b'#';
            }
            if (25..28).contains(&r) {
                row[6..9].fill(b'#');
            }
            if r % 11 == 0 {
                row[(r * 7) % 38 + 1] = b'#';
            }
            rows.push(String::from_utf8(row).unwrap());
        }
        rows.push(rows[0].clone());
        let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
        let grid = OccupancyGrid::from_rows(&rows, 0.5, (-10.0, -10.0));
        let mut next = randoms(0xBEA5);
        let (mut left_out, mut hits) = (0, 0);
        for k in 0..3000 {
            // Anywhere in and around the hall, some on whole and half metres (cell borders).
            let (mut x, mut y) = (24.0 * next() - 12.0, 24.0 * next() - 12.0);
            if k % 3 == 0 {
                (x, y) = ((x * 2.0).round() / 2.0, (y * 2.0).round() / 2.0);
            }
            let reach = [1.0, 4.0, 8.0][k % 3];
            let fan = Fan {
                first: 6.0 * next(),
                step: PI / 180.0,
                count: 181,
            };
            let beams = WallBeams::new(&grid, x, y, reach, fan);
            for i in 0..fan.count {
                let (dy, dx) = (fan.first + i as f64 * fan.step).sin_cos();
                let hit = grid.raycast_along(x, y, dx, dy, reach);
                hits += usize::from(hit.is_some());
                if !beams.may_meet(i) {
                    left_out += 1;
                    assert_eq!(hit, None, "beam {i} from ({x}, {y}) reaching {reach}");
                }
            }
        }
        assert!(left_out > 100_000 && hits > 50_000, "{left_out} {hits}");
    }
}
