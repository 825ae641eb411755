//! The floorplan's walls as Stage's rangers see them: a raster of square cells of the world's
//! `resolution` (2 cm unless set), not the bitmap's own pixels. Stage turns a bitmap into
//! polygons around its dark pixels, scales them over the floorplan, and marks every cell an
//! outline passes through, its corners floored to whole cells; its rays then walk those cells.
//! A wall region therefore reaches, in Stage, every cell its closed outline touches: up to a
//! cell more than the bitmap's pixels on the north and east sides, and a diagonal corner or a
//! one-pixel wall is where its cells are, not where its pixels are; a thick wall's inside is
//! not marked at all, so that a sensor inside a wall sees out through its far side. Rays cast
//! against this raster meet walls where Stage's meet them.
//!
//! Each cell also holds its clearance (how many cells away, in rows or columns, the nearest
//! wall cell is), so that a ray crosses open space in a few jumps instead of cell by cell: the
//! cost of a beam grows with the walls it passes near, not with its length in 2 cm cells.

use super::cell_blocks::CellBlocks;
use super::raster_walk::RegionMap;
use super::wall_boxes::{CellBox, WallBoxes};
use super::wall_tiles::{CLEARANCE, WallTiles};
use crate::world::{World, floor_i64};

/// The most cells a raster may have (64 Mi, 64 MiB): a finer or larger world keeps the
/// floorplan's own grid for its rays.
const MAX_CELLS: usize = 64 << 20;

/// Clearance is counted up to this many cells (a jump of about 5 m at 2 cm).
const MAX_CLEARANCE: u8 = 255;

/// Rasters of more cells than this, with at most [`TILED_MOST_BOXES`] wall boxes, are worked
/// out in tiles when first read (`wall_tiles.rs`) instead of in full before the first step.
const TILED_FROM: usize = 4 << 20;

/// The most wall boxes a tiled raster may have: each tile's cells are worked out from the
/// boxes near it, box by box, where the passes' cost does not grow with the walls.
const TILED_MOST_BOXES: usize = 4096;

/// The walls on Stage's raster, with each cell's clearance.
#[derive(Debug, Clone, PartialEq)]
pub struct WallRaster {
    /// Metres per cell, and cells per metre (Stage multiplies by the latter).
    pub(super) resolution: f64,
    pub(super) per_metre: f64,
    /// Global cell (`floor(x * per_metre)`) of the raster's first column and row.
    first: (i64, i64),
    width: usize,
    height: usize,
    /// Row-major from the south: 0 on a wall cell, else the distance in cells (the larger of
    /// the column and row differences) to the nearest wall cell, at most [`MAX_CLEARANCE`].
    clearance: Vec<u8>,
    /// For a ray heading into each quarter of directions (east-north, west-north, east-south,
    /// west-south: `raster_walk::quadrant`), the side of the largest square of free cells with this cell
    /// at its corner and the rest of it that way, at most [`MAX_CLEARANCE`]: a ray moving away
    /// from a wall beside or behind it jumps as far as the walls ahead allow. In blocks, not
    /// rows: a ray's last reads before a wall lie close together.
    ahead: [CellBlocks; 4],
    /// Boxes holding exactly the wall cells: for a scan to tell which beams may meet a wall,
    /// and for the tiles.
    pub(super) boxes: WallBoxes,
    /// For a large raster of few walls, the values of `clearance` and `ahead` (then empty) in
    /// tiles, worked out when first read.
    tiles: Option<WallTiles>,
    /// Stage's regions holding a wall cell (`sim/raster_walk.rs`), worked out on the first ray.
    pub(super) region_map: std::sync::OnceLock<RegionMap>,
}

/// Each run of consecutive indices below `len` where `on` holds, as `run(first, past_last)`.
fn runs(len: i64, on: impl Fn(i64) -> bool, mut run: impl FnMut(usize, usize)) {
    let mut k = 0;
    while k < len {
        if !on(k) {
            k += 1;
            continue;
        }
        let start = k;
        while k < len && on(k) {
            k += 1;
        }
        run(start as usize, k as usize);
    }
}

/// Every cell of a 4-connected line from cell `a` to cell `b`, both ends included, as Stage
/// marks a block's edge: each step moves one column or one row, whichever keeps the cells
/// nearer the straight line (ties: a row).
pub(super) fn line_cells(a: (i64, i64), b: (i64, i64), mut mark: impl FnMut(i64, i64)) {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (sx, sy) = (dx.signum(), dy.signum());
    let (ax, ay) = (dx.abs(), dy.abs());
    let (mut x, mut y) = a;
    // Twice the signed distance from the line, scaled: which step stays nearer.
    let mut error = ay - ax;
    mark(x, y);
    for _ in 0..ax + ay {
        if error < 0 {
            x += sx;
            error += 2 * ay;
        } else {
            y += sy;
            error -= 2 * ax;
        }
        mark(x, y);
    }
}

impl WallRaster {
    /// The raster of `world`'s floorplan: its bitmap's wall pixels and its drawn walls (blocks,
    /// `boundary 1`); `None` without walls, or when the raster would be too large.
    pub fn of(world: &World) -> Option<WallRaster> {
        let per_metre = 1.0 / world.resolution;
        if !(per_metre.is_finite() && per_metre > 0.0) {
            return None;
        }
        let mut marks: Vec<(i64, i64, i64, i64)> = Vec::new();
        let cell = |v: f64| floor_i64(v * per_metre);
        // An unrotated bitmap's own pixels, their edges where Stage puts them (`StageBitmap`);
        // else the floor grid's.
        let placed = world.floor_bitmap.as_deref();
        let grid = placed.map(|b| &b.pixels).or(world.floor.as_ref());
        if let (Some(grid), Some(_)) = (grid, &world.floorplan) {
            let edge_x =
                |c: usize| placed.map_or(grid.origin.0 + c as f64 * grid.cell.0, |b| b.x(c));
            let edge_y =
                |r: usize| placed.map_or(grid.origin.1 + r as f64 * grid.cell.1, |b| b.y(r));
            let wall = |column: usize, row: usize| {
                grid.occupied_at(
                    grid.origin.0 + (column as f64 + 0.5) * grid.cell.0,
                    grid.origin.1 + (row as f64 + 0.5) * grid.cell.1,
                )
            };
            // Stage traces the dark pixels' outlines and marks only the cells its edges pass
            // through: each side of a dark pixel with a light pixel (or the image's edge)
            // beyond it, the sides in a row or column joined into runs. A wall's inside is
            // not marked, so that a ray starting there walks to its far side, as in Stage.
            let dark = |column: i64, row: i64| {
                column >= 0
                    && row >= 0
                    && (column as usize) < grid.width
                    && (row as usize) < grid.height
                    && wall(column as usize, row as usize)
            };
            let (width, height) = (grid.width as i64, grid.height as i64);
            for row in 0..=height {
                // The horizontal edges on the line between rows `row - 1` and `row`.
                let y = cell(edge_y(row as usize));
                runs(
                    width,
                    |c| dark(c, row - 1) != dark(c, row),
                    |a, b| {
                        marks.push((cell(edge_x(a)), y, cell(edge_x(b)), y));
                    },
                );
            }
            for column in 0..=width {
                // The vertical edges on the line between columns `column - 1` and `column`.
                let x = cell(edge_x(column as usize));
                runs(
                    height,
                    |r| dark(column - 1, r) != dark(column, r),
                    |a, b| {
                        marks.push((x, cell(edge_y(a)), x, cell(edge_y(b))));
                    },
                );
            }
        }
        let mut lines = Vec::new();
        for polygon in &world.floor_blocks {
            for (k, a) in polygon.iter().enumerate() {
                let b = polygon[(k + 1) % polygon.len()];
                lines.push(((cell(a[0]), cell(a[1])), (cell(b[0]), cell(b[1]))));
            }
        }
        let ends = marks
            .iter()
            .flat_map(|&(x0, y0, x1, y1)| [(x0, y0), (x1, y1)])
            .chain(lines.iter().flat_map(|&(a, b)| [a, b]));
        let (mut low, mut high) = ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN));
        for (x, y) in ends {
            low = (low.0.min(x), low.1.min(y));
            high = (high.0.max(x), high.1.max(y));
        }
        if low.0 > high.0 {
            return None;
        }
        // A free cell all round, so that a cell outside the raster is never beside a wall.
        let first = (low.0 - 1, low.1 - 1);
        let (w, h) = (high.0 - low.0 + 3, high.1 - low.1 + 3);
        if w <= 0 || h <= 0 || (w as u128) * (h as u128) > MAX_CELLS as u128 {
            return None;
        }
        let mut raster = WallRaster {
            resolution: world.resolution,
            per_metre,
            first,
            width: w as usize,
            height: h as usize,
            clearance: Vec::new(),
            ahead: Default::default(),
            boxes: Default::default(),
            tiles: None,
            region_map: Default::default(),
        };
        let mut cells: Vec<CellBox> = marks
            .iter()
            .map(|&(x0, y0, x1, y1)| [x0, y0, x1, y1])
            .collect();
        for &(a, b) in &lines {
            line_cells(a, b, |x, y| cells.push([x, y, x, y]));
        }
        raster.boxes = WallBoxes::new(cells);
        if (w * h) as usize > TILED_FROM && raster.boxes.len() <= TILED_MOST_BOXES {
            raster.tiles = Some(WallTiles::new(first, w as usize, h as usize));
            return Some(raster);
        }
        raster.clearance = vec![MAX_CLEARANCE; (w * h) as usize];
        for (x0, y0, x1, y1) in marks {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    raster.mark(x, y);
                }
            }
        }
        for (a, b) in lines {
            raster.mark_line(a, b);
        }
        raster.count_clearance();
        Some(raster)
    }

    fn mark(&mut self, x: i64, y: i64) {
        let (c, r) = ((x - self.first.0) as usize, (y - self.first.1) as usize);
        self.clearance[r * self.width + c] = 0;
    }

    fn mark_line(&mut self, a: (i64, i64), b: (i64, i64)) {
        line_cells(a, b, |x, y| self.mark(x, y));
    }

    /// Clearance of global cell `(x, y)`: 0 on a wall; outside the raster, how far it lies
    /// outside (no wall is nearer).
    #[inline]
    pub(super) fn clearance(&self, x: i64, y: i64) -> u32 {
        let (c, r) = (x - self.first.0, y - self.first.1);
        if c >= 0 && r >= 0 && (c as usize) < self.width && (r as usize) < self.height {
            let (c, r) = (c as usize, r as usize);
            if let Some(tiles) = &self.tiles {
                return u32::from(tiles.get(CLEARANCE, c, r, &self.boxes));
            }
            return u32::from(self.clearance[r * self.width + c]);
        }
        self.outside(x, y)
    }

    /// The clearance of global cell `(x, y)` outside the raster: how far outside it lies.
    #[cold]
    #[inline(never)]
    fn outside(&self, x: i64, y: i64) -> u32 {
        let (c, r) = (x - self.first.0, y - self.first.1);
        let outside = |v: i64, n: usize| {
            if v < 0 { -v } else { (v - n as i64 + 1).max(0) }
        };
        let far = outside(c, self.width).max(outside(r, self.height));
        far.clamp(1, i64::from(MAX_CLEARANCE)) as u32
    }

    /// The free square of global cell `(x, y)` for a ray heading into quarter `q` (see
    /// [`WallRaster::ahead`]): 0 on a wall; outside the raster, its clearance.
    #[inline]
    pub(super) fn ahead(&self, x: i64, y: i64, q: usize) -> u32 {
        let (c, r) = (x - self.first.0, y - self.first.1);
        if c >= 0 && r >= 0 && (c as usize) < self.width && (r as usize) < self.height {
            let (c, r) = (c as usize, r as usize);
            if let Some(tiles) = &self.tiles {
                return u32::from(tiles.get(q, c, r, &self.boxes));
            }
            return u32::from(self.ahead[q].get(c, r));
        }
        self.outside(x, y)
    }

    /// The same raster with its values in tiles, worked out when read (`wall_tiles.rs`).
    #[cfg(test)]
    pub(super) fn tiled(&self) -> WallRaster {
        WallRaster {
            clearance: Vec::new(),
            ahead: Default::default(),
            tiles: Some(WallTiles::new(self.first, self.width, self.height)),
            ..self.clone()
        }
    }

    /// How many of its tiles were worked out as far from walls, as their boxes, and as their
    /// cells; `None` when it is not tiled.
    #[cfg(test)]
    pub(super) fn worked_out(&self) -> Option<[usize; 3]> {
        self.tiles.as_ref().map(WallTiles::worked_out)
    }

    /// Are its values in tiles, worked out when read (a large raster of few walls)?
    pub(super) fn is_tiled(&self) -> bool {
        self.tiles.is_some()
    }

    /// The raster's first and last global cells, each way.
    pub(super) fn cell_bounds(&self) -> ((i64, i64), (i64, i64)) {
        let last = |first: i64, n: usize| first + n as i64 - 1;
        (
            self.first,
            (
                last(self.first.0, self.width),
                last(self.first.1, self.height),
            ),
        )
    }

    /// Is global cell `(x, y)` a wall?
    pub fn is_wall(&self, x: i64, y: i64) -> bool {
        self.clearance(x, y) == 0
    }
}

mod passes;
#[cfg(test)]
mod tests;
