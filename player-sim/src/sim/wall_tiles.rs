//! A large raster's clearances and free squares in tiles, each worked out from the walls' boxes
//! the first time a ray or a scan reads it, instead of five full passes over the raster before
//! the first step. The 1 024-robot swarm's hall is 41 million cells of 2 cm: its five byte
//! arrays (205 MB) took 0.7 s to build on two cores, a sixth of a 20-second run, and most of
//! their cells, far from the border and the six inner walls, hold 255 and are never read.
//!
//! A tile's values are those the passes give (`wall_raster.rs`), from the boxes near it: the
//! clearance of a cell is its distance to the nearest wall cell (the larger of the column and
//! row differences, at most 255), and its free square for a ray heading into a quarter is the
//! distance to the nearest wall cell that way (a wall cell `dx` columns and `dy` rows ahead
//! ends the square at side `max(dx, dy)`). A wall cell more than 255 cells away changes neither:
//! only the boxes within 255 cells are asked, and a tile that none comes near, or whose cells
//! are all 255, is stored as nothing. A tile with few boxes near keeps those and works a cell's
//! value out when it is read ([`FEW`]). Tested cell for cell against the passes.

use std::sync::OnceLock;

use super::wall_boxes::{CellBox, WallBoxes};

/// Cells along a tile's side (a power of two): 16 KiB a tile, a few dozen tiles along the
/// swarm's hall, so that the table of tiles stays in cache.
const SHIFT: usize = 7;
const SIDE: usize = 1 << SHIFT;

/// The farthest a wall cell counts from (the raster's `MAX_CLEARANCE`).
const MOST: i32 = 255;

/// The kind of value [`WallTiles::get`] reads: the free square of quarter `0..4` (see
/// `wall_raster::quadrant`), or the clearance.
pub(super) const CLEARANCE: usize = 4;

/// A tile's cells, in blocks of 8 x 8 (see [`within`]).
type Cells = Box<[u8; SIDE * SIDE]>;

/// Tiles with at most this many wall boxes near them keep the boxes, not the cells, and work a
/// cell's value out when it is read: the swarm's tiles along its walls (a few boxes each) were
/// tens of megabytes of cells read all over the hall, a wait on memory at nearly every read,
/// where a few boxes stay in cache and take a few comparisons each.
const FEW: usize = 8;

/// A tile, once worked out.
#[derive(Clone)]
enum Tile {
    /// Every cell 255: no wall near.
    Far,
    /// The few wall boxes near it, relative to its first cell.
    Few(Box<[[i32; 4]]>),
    Cells(Cells),
}

impl std::fmt::Debug for Tile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Tile::Far => f.write_str("Far"),
            Tile::Few(near) => write!(f, "Few({})", near.len()),
            Tile::Cells(_) => f.write_str("Cells"),
        }
    }
}

/// Where cell `(c, r)` of its tile is kept: in blocks of 8 x 8 cells, a cache line each, so
/// that the cells a ray reads near a wall, and its neighbouring beams' there, share lines
/// whichever way the wall runs.
#[inline]
fn within(c: usize, r: usize) -> usize {
    let (c, r) = (c & (SIDE - 1), r & (SIDE - 1));
    ((((r >> 3) << (SHIFT - 3)) | (c >> 3)) << 6) | ((r & 7) << 3) | (c & 7)
}

/// The raster's values in tiles, each worked out on first read.
#[derive(Debug, Clone, Default)]
pub(super) struct WallTiles {
    /// Global cell of the raster's first column and row.
    first: (i64, i64),
    columns: usize,
    /// For each kind (four quarters, then the clearance), its tiles row-major.
    tiles: [Vec<OnceLock<Tile>>; 5],
}

/// Two rasters of the same walls and size hold the same values, read or not.
impl PartialEq for WallTiles {
    fn eq(&self, other: &WallTiles) -> bool {
        self.first == other.first
            && self.columns == other.columns
            && self.tiles[0].len() == other.tiles[0].len()
    }
}

impl WallTiles {
    /// The tiles of a raster of `width` x `height` cells from global cell `first`, none worked
    /// out yet.
    pub(super) fn new(first: (i64, i64), width: usize, height: usize) -> WallTiles {
        let columns = width.div_ceil(SIDE);
        let count = columns * height.div_ceil(SIDE);
        WallTiles {
            first,
            columns,
            tiles: std::array::from_fn(|_| (0..count).map(|_| OnceLock::new()).collect()),
        }
    }

    /// How many tiles were worked out as far from walls, as their boxes, and as their cells.
    #[cfg(test)]
    pub(super) fn worked_out(&self) -> [usize; 3] {
        let mut counts = [0; 3];
        for tile in self.tiles.iter().flatten().filter_map(OnceLock::get) {
            counts[match tile {
                Tile::Far => 0,
                Tile::Few(_) => 1,
                Tile::Cells(_) => 2,
            }] += 1;
        }
        counts
    }

    /// The value of kind `kind` at raster column `c`, row `r` (within the raster), the walls
    /// being `walls`. Out of line, so that the raster's read of a full array (a cave's) stays inlined in the
    /// walk: the tiles' reads wait on memory far longer than a call takes.
    #[inline(never)]
    pub(super) fn get(&self, kind: usize, c: usize, r: usize, walls: &WallBoxes) -> u8 {
        let k = (r >> SHIFT) * self.columns + (c >> SHIFT);
        let tile = match self.tiles[kind][k].get() {
            Some(tile) => tile,
            None => self.first_read(kind, k, walls),
        };
        match tile {
            Tile::Cells(cells) => cells[within(c, r)],
            Tile::Few(near) => value(kind, near, (c & (SIDE - 1)) as i32, (r & (SIDE - 1)) as i32),
            Tile::Far => MOST as u8,
        }
    }

    /// Tile `k` of kind `kind`, worked out now unless another thread has.
    #[cold]
    #[inline(never)]
    fn first_read(&self, kind: usize, k: usize, walls: &WallBoxes) -> &Tile {
        let (tc, tr) = (k % self.columns, k / self.columns);
        self.tiles[kind][k].get_or_init(|| self.work_out(kind, tc, tr, walls))
    }

    /// Tile `(tc, tr)` of kind `kind` from the boxes that may come within 255 cells of it.
    #[cold]
    #[inline(never)]
    fn work_out(&self, kind: usize, tc: usize, tr: usize, walls: &WallBoxes) -> Tile {
        // The tile's first cell, global.
        let (x0, y0) = (
            self.first.0 + (tc * SIDE) as i64,
            self.first.1 + (tr * SIDE) as i64,
        );
        let (x1, y1) = (x0 + SIDE as i64 - 1, y0 + SIDE as i64 - 1);
        let most = i64::from(MOST);
        // Where a wall cell may count: all round for the clearance, else the quarter's way.
        let (west, south) = (kind & 1 == 1, kind & 2 == 2);
        let all = kind == CLEARANCE;
        let low = (
            if all || west { x0 - most } else { x0 },
            if all || south { y0 - most } else { y0 },
        );
        let high = (
            if all || !west { x1 + most } else { x1 },
            if all || !south { y1 + most } else { y1 },
        );
        let mut near: Vec<[i32; 4]> = Vec::new();
        walls.each_within(low, high, |b: &CellBox| {
            // Relative to the tile, clamped far beyond any distance that counts.
            let far = 4 * (SIDE as i64 + most);
            let rel = |v: i64, o: i64| (v - o).clamp(-far, far) as i32;
            near.push([rel(b[0], x0), rel(b[1], y0), rel(b[2], x0), rel(b[3], y0)]);
        });
        if near.is_empty() {
            return Tile::Far;
        }
        if near.len() <= FEW {
            return Tile::Few(near.into_boxed_slice());
        }
        let mut cells: Cells = vec![MOST as u8; SIDE * SIDE]
            .into_boxed_slice()
            .try_into()
            .expect("a tile's cells");
        for [bx0, by0, bx1, by1] in near {
            for r in 0..SIDE as i32 {
                let Some(dy) = share(all, south, (by0, by1), r).filter(|&dy| dy < MOST) else {
                    continue;
                };
                for c in 0..SIDE as i32 {
                    if let Some(dx) = share(all, west, (bx0, bx1), c) {
                        let cell = &mut cells[within(c as usize, r as usize)];
                        *cell = (*cell).min(dx.max(dy).min(MOST) as u8);
                    }
                }
            }
        }
        if cells.iter().all(|&v| v == MOST as u8) {
            Tile::Far
        } else {
            Tile::Cells(cells)
        }
    }
}

/// The value of kind `kind` at cell `(c, r)` of a tile, the wall boxes near it being `near`
/// (relative to the tile's first cell), as [`WallTiles::work_out`] gives it.
#[inline]
fn value(kind: usize, near: &[[i32; 4]], c: i32, r: i32) -> u8 {
    let (west, south) = (kind & 1 == 1, kind & 2 == 2);
    let all = kind == CLEARANCE;
    let mut v = MOST;
    for &[bx0, by0, bx1, by1] in near {
        if let (Some(dx), Some(dy)) = (
            share(all, west, (bx0, bx1), c),
            share(all, south, (by0, by1), r),
        ) {
            v = v.min(dx.max(dy));
        }
    }
    v.min(MOST) as u8
}

/// A wall box's share of a cell's distance along one axis, the cell at `v` and the box
/// spanning `lo..=hi` that way: all round (`all`), or only ahead of a ray heading towards lower
/// values (`back`) or higher; `None` for a box behind.
#[inline]
fn share(all: bool, back: bool, (lo, hi): (i32, i32), v: i32) -> Option<i32> {
    if all {
        Some((lo - v).max(v - hi).max(0))
    } else if back {
        (lo <= v).then(|| (v - hi).max(0))
    } else {
        (hi >= v).then(|| (lo - v).max(0))
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::WallRaster;
    use crate::sim::test_halls::walled;
    use crate::sim::test_randoms::randoms;
    use crate::world::floor_i64;

    /// Every cell's clearance and free squares, tiled and from the passes, in a 14 x 11 m hall
    /// (2 cm cells: tiles' edges, and walls farther than 255 cells) of random pixel walls and
    /// drawn lines.
    #[test]
    fn tiles_hold_what_the_passes_give() {
        let mut next = randoms(0x711E5);
        for round in 0..3 {
            let (columns, rows) = (56, 44);
            let grid: Vec<String> = (0..rows)
                .map(|r| {
                    (0..columns)
                        .map(|c| {
                            let border = r == 0 || c == 0 || r == rows - 1 || c == columns - 1;
                            let wall = (border && round != 1) || next() < 0.01;
                            if wall { '#' } else { '.' }
                        })
                        .collect()
                })
                .collect();
            let mut world = walled(&grid, 0.25, 0.02);
            let mut point = || [14.0 * next() - 7.0, 11.0 * next() - 5.5];
            world.floor_blocks = vec![vec![point(), point(), point()], vec![point(), point()]];
            let passes = WallRaster::of(&world).expect("walls");
            let tiles = passes.tiled();
            let (x0, y0) = (floor_i64(-7.0 * 50.0) - 3, floor_i64(-5.5 * 50.0) - 3);
            for y in y0..y0 + 560 {
                for x in x0..x0 + 710 {
                    assert_eq!(tiles.clearance(x, y), passes.clearance(x, y), "({x}, {y})");
                    for q in 0..4 {
                        let (a, b) = (tiles.ahead(x, y, q), passes.ahead(x, y, q));
                        assert_eq!(a, b, "({x}, {y}) quarter {q}, round {round}");
                    }
                }
            }
            // Both ways of keeping a tile were read: its few boxes, and its cells.
            let [_, kept_boxes, kept_cells] = tiles.worked_out().expect("tiled");
            assert!(
                kept_boxes > 0 && kept_cells > 0,
                "round {round}: {kept_boxes} {kept_cells}"
            );
        }
    }
}
