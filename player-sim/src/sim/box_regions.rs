//! The regions of Stage's raster a box's cells lie in, which rays walk cell by cell rather
//! than jump (`sim/raster_walk.rs`): those its outline's cells pass through, as Stage counts
//! only the cells it marks. Not every region its corners' cells span: a turned box across a
//! region's corner may leave one of the four untouched, and Stage jumps a ray across that
//! region. In uoa_robotics_lab a robot turned by 120 degrees spanned such a corner: walking
//! the empty region moved its laser's stepped path by half a cell, and a dozen beams met other
//! table legs than Stage's.

use super::box_cells::Placed;
use super::raster_walk::{RegionMap, region_of};
use super::wall_raster::line_cells;

impl Placed<'_> {
    /// Adds the regions of Stage's raster (`resolution`) the box's outline cells lie in.
    pub(super) fn add_regions(&self, resolution: f64, regions: &mut RegionMap) {
        self.each_region(resolution, |x, y| regions.hold(x, y));
    }

    /// Calls `hold` with each region the box's outline cells lie in (some more than once).
    fn each_region(&self, resolution: f64, mut hold: impl FnMut(i64, i64)) {
        let per_metre = 1.0 / resolution;
        if !(per_metre.is_finite() && per_metre > 0.0) {
            return;
        }
        let corners = self.corner_cells(per_metre);
        let (mut low, mut high) = ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN));
        for &(x, y) in corners.iter().flatten() {
            low = (low.0.min(x), low.1.min(y));
            high = (high.0.max(x), high.1.max(y));
        }
        // A hall-sized box is skipped: its regions would be too many to list.
        if low.0 > high.0 || (high.0 - low.0).max(high.1 - low.1) > 4 * 32 {
            return;
        }
        for polygon in &corners {
            for (k, &a) in polygon.iter().enumerate() {
                hold_edge(a, polygon[(k + 1) % polygon.len()], &mut hold);
            }
        }
    }
}

/// Holds the regions the cells of the edge from cell `a` to cell `b` lie in. Its cells step
/// from `a` to `b` a column or a row at a time, within the rectangle of its ends: an edge
/// with its ends in one row (or column) of regions crosses each region between them, and only
/// one across a region's corner needs its cells walked.
fn hold_edge(a: (i64, i64), b: (i64, i64), hold: &mut impl FnMut(i64, i64)) {
    let (ra, rb) = (
        (region_of(a.0), region_of(a.1)),
        (region_of(b.0), region_of(b.1)),
    );
    if ra.0 == rb.0 || ra.1 == rb.1 {
        for y in ra.1.min(rb.1)..=ra.1.max(rb.1) {
            for x in ra.0.min(rb.0)..=ra.0.max(rb.0) {
                hold(x, y);
            }
        }
    } else {
        line_cells(a, b, |x, y| hold(region_of(x), region_of(y)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::raster_walk::Regions;

    #[test]
    fn a_turned_box_holds_only_the_regions_its_outline_crosses() {
        // A bar turned by -45 degrees across the corner where four regions of 32 cells meet
        // (1 m cells): its corners span all four, its outline (x + y below 62 cells) never
        // reaches the north-east one, which Stage leaves empty and its rays jump.
        let (sin, cos) = (-std::f64::consts::FRAC_PI_4).sin_cos();
        let bar = Placed {
            x: 30.5,
            y: 30.5,
            sin,
            cos,
            half_length: 4.0 * std::f64::consts::SQRT_2,
            half_width: 0.3,
            shape: &[],
        };
        let mut regions = RegionMap::over((0, 0), (95, 95));
        bar.add_regions(1.0, &mut regions);
        assert!(regions.populated(0, 0) && regions.populated(1, 0) && regions.populated(0, 1));
        assert!(!regions.populated(1, 1));
        // A box within one region holds it.
        let mut one = RegionMap::over((0, 0), (95, 95));
        Placed::leg(40.0, 40.0).add_regions(1.0, &mut one);
        assert!(one.populated(1, 1) && !one.populated(0, 0));
    }
}
