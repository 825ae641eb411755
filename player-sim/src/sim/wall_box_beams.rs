//! Which beams of a scan may meet a wall, from the walls' own rectangles (`wall_boxes.rs`): a
//! beam can only meet a wall cell by passing through that cell's box. The quadtree of
//! clearances (`wall_free.rs`) proves squares of 2 m free and walks every beam towards any
//! square it cannot prove: in the swarm six beams in seven so walked met no wall, each a walk
//! of up to 8 m through a 41-million-cell raster.
//! Here a beam walks only when it passes through a wall box widened by a few cells and cut to
//! the sensor's reach: nearly every beam walked meets its wall.
//!
//! A point of a ray lies in floored cell `k`, and the walk looks into `k` or (west and south of
//! the origin) `k + 1` (see `raster_walk.rs`), on Stage's stepped path, which strays up to
//! [`PATH_SLACK`] cells from the ray's line: a wall cell `w` is found only from a line passing
//! within that many cells and one of it, within the reach. Widened by [`MARGIN`] cells all
//! round and cut to the disc of the reach plus the margin, a box's directions from the sensor
//! hold every beam that may find one of its cells. The other beams meet no wall: readings cannot
//! change (tested against the walk below).

use super::beams::{Fan, beams_spanning};
use super::wall_free::PATH_SLACK;
use super::wall_raster::WallRaster;
use super::wrap;

/// Cells each box is widened by on every side, and the reach beyond the sensor's: the path's
/// stray, the cell beside a point's and a hair more.
const MARGIN: f64 = (PATH_SLACK + 2) as f64;

/// More boxes listed in the buckets a reach covers than this: not tested here (a cave's
/// hundreds of pixel rows), the caller's own test instead.
const MOST_BOXES: usize = 48;

impl WallRaster {
    /// For each beam of `fan` from `(x, y)` reaching `max` metres, whether it may meet a wall
    /// cell (a beam marked `false` meets none); `None` when too many boxes lie near to tell.
    pub(super) fn beams_to_walls(&self, x: f64, y: f64, max: f64, fan: Fan) -> Option<Vec<bool>> {
        let walls = &self.boxes;
        // In cells, as the walk measures.
        let (gx, gy) = (x * self.per_metre, y * self.per_metre);
        let reach = max * self.per_metre + MARGIN;
        if !(gx.is_finite() && gy.is_finite() && reach.is_finite() && reach >= 0.0) {
            return None;
        }
        let mut may_meet = vec![false; fan.count];
        if walls.len() == 0 {
            return Some(may_meet);
        }
        let (low, high) = (
            (
                (gx - reach).floor() as i64 - 1,
                (gy - reach).floor() as i64 - 1,
            ),
            (
                (gx + reach).ceil() as i64 + 1,
                (gy + reach).ceil() as i64 + 1,
            ),
        );
        if walls.listed_within(low, high) > MOST_BOXES {
            return None;
        }
        walls.each_within(low, high, |b| {
            let widened = [
                b[0] as f64 - MARGIN,
                b[1] as f64 - MARGIN,
                (b[2] + 1) as f64 + MARGIN,
                (b[3] + 1) as f64 + MARGIN,
            ];
            for (lo, hi) in beams_into(fan, (gx, gy), reach, widened) {
                may_meet[lo..hi].fill(true);
            }
        });
        Some(may_meet)
    }
}

/// The beams of `fan` from `s` that pass through the part of the box `[x0, y0, x1, y1]` within
/// `reach` of `s`: every beam from within the box; from outside, those within the directions
/// of that part's corners (the box's corners within the disc, and where its sides cross the
/// circle: the part is convex and does not hold `s`, so its directions span less than half a
/// turn and end at two of those points).
fn beams_into(
    fan: Fan,
    s: (f64, f64),
    reach: f64,
    [x0, y0, x1, y1]: [f64; 4],
) -> [(usize, usize); 2] {
    let none = [(0, 0), (0, 0)];
    let all = [(0, fan.count), (0, 0)];
    let (nx, ny) = (
        (x0 - s.0).max(s.0 - x1).max(0.0),
        (y0 - s.1).max(s.1 - y1).max(0.0),
    );
    if nx * nx + ny * ny > reach * reach {
        return none;
    }
    if nx == 0.0 && ny == 0.0 {
        return all;
    }
    let r2 = reach * reach;
    let mut points = [(0.0, 0.0); 12];
    let mut n = 0;
    let mut add = |px: f64, py: f64| {
        points[n] = (px - s.0, py - s.1);
        n += 1;
    };
    for (cx, cy) in [(x0, y0), (x1, y0), (x0, y1), (x1, y1)] {
        if (cx - s.0).powi(2) + (cy - s.1).powi(2) <= r2 {
            add(cx, cy);
        }
    }
    // Where the sides cross the circle.
    for (at, from, to, vertical) in [
        (x0, y0, y1, true),
        (x1, y0, y1, true),
        (y0, x0, x1, false),
        (y1, x0, x1, false),
    ] {
        let off = at - if vertical { s.0 } else { s.1 };
        let left = r2 - off * off;
        if left < 0.0 {
            continue;
        }
        let along = left.sqrt();
        let centre = if vertical { s.1 } else { s.0 };
        for v in [centre - along, centre + along] {
            if (from..=to).contains(&v) {
                if vertical { add(at, v) } else { add(v, at) }
            }
        }
    }
    if n == 0 {
        // Rounding at a tangent: every beam rather than a guess.
        return all;
    }
    let (mx, my) = points[..n]
        .iter()
        .fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
    let centre = my.atan2(mx);
    let (mut low, mut high) = (0.0f64, 0.0f64);
    for &(px, py) in &points[..n] {
        let off = wrap(py.atan2(px) - centre);
        (low, high) = (low.min(off), high.max(off));
    }
    let half = (high - low) / 2.0 + 1e-9;
    // NaN included.
    if half.is_nan() || half >= std::f64::consts::FRAC_PI_2 - 1e-6 {
        return all;
    }
    beams_spanning(fan, centre + (low + high) / 2.0, half)
}

#[cfg(test)]
mod tests {
    use crate::sim::test_halls::{bordered, walled};
    use crate::sim::test_randoms::randoms;

    use super::*;

    /// A 40 x 40 m hall of 0.5 m pixels with two inner walls and a pillar, and a drawn
    /// triangle (`floor_blocks`), on a raster of `resolution`.
    fn hall(resolution: f64) -> WallRaster {
        let rows = bordered(80, 80, |r, c| {
            (c == 20 && (10..50).contains(&r))
                || (c == 60 && (30..70).contains(&r))
                || ((40..44).contains(&c) && (30..34).contains(&r))
        });
        let mut world = walled(&rows, 0.5, resolution);
        world.floor_blocks = vec![vec![[5.0, -12.0], [9.0, -11.0], [6.5, -8.0]]];
        WallRaster::of(&world).expect("walls")
    }

    #[test]
    fn a_beam_left_out_meets_no_wall() {
        let raster = hall(0.05);
        // The bitmap's walls as Stage marks them, their outlines: the border ring's outer and
        // inner sides (8), each inner wall's four sides (8, a pixel is 10 cells) and the
        // pillar's four; each line of the drawn triangle a box for each run of its cells.
        let big = raster
            .boxes
            .all()
            .iter()
            .filter(|b| b[2] - b[0] > 8 || b[3] - b[1] > 8);
        assert_eq!(big.count(), 20, "{:?}", raster.boxes.all());
        let mut next = randoms(0xB0C5);
        let (mut skipped, mut walked, mut hits) = (0, 0, 0);
        for k in 0..4000 {
            // Anywhere in and around the hall, some on whole cells and whole metres.
            let (mut x, mut y) = (48.0 * next() - 24.0, 48.0 * next() - 24.0);
            if k % 3 == 0 {
                (x, y) = ((x * 20.0).round() / 20.0, (y * 2.0).round() / 2.0);
            }
            let max = [0.5, 2.0, 5.0, 8.0][k % 4];
            let fan = Fan {
                first: 7.0 * next() - 3.5,
                step: [std::f64::consts::PI / 180.0, std::f64::consts::TAU / 360.0][k % 2],
                count: [181, 360][k % 2],
            };
            let Some(may_meet) = raster.beams_to_walls(x, y, max, fan) else {
                continue;
            };
            for (i, &may) in may_meet.iter().enumerate() {
                let (dy, dx) = (fan.first + i as f64 * fan.step).sin_cos();
                let hit = raster.cast(x, y, dx, dy, max);
                if may {
                    walked += 1;
                    hits += usize::from(hit.is_some());
                } else {
                    skipped += 1;
                    assert_eq!(hit, None, "beam {i} from ({x}, {y}) reaching {max}");
                }
            }
        }
        // Most beams are left out, and most of those walked meet their wall (fewer from points
        // inside a wall, which walk to its far side).
        assert!(skipped > 550_000 && walked > 50_000, "{skipped} {walked}");
        assert!(hits * 4 > walked * 3, "{hits} of {walked}");
    }
}
