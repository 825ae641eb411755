//! Stage's regions: squares of 32 × 32 cells, from the origin's cell on a grid of 32. Stage
//! walks a ray cell by cell only through regions where something (a wall, a robot, a box, a
//! body mounted on a robot, the sensor itself) has marked a cell, and jumps across the others,
//! so which regions hold something decides the path of every ray that passes them.

/// Cells along a region's side, as a power of two.
pub(in crate::sim) const REGION_BITS: u32 = 5;

/// The region (along one axis) of global cell `c`.
#[inline]
pub(in crate::sim) fn region_of(c: i64) -> i64 {
    c >> REGION_BITS
}

/// Which regions hold something.
pub(in crate::sim) trait Regions {
    /// Has anything marked a cell of region `(x, y)`?
    fn populated(&self, x: i64, y: i64) -> bool;
}

/// Which regions hold something, over the regions of a rectangle of cells (none beyond it): a
/// scan's, the walls' and its bodies' within its reach, read in one step a region.
#[derive(Debug, Clone, Default, PartialEq)]
pub(in crate::sim) struct RegionMap {
    first: (i64, i64),
    width: i64,
    height: i64,
    held: Vec<bool>,
}

impl RegionMap {
    /// No region held, over the regions of the cells from `low` to `high`.
    pub(in crate::sim) fn over(low: (i64, i64), high: (i64, i64)) -> RegionMap {
        let first = (region_of(low.0), region_of(low.1));
        let (width, height) = (
            (region_of(high.0) - first.0 + 1).max(0),
            (region_of(high.1) - first.1 + 1).max(0),
        );
        RegionMap {
            first,
            width,
            height,
            held: vec![false; (width * height) as usize],
        }
    }

    #[inline]
    fn index(&self, x: i64, y: i64) -> Option<usize> {
        let (c, r) = (x - self.first.0, y - self.first.1);
        // One comparison an axis: below 0 wraps past any width.
        ((c as u64) < self.width as u64 && (r as u64) < self.height as u64)
            .then(|| (r * self.width + c) as usize)
    }

    /// Region `(x, y)` holds something (ignored beyond the map).
    pub(in crate::sim) fn hold(&mut self, x: i64, y: i64) {
        if let Some(k) = self.index(x, y) {
            self.held[k] = true;
        }
    }

    /// The regions `other` holds, held here too (within this map): row by row, the rows'
    /// overlap at once (every scan takes in the walls' regions within its reach).
    pub(in crate::sim) fn hold_all(&mut self, other: &RegionMap) {
        let from = self.first.0.max(other.first.0);
        let to = (self.first.0 + self.width).min(other.first.0 + other.width);
        if from >= to {
            return;
        }
        let rows = self.first.1.max(other.first.1)
            ..(self.first.1 + self.height).min(other.first.1 + other.height);
        for y in rows {
            let mine = ((y - self.first.1) * self.width + from - self.first.0) as usize;
            let theirs = ((y - other.first.1) * other.width + from - other.first.0) as usize;
            let n = (to - from) as usize;
            for (a, &b) in self.held[mine..mine + n]
                .iter_mut()
                .zip(&other.held[theirs..theirs + n])
            {
                *a |= b;
            }
        }
    }
}

impl Regions for RegionMap {
    #[inline]
    fn populated(&self, x: i64, y: i64) -> bool {
        self.index(x, y).is_some_and(|k| self.held[k])
    }
}

/// The regions either of two sets holds.
pub(in crate::sim) struct Both<'a, A: ?Sized, B: ?Sized>(pub &'a A, pub &'a B);

impl<A: Regions + ?Sized, B: Regions + ?Sized> Regions for Both<'_, A, B> {
    #[inline]
    fn populated(&self, x: i64, y: i64) -> bool {
        self.0.populated(x, y) || self.1.populated(x, y)
    }
}

impl<R: Regions + ?Sized> Regions for Option<&R> {
    #[inline]
    fn populated(&self, x: i64, y: i64) -> bool {
        self.is_some_and(|r| r.populated(x, y))
    }
}

/// Some regions, listed in order.
#[derive(Debug, Clone, Default, PartialEq)]
pub(in crate::sim) struct Listed(Vec<(i64, i64)>);

impl Listed {
    /// Adds the region of global cell `(x, y)`.
    pub(in crate::sim) fn add_cell(&mut self, x: i64, y: i64) {
        let r = (region_of(x), region_of(y));
        if let Err(at) = self.0.binary_search(&r) {
            self.0.insert(at, r);
        }
    }
}

#[cfg(test)]
impl Listed {
    /// The regions, in order.
    pub(in crate::sim) fn listed(&self) -> &[(i64, i64)] {
        &self.0
    }
}

impl Regions for Listed {
    #[inline]
    fn populated(&self, x: i64, y: i64) -> bool {
        !self.0.is_empty() && self.0.binary_search(&(x, y)).is_ok()
    }
}

/// No region: every one but the ray's start is jumped.
pub(in crate::sim) struct Nowhere;

impl Regions for Nowhere {
    fn populated(&self, _: i64, _: i64) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Holding another map's regions holds exactly those within this map, whichever way the
    /// two overlap (or do not).
    #[test]
    fn holding_all_of_another_map_holds_its_regions_within_this_one() {
        let mut other = RegionMap::over((-100, -70), (90, 200));
        for (x, y) in [(-4, -3), (0, 0), (2, 6), (-1, 5), (1, -2), (2, -3)] {
            other.hold(x, y);
        }
        for low in [(-300, -300), (-40, 10), (0, 0), (60, -100), (500, 500)] {
            for high in [(-200, 40), (30, 100), (400, 400)] {
                let mut map = RegionMap::over(low, high);
                map.hold(region_of(high.0), region_of(high.1));
                let before = map.clone();
                map.hold_all(&other);
                for y in -12..16 {
                    for x in -12..16 {
                        let inside = map.index(x, y).is_some();
                        let want = before.populated(x, y) || (inside && other.populated(x, y));
                        assert_eq!(map.populated(x, y), want, "{low:?} {high:?} ({x}, {y})");
                    }
                }
            }
        }
    }
}
