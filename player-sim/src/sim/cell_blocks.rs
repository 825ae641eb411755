//! A raster of bytes kept in blocks of 8 × 8 cells, each block one 64-byte cache line, instead
//! of row by row. A ray nearing a wall reads a few cells close together, a row or a column
//! apart: row by row each of those reads was a line of its own (a row of the cave's raster is
//! 800 bytes), and the read of a cell's free square was half the walls' walk, waiting on memory.
//! In blocks, the last cells before a wall mostly share a line.

/// Cells a block spans each way, as a shift.
const SIDE_BITS: usize = 3;
const SIDE: usize = 1 << SIDE_BITS;

/// One block's cells, row by row from the south, on a cache line of its own.
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(align(64))]
struct Block([u8; SIDE * SIDE]);

/// A `width` × `height` raster of bytes in blocks.
#[derive(Debug, Clone, PartialEq, Default)]
pub(super) struct CellBlocks {
    /// Blocks in a row of blocks.
    across: usize,
    blocks: Vec<Block>,
}

impl CellBlocks {
    /// The raster whose rows (from the south, each `width` long) are `rows`.
    pub(super) fn from_rows(rows: &[u8], width: usize) -> CellBlocks {
        let height = rows.len().checked_div(width).unwrap_or(0);
        let across = width.div_ceil(SIDE);
        let down = height.div_ceil(SIDE);
        let mut blocks = vec![Block([0; SIDE * SIDE]); across * down];
        for (r, row) in rows.chunks_exact(width.max(1)).enumerate() {
            for (c, &v) in row.iter().enumerate() {
                let (block, within) = Self::place(across, c, r);
                blocks[block].0[within] = v;
            }
        }
        CellBlocks { across, blocks }
    }

    /// The block of cell `(c, r)` and its place within it.
    #[inline]
    fn place(across: usize, c: usize, r: usize) -> (usize, usize) {
        let block = (r >> SIDE_BITS) * across + (c >> SIDE_BITS);
        let within = ((r & (SIDE - 1)) << SIDE_BITS) | (c & (SIDE - 1));
        (block, within)
    }

    /// Cell `(c, r)`'s byte; the caller keeps within the raster.
    #[inline]
    pub(super) fn get(&self, c: usize, r: usize) -> u8 {
        let (block, within) = Self::place(self.across, c, r);
        self.blocks[block].0[within]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_cell_reads_as_its_row_had_it() {
        // Sides that are and are not whole blocks.
        for (width, height) in [(8, 8), (13, 5), (1, 17), (40, 30)] {
            let rows: Vec<u8> = (0..width * height).map(|k| (k * 7 % 251) as u8).collect();
            let blocks = CellBlocks::from_rows(&rows, width);
            for r in 0..height {
                for c in 0..width {
                    assert_eq!(blocks.get(c, r), rows[r * width + c], "({c}, {r})");
                }
            }
        }
    }
}
