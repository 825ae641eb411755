//! Which boxes each beam of a scan may meet. A box seen from the sensor covers a narrow fan of
//! directions (a robot 5 m away, about 6° of a laser's 180°): listing, once per scan, the
//! beams inside each box's fan lets a beam test the two or three boxes in its direction
//! instead of every box near the sensor, and a beam with none in its direction (and no wall
//! within reach) reads its maximum without any trigonometry.
//!
//! The fans are widened by a beam on each side, so that a beam is listed for every box whose
//! bounding circle it could touch (the caller still tests each box exactly). A box is only its
//! bounding circle here, so that the beams know nothing of what the boxes are.

use std::f64::consts::{PI, TAU};

use smallvec::SmallVec;

use super::quick_angles;
use crate::world::floor_i64;

/// Evenly spaced beams: beam `i` points at `first + i * step` (world angle).
#[derive(Debug, Clone, Copy)]
pub struct Fan {
    pub first: f64,
    pub step: f64,
    pub count: usize,
}

/// For each beam of a [`Fan`], the boxes (indices in the order their circles were given) in
/// its direction, in increasing order.
#[derive(Debug, Clone)]
pub struct BeamBoxes {
    /// Beam `i`'s boxes are `boxes[starts[i]..starts[i + 1]]`.
    starts: Vec<u32>,
    boxes: Vec<u32>,
}

impl BeamBoxes {
    /// Lists the boxes whose bounding circles (centre and radius) are `circles` by the beams
    /// from `(x, y)` of `fan` that may meet them.
    pub fn new(
        circles: impl Iterator<Item = (f64, f64, f64)>,
        x: f64,
        y: f64,
        fan: Fan,
    ) -> BeamBoxes {
        let n = fan.count;
        // Each box's beams as (first, last) ranges; at most two (a fan over the full circle
        // may see one box at both of its ends). Inline for the boxes about a scan.
        let ranges: SmallVec<[[(usize, usize); 2]; 32]> = circles
            .map(|(cx, cy, radius)| beams_towards(fan, cx - x, cy - y, radius))
            .collect();
        // A counting sort by beam in one list: each beam's count at its end, then where each
        // begins, then (filled in order, so each beam's boxes stay in increasing order) where
        // each ends, moved back a place to be where the next begins.
        let mut starts = vec![0u32; n + 1];
        for (lo, hi) in ranges.iter().flatten().copied() {
            for c in &mut starts[lo + 1..hi + 1] {
                *c += 1;
            }
        }
        for i in 0..n {
            starts[i + 1] += starts[i];
        }
        let mut boxes = vec![0u32; starts[n] as usize];
        for (k, both) in ranges.iter().enumerate() {
            for &(lo, hi) in both {
                for next in &mut starts[lo..hi] {
                    boxes[*next as usize] = k as u32;
                    *next += 1;
                }
            }
        }
        starts.copy_within(0..n, 1);
        starts[0] = 0;
        BeamBoxes { starts, boxes }
    }

    /// The boxes in beam `i`'s direction, in increasing order.
    pub fn of(&self, i: usize) -> &[u32] {
        &self.boxes[self.starts[i] as usize..self.starts[i + 1] as usize]
    }
}

/// The beams of `fan` that may pass within `radius` of the point `(cx, cy)` (relative to the
/// sensor), ahead of it: up to two half-open ranges of beam indices (empty ones `(0, 0)`);
/// every beam from within the circle.
pub(super) fn beams_towards(fan: Fan, cx: f64, cy: f64, radius: f64) -> [(usize, usize); 2] {
    let all = [(0, fan.count), (0, 0)];
    // A square root, not `hypot` (a call into the maths library, for every box of every scan).
    let distance = (cx * cx + cy * cy).sqrt();
    // A box around the sensor, or a fan that is not spread: every beam (NaNs included).
    let apart = distance > radius * (1.0 + 1e-9) + 1e-9;
    let spread = fan.step > 1e-9 && fan.count >= 2;
    if !apart || !spread {
        return all;
    }
    // Both angles a little wide of the exact ones at most, so the fan a little wider.
    let half = quick_angles::asin(radius / distance) + 2.0 * quick_angles::ANGLE_ERROR;
    let bearing = quick_angles::atan2(cy, cx);
    // `half` is below π/2 here: a box never covers more than half a turn of directions.
    debug_assert!(half < PI / 2.0 + 3.0 * quick_angles::ANGLE_ERROR || half.is_nan());
    beams_spanning(fan, bearing, half)
}

/// The beams of `fan` whose direction is within `half` (below π/2) of `bearing`, widened by a
/// beam on each side: up to two half-open ranges of beam indices (empty ones `(0, 0)`).
pub(super) fn beams_spanning(fan: Fan, bearing: f64, half: f64) -> [(usize, usize); 2] {
    let all = [(0, fan.count), (0, 0)];
    if !(fan.step > 1e-9 && fan.count >= 2) {
        return all;
    }
    // The bearing from the first beam, in [0, 2π); the fan spans [0, (count-1) step].
    let from_first = (bearing - fan.first).rem_euclid(TAU);
    if !from_first.is_finite() || !half.is_finite() {
        return all;
    }
    // The box's fan, and the same a turn before and after: a fan of beams spanning nearly a
    // turn sees a box near its first beam from its last ones too.
    let last = (fan.count - 1) as i64;
    let mut out = [(0, 0); 2];
    let mut found = 0;
    for centre in [from_first, from_first - TAU, from_first + TAU] {
        // `floor` and `ceil` without the calls (`floor_i64`); the quotients are finite and
        // within about 2e10 (a step of at least 1e-9 across at most two turns).
        let lo = floor_i64((centre - half) / fan.step).saturating_sub(1);
        let hi = floor_i64(-(centre + half) / fan.step)
            .saturating_neg()
            .saturating_add(1);
        if hi < 0 || lo > last {
            continue;
        }
        if found == 2 {
            return all;
        }
        out[found] = (lo.max(0) as usize, hi.min(last) as usize + 1);
        found += 1;
    }
    // Two ranges that meet (a fan wider than a turn): every beam, each listed once.
    let [(a, b), (c, d)] = out;
    if found == 2 && a < d && c < b {
        return all;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each beam lists, in increasing order, exactly the boxes whose beams take it in.
    #[test]
    fn each_beam_lists_the_boxes_in_its_direction_in_order() {
        let fan = Fan {
            first: -PI / 2.0,
            step: PI / 180.0,
            count: 181,
        };
        let circles: Vec<(f64, f64, f64)> = (0..40)
            .map(|k| {
                let a = k as f64 * 0.77;
                let d = 0.2 + (k % 7) as f64;
                (d * a.cos(), d * a.sin(), 0.1 + (k % 3) as f64 * 0.3)
            })
            .collect();
        let lists = BeamBoxes::new(circles.iter().copied(), 0.0, 0.0, fan);
        for i in 0..fan.count {
            let want: Vec<u32> = (0..circles.len() as u32)
                .filter(|&k| {
                    let (cx, cy, r) = circles[k as usize];
                    let ranges = beams_towards(fan, cx, cy, r);
                    ranges.iter().any(|&(lo, hi)| (lo..hi).contains(&i))
                })
                .collect();
            assert_eq!(lists.of(i), &want[..], "beam {i}");
        }
    }

    #[test]
    fn a_box_ahead_is_listed_for_the_beams_around_its_bearing() {
        // 181 beams over 180°, the first at -90°.
        let fan = Fan {
            first: -PI / 2.0,
            step: PI / 180.0,
            count: 181,
        };
        let [(lo, hi), rest] = beams_towards(fan, 5.0, 0.0, 0.29);
        assert_eq!(rest, (0, 0));
        // asin(0.29 / 5) ≈ 3.3°: beams 86.7..93.3, widened by one.
        assert!(lo <= 86 && hi >= 94 && lo >= 84 && hi <= 96, "{lo}..{hi}");
        assert_eq!(beams_towards(fan, -5.0, 0.0, 0.29), [(0, 0), (0, 0)]);
        assert_eq!(beams_towards(fan, 0.1, 0.0, 0.29), [(0, 181), (0, 0)]);
        // A full circle of beams sees a box at its seam from both ends.
        let ring = Fan {
            first: 0.0,
            step: TAU / 360.0,
            count: 360,
        };
        let [(a, b), (c, d)] = beams_towards(ring, 5.0, 0.0, 0.29);
        assert!(a == 0 && b > 0 && d == 360 && c < 360, "{a}..{b}, {c}..{d}");
    }
}
