//! A ray walked through the [`WallRaster`]: cell by cell near walls, and in jumps across open
//! space — a cell `d` cells from the nearest wall lets the ray move `d - 1` cells along its
//! longer axis at once without passing any wall cell. The first wall cell the ray enters is the
//! one a cell-by-cell walk would find; the jumps only skip cells known to be free.
//!
//! The distance read is Stage's too, within its resolution: Stage counts a ray's length in
//! whole cells along the axis it moves along the more, so a wall entered across that axis
//! reads at the first whole step past its face (on average half a cell farther than the face).
//!
//! Which cell a point lies in follows Stage's rays: Stage finds a ray's cell by truncating its
//! coordinates (in cells) towards zero, while it floors the corners of the walls it marks, so
//! that west and south of the origin a ray meets a wall one cell before the cell the wall was
//! marked in. Matching that keeps readings there within a cell of Stage's instead of two.

use super::wall_raster::{WallRaster, quadrant};
use crate::world::floor_i64;

/// Cells a ray walks through: how far it may jump from a cell (0 on a solid cell).
pub(super) trait Cells {
    /// Cells per metre.
    fn per_metre(&self) -> f64;
    /// The free square of global cell `(x, y)` for a ray heading into quarter `q` (see
    /// [`WallRaster`]): 0 on a solid cell; a ray may move that many cells less one along its
    /// longer axis without entering a solid one.
    fn ahead(&self, x: i64, y: i64, q: usize) -> u32;
}

impl Cells for WallRaster {
    #[inline]
    fn per_metre(&self) -> f64 {
        self.per_metre
    }

    #[inline]
    fn ahead(&self, x: i64, y: i64, q: usize) -> u32 {
        WallRaster::ahead(self, x, y, q)
    }
}

/// The cell Stage's ray looks into for a point in floored cell `k` (see the module's note).
#[inline]
fn looked_into(k: i64) -> i64 {
    if k < 0 { k + 1 } else { k }
}

/// Clearances below this are walked cell by cell.
const JUMP_FROM: u32 = 2;

impl WallRaster {
    /// Distance from `(x, y)` along the unit direction `(dx, dy)` to where the ray enters the
    /// first wall cell, if within `max` (0 when it starts in one).
    pub fn cast(&self, x: f64, y: f64, dx: f64, dy: f64, max: f64) -> Option<f64> {
        walk(self, x, y, dx, dy, max)
    }
}

/// Distance from `(x, y)` along the unit direction `(dx, dy)` to where the ray enters the
/// first solid cell of `cells`, if within `max` (0 when it starts in one).
pub(super) fn walk<C: Cells>(cells: &C, x: f64, y: f64, dx: f64, dy: f64, max: f64) -> Option<f64> {
    let per_metre = cells.per_metre();
    let (gx, gy) = (x * per_metre, y * per_metre);
    let reach = max * per_metre;
    if !(gx.is_finite() && gy.is_finite() && reach >= 0.0 && dx.is_finite() && dy.is_finite()) {
        return None;
    }
    if dx == 0.0 && dy == 0.0 {
        let k = (looked_into(floor_i64(gx)), looked_into(floor_i64(gy)));
        return (cells.ahead(k.0, k.1, 0) == 0).then_some(0.0);
    }
    // Which axis the ray moves along the more, and how far per unit along the ray.
    // A diagonal's tie (to rounding: its sine and cosine may differ in the last bit) goes
    // to y, as a tie goes in Stage.
    let x_longer = dx.abs() > dy.abs() + 1e-12;
    let longer = if x_longer { dx.abs() } else { dy.abs() };
    let q = quadrant(dx, dy);
    let x_axis = Axis::new(gx, dx);
    let y_axis = Axis::new(gy, dy);
    // Along the ray, in cells: where the walk (re)starts.
    let mut from = 0.0f64;
    loop {
        let (mut kx, mut next_x) = x_axis.start(from);
        let (mut ky, mut next_y) = y_axis.start(from);
        // Where the ray entered the cell it is in.
        let mut entered = from;
        // Whether the ray entered its cell across a face of the longer axis.
        let mut across_longer = false;
        loop {
            let clear = cells.ahead(looked_into(kx), looked_into(ky), q);
            if clear == 0 {
                // Stage measures a ray in whole cells along its longer axis: through a
                // face across that axis, the first whole step past it.
                let walked = if across_longer {
                    (entered * longer - 1e-9).ceil() / longer
                } else {
                    entered
                };
                return (walked <= reach).then_some(walked / per_metre);
            }
            if clear >= JUMP_FROM {
                // Every cell whose looked-into cell is within `clear - 1` of this one's the
                // way the ray heads is free: jump to just before the ray leaves them.
                let d = i64::from(clear) - 1;
                let free = x_axis.free(kx, d, entered).min(y_axis.free(ky, d, entered));
                from = entered + free - 1e-9;
                if from > reach {
                    return None;
                }
                break;
            }
            // Through a corner (both faces at once, to rounding), the longer axis's face:
            // so that a ray a hair to either side of the corner reads the same.
            across_longer = if x_longer {
                next_x <= next_y + 1e-9
            } else {
                next_y <= next_x + 1e-9
            };
            if next_x < next_y {
                entered = next_x;
                kx += x_axis.step;
                next_x += x_axis.delta;
            } else {
                entered = next_y;
                ky += y_axis.step;
                next_y += y_axis.delta;
            }
            if entered > reach {
                return None;
            }
        }
    }
}

/// A ray's motion along one axis, in cells: from `origin`, `d` per unit along the ray.
struct Axis {
    origin: f64,
    d: f64,
    /// `1 / |d|`: how far along the ray one cell of this axis is (infinite when `d` is 0).
    delta: f64,
    /// The cell index's step: +1 or -1.
    step: i64,
}

impl Axis {
    fn new(origin: f64, d: f64) -> Axis {
        Axis {
            origin,
            d,
            delta: 1.0 / d.abs(),
            step: if d > 0.0 { 1 } else { -1 },
        }
    }

    /// The floored cell at `t` along the ray, and where along the ray it leaves that cell.
    #[inline]
    fn start(&self, t: f64) -> (i64, f64) {
        let p = self.origin + t * self.d;
        let k = floor_i64(p);
        if self.d == 0.0 {
            return (k, f64::INFINITY);
        }
        let edge = (k + i64::from(self.d > 0.0)) as f64;
        (k, t + (edge - p).abs() * self.delta)
    }

    /// How far along the ray, from `t` (in floored cell `k`), the ray stays among the cells
    /// whose looked-into cell is within `reach` of `k`'s.
    #[inline]
    fn free(&self, k: i64, reach: i64, t: f64) -> f64 {
        let m = looked_into(k);
        let p = self.origin + t * self.d;
        if self.d > 0.0 {
            // The last floored cell looked into as `m + reach` or nearer: the ray leaves it
            // at its upper edge.
            let v = m + reach;
            let last = if v >= 0 { v } else { v - 1 };
            ((last + 1) as f64 - p) * self.delta
        } else if self.d < 0.0 {
            let u = m - reach;
            let first = if u >= 1 { u } else { u - 1 };
            (p - first as f64) * self.delta
        } else {
            f64::INFINITY
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::test_randoms::randoms;
    use crate::world::OccupancyGrid;

    /// The first wall cell along the ray by marching in steps of a thousandth of a cell.
    fn marched(r: &WallRaster, x: f64, y: f64, dx: f64, dy: f64, max: f64) -> Option<f64> {
        let (gx, gy) = (x * r.per_metre, y * r.per_metre);
        let steps = (max * r.per_metre * 1000.0) as usize;
        (0..=steps).map(|k| k as f64 / 1000.0).find_map(|t| {
            let (cx, cy) = (floor_i64(gx + t * dx), floor_i64(gy + t * dy));
            r.is_wall(looked_into(cx), looked_into(cy))
                .then_some(t / r.per_metre)
        })
    }

    #[test]
    fn jumps_find_the_wall_cell_a_march_finds() {
        // Pillars, a wall and lone cells in a 6 x 6 m hall of 0.2 m cells, around the origin
        // (where Stage's rays look into the cell beside the marked one).
        let mut rows = vec![String::from("##############################")];
        for r in 1..29 {
            let mut row: Vec<u8> = b"#............................#".to_vec();
            if (5..20).contains(&r) {
                row[17] = b'#';
            }
            if r % 7 == 0 {
                row[(r * 5) % 27 + 1] = b'#';
            }
            rows.push(String::from_utf8(row).unwrap());
        }
        rows.push(rows[0].clone());
        let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
        let mut world = crate::world::World::default();
        world.resolution = 0.05;
        world.floor = Some(OccupancyGrid::from_rows(&rows, 0.2, (-3.0, -3.0)));
        world.floorplan = Some(crate::world::Floorplan {
            bitmap: Default::default(),
            size: [6.0, 6.0],
            centre: [0.0, 0.0],
            height: 1.0,
            color: [0, 0, 0],
        });
        let raster = WallRaster::of(&world).expect("walls");
        let mut next = randoms(0x5A57E4);
        let mut hits = 0;
        for _ in 0..400 {
            let (x, y) = (5.6 * next() - 2.8, 5.6 * next() - 2.8);
            let (dy, dx) = (std::f64::consts::TAU * next()).sin_cos();
            let max = 1.0 + 6.0 * next();
            let want = marched(&raster, x, y, dx, dy, max);
            let got = raster.cast(x, y, dx, dy, max);
            hits += usize::from(got.is_some());
            // Stage's reading: at the face, or the first whole cell past it along the ray's
            // longer axis.
            let step = 1.0 / dx.abs().max(dy.abs()) / raster.per_metre;
            match (want, got) {
                (Some(a), Some(b)) => {
                    assert!(
                        b > a - 1e-4 && b < a + step + 1e-4,
                        "{a} {b} from ({x}, {y})"
                    )
                }
                // A whole step past a wall near the end of the reach may leave it.
                (Some(a), None) => assert!(a + step > max - 1e-4, "{a} from ({x}, {y})"),
                (None, b) => assert_eq!(b, None, "from ({x}, {y})"),
            }
        }
        assert!(hits > 200, "{hits}");
    }
}
