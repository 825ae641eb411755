//! How many wall cells a rectangle of the floorplan holds, in constant time: a summed-area
//! table, built on first use. A sensor in open floor (no wall within its range of it, as for
//! most of a thousand robots in a hall) then casts no beam through the grid at all.

use std::sync::OnceLock;

/// Counts of wall cells below and left of each grid corner: `(width + 1) × (height + 1)`.
#[derive(Debug, Clone, Default)]
pub(super) struct WallSums(OnceLock<Vec<u32>>);

impl PartialEq for WallSums {
    /// Derived from the grid's cells: two grids with equal cells are equal, built or not.
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl WallSums {
    /// The table for `occupied` (`width` cells a row, from the south row up).
    fn table(&self, occupied: &[bool], width: usize) -> &[u32] {
        self.0.get_or_init(|| {
            let height = occupied.len().checked_div(width).unwrap_or(0);
            let stride = width + 1;
            let mut sums = vec![0u32; stride * (height + 1)];
            for row in 0..height {
                let mut in_row = 0;
                for column in 0..width {
                    in_row += u32::from(occupied[row * width + column]);
                    sums[(row + 1) * stride + column + 1] =
                        sums[row * stride + column + 1] + in_row;
                }
            }
            sums
        })
    }

    /// Wall cells in columns `c0..c1` and rows `r0..r1` (ends exclusive, within the grid).
    pub(super) fn count(
        &self,
        occupied: &[bool],
        width: usize,
        (c0, c1): (usize, usize),
        (r0, r1): (usize, usize),
    ) -> u32 {
        let sums = self.table(occupied, width);
        let at = |c: usize, r: usize| sums[r * (width + 1) + c];
        at(c1, r1) + at(c0, r0) - at(c0, r1) - at(c1, r0)
    }
}
