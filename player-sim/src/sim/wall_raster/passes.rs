//! The passes that fill a raster once its walls are marked: each cell's clearance, and its
//! free square towards each quarter of directions (what a ray jumps across).

use super::{MAX_CLEARANCE, WallRaster};
use crate::sim::cell_blocks::CellBlocks;

impl WallRaster {
    /// Each cell's distance in cells to the nearest wall cell (the larger of the column and
    /// row differences): two passes over the raster, each taking the smaller of a cell and its
    /// already-passed neighbours' plus one.
    pub(super) fn count_clearance(&mut self) {
        let (w, h) = (self.width, self.height);
        let c = &mut self.clearance;
        let near = |v: u8| v.saturating_add(1);
        for r in 0..h {
            for x in 0..w {
                let k = r * w + x;
                let mut v = c[k];
                if x > 0 {
                    v = v.min(near(c[k - 1]));
                }
                if r > 0 {
                    v = v.min(near(c[k - w]));
                    if x > 0 {
                        v = v.min(near(c[k - w - 1]));
                    }
                    if x + 1 < w {
                        v = v.min(near(c[k - w + 1]));
                    }
                }
                c[k] = v;
            }
        }
        for r in (0..h).rev() {
            for x in (0..w).rev() {
                let k = r * w + x;
                let mut v = c[k];
                if x + 1 < w {
                    v = v.min(near(c[k + 1]));
                }
                if r + 1 < h {
                    v = v.min(near(c[k + w]));
                    if x + 1 < w {
                        v = v.min(near(c[k + w + 1]));
                    }
                    if x > 0 {
                        v = v.min(near(c[k + w - 1]));
                    }
                }
                c[k] = v;
            }
        }
        // The four quarters' squares are independent passes over the raster (each a second of
        // the 1 024-robot swarm's 41-million-cell hall on one core): one thread each.
        let raster = &*self;
        self.ahead = std::thread::scope(|scope| {
            let quarters =
                [0, 1, 2, 3].map(|q| scope.spawn(move || raster.squares(q & 1 == 1, q & 2 == 2)));
            quarters.map(|quarter| {
                let rows = quarter.join().expect("a raster thread");
                CellBlocks::from_rows(&rows, raster.width)
            })
        });
    }

    /// The free squares reaching west (else east) and south (else north) of each cell: a free
    /// cell's square is one more than the smallest of its three neighbours' that way (beyond
    /// the raster no wall stands).
    fn squares(&self, west: bool, south: bool) -> Vec<u8> {
        let (w, h) = (self.width, self.height);
        let mut out = vec![0u8; w * h];
        let columns: Vec<usize> = if west {
            (0..w).collect()
        } else {
            (0..w).rev().collect()
        };
        let rows: Vec<usize> = if south {
            (0..h).collect()
        } else {
            (0..h).rev().collect()
        };
        for &r in &rows {
            let next_row = if south {
                r.checked_sub(1)
            } else {
                Some(r + 1).filter(|&n| n < h)
            };
            for &x in &columns {
                let k = r * w + x;
                if self.clearance[k] == 0 {
                    continue;
                }
                let next_x = if west {
                    x.checked_sub(1)
                } else {
                    Some(x + 1).filter(|&n| n < w)
                };
                let at = |c: Option<usize>, row: Option<usize>| match (c, row) {
                    (Some(c), Some(row)) => out[row * w + c],
                    _ => MAX_CLEARANCE,
                };
                let smallest = at(next_x, Some(r))
                    .min(at(Some(x), next_row))
                    .min(at(next_x, next_row));
                out[k] = smallest.saturating_add(1);
            }
        }
        out
    }
}
