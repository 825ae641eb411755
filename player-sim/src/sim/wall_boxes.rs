//! Which beams of a scan may meet a wall, from the walls' own rectangles: the raster's wall
//! cells are few boxes in a hall (the 1 024-robot swarm's border and six inner walls: ten
//! boxes once a bitmap's rows of pixels are merged), and a beam can only meet a wall cell by
//! passing through that cell's box. The quadtree of clearances (`wall_free.rs`) proves squares
//! of 2 m free and walks every beam towards any square it cannot prove: in the swarm six beams
//! in seven so walked met no wall, each a walk of up to 8 m through a 41-million-cell raster.
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

/// Side of the buckets the boxes are listed in, in cells (5 m at 2 cm).
const BUCKET: i64 = 256;

/// More boxes listed in the buckets a reach covers than this: not tested here (a cave's
/// hundreds of pixel rows), the caller's own test instead.
const MOST_BOXES: usize = 48;

/// A wall's cells: columns `x0..=x1` and rows `y0..=y1` (global cells).
pub(super) type CellBox = [i64; 4];

/// The boxes holding every wall cell of a raster, listed by bucket.
#[derive(Debug, Clone, PartialEq, Default)]
pub(super) struct WallBoxes {
    boxes: Vec<CellBox>,
    /// Global cell of the first bucket's first column and row.
    first: (i64, i64),
    columns: i64,
    rows: i64,
    /// Bucket `k`'s boxes are `members[starts[k]..starts[k + 1]]`.
    starts: Vec<u32>,
    members: Vec<u32>,
}

impl WallBoxes {
    /// The boxes `boxes`, which together hold exactly the wall cells, merged: boxes of the same
    /// rows in touching columns (a drawn line's cells), then of the same columns in touching
    /// rows (a bitmap's pixel rows into walls). The merged boxes hold the same cells.
    pub(super) fn new(mut boxes: Vec<CellBox>) -> WallBoxes {
        boxes.retain(|b| b[0] <= b[2] && b[1] <= b[3]);
        boxes.sort_unstable_by_key(|&[x0, y0, _, y1]| (y0, y1, x0));
        let mut rows: Vec<CellBox> = Vec::with_capacity(boxes.len());
        for b in boxes {
            match rows.last_mut() {
                Some(m) if m[1] == b[1] && m[3] == b[3] && b[0] <= m[2] + 1 => {
                    m[2] = m[2].max(b[2])
                }
                _ => rows.push(b),
            }
        }
        rows.sort_unstable_by_key(|&[x0, y0, x1, _]| (x0, x1, y0));
        let mut merged: Vec<CellBox> = Vec::with_capacity(rows.len());
        for b in rows {
            match merged.last_mut() {
                Some(m) if m[0] == b[0] && m[2] == b[2] && b[1] <= m[3] + 1 => {
                    m[3] = m[3].max(b[3])
                }
                _ => merged.push(b),
            }
        }
        let Some(low) = merged
            .iter()
            .map(|b| (b[0], b[1]))
            .reduce(|a, b| (a.0.min(b.0), a.1.min(b.1)))
        else {
            return WallBoxes::default();
        };
        let high = merged
            .iter()
            .fold(low, |a, b| (a.0.max(b[2]), a.1.max(b[3])));
        let columns = (high.0 - low.0) / BUCKET + 1;
        let rows = (high.1 - low.1) / BUCKET + 1;
        let mut walls = WallBoxes {
            boxes: Vec::new(),
            first: low,
            columns,
            rows,
            starts: vec![0; (columns * rows + 1) as usize],
            members: Vec::new(),
        };
        // A counting sort of (bucket, box) pairs, boxes in order within each bucket.
        let buckets: Vec<Vec<usize>> = merged.iter().map(|b| walls.buckets_of(b)).collect();
        for &k in buckets.iter().flatten() {
            walls.starts[k + 1] += 1;
        }
        for k in 0..walls.starts.len() - 1 {
            walls.starts[k + 1] += walls.starts[k];
        }
        let mut next = walls.starts.clone();
        walls.members = vec![0; walls.starts[walls.starts.len() - 1] as usize];
        for (i, of_box) in buckets.iter().enumerate() {
            for &k in of_box {
                walls.members[next[k] as usize] = i as u32;
                next[k] += 1;
            }
        }
        walls.boxes = merged;
        walls
    }

    /// The bucket columns and rows (inclusive, clamped to the grid) over cells `low..=high`.
    fn bucket_span(&self, low: (i64, i64), high: (i64, i64)) -> ((i64, i64), (i64, i64)) {
        let column = |v: i64| ((v - self.first.0).div_euclid(BUCKET)).clamp(0, self.columns - 1);
        let row = |v: i64| ((v - self.first.1).div_euclid(BUCKET)).clamp(0, self.rows - 1);
        ((column(low.0), row(low.1)), (column(high.0), row(high.1)))
    }

    /// How many boxes there are.
    /// Every box, merged.
    pub(super) fn all(&self) -> &[CellBox] {
        &self.boxes
    }

    pub(super) fn len(&self) -> usize {
        self.boxes.len()
    }

    /// Calls `f` once with each box that holds a cell of `low..=high` (global cells).
    pub(super) fn each_within(
        &self,
        low: (i64, i64),
        high: (i64, i64),
        mut f: impl FnMut(&CellBox),
    ) {
        if self.boxes.is_empty() {
            return;
        }
        let ((c0, r0), (c1, r1)) = self.bucket_span(low, high);
        for r in r0..=r1 {
            for c in c0..=c1 {
                let k = (r * self.columns + c) as usize;
                for &i in &self.members[self.starts[k] as usize..self.starts[k + 1] as usize] {
                    let b = &self.boxes[i as usize];
                    // Each box once: in the first bucket of the span that lists it.
                    let ((bc, br), _) = self.bucket_span((b[0], b[1]), (b[2], b[3]));
                    let meets = b[0] <= high.0 && b[2] >= low.0 && b[1] <= high.1 && b[3] >= low.1;
                    if bc.max(c0) == c && br.max(r0) == r && meets {
                        f(b);
                    }
                }
            }
        }
    }

    /// The buckets box `b` lies in.
    fn buckets_of(&self, b: &CellBox) -> Vec<usize> {
        let ((c0, r0), (c1, r1)) = self.bucket_span((b[0], b[1]), (b[2], b[3]));
        (r0..=r1)
            .flat_map(|r| (c0..=c1).map(move |c| (r * self.columns + c) as usize))
            .collect()
    }
}

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
        if walls.boxes.is_empty() {
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
        let ((c0, r0), (c1, r1)) = walls.bucket_span(low, high);
        let listed = |r: i64| {
            let row = r * walls.columns;
            (walls.starts[(row + c1 + 1) as usize] - walls.starts[(row + c0) as usize]) as usize
        };
        if (r0..=r1).map(listed).sum::<usize>() > MOST_BOXES {
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
    use crate::sim::test_randoms::randoms;
    use crate::world::{Floorplan, OccupancyGrid, World};

    use super::*;

    /// A 40 x 40 m hall of 0.5 m pixels with two inner walls and a pillar, and a drawn
    /// triangle (`floor_blocks`), on a raster of `resolution`.
    fn hall(resolution: f64) -> WallRaster {
        let mut rows = vec![String::from(&"#".repeat(80))];
        for r in 1..79 {
            let mut row = vec![b'.'; 80];
            (row[0], row[79]) = (b'#', b'#');
            if (10..50).contains(&r) {
                row[20] = b'#';
            }
            if (30..70).contains(&r) {
                row[60] = b'#';
            }
            if (30..34).contains(&r) {
                row[40..44].fill(b'#');
            }
            rows.push(String::from_utf8(row).unwrap());
        }
        rows.push(rows[0].clone());
        let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
        let mut world = World::default();
        world.resolution = resolution;
        world.floor = Some(OccupancyGrid::from_rows(&rows, 0.5, (-20.0, -20.0)));
        world.floorplan = Some(Floorplan {
            bitmap: Default::default(),
            size: [40.0, 40.0],
            centre: [0.0, 0.0],
            height: 1.0,
            color: [0, 0, 0],
        });
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
            .boxes
            .iter()
            .filter(|b| b[2] - b[0] > 8 || b[3] - b[1] > 8);
        assert_eq!(big.count(), 20, "{:?}", raster.boxes.boxes);
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
