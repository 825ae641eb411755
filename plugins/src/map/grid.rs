//! An occupancy grid assembled from the tiles a Player `map` device sends: which tiles to ask
//! for, where each one's cells go, and the grey each cell is drawn in. No device and no scene
//! here, so that a lying map or a broken tile can be tested directly.

use player_proto::interfaces::map::{MapData, MapError, MapInfo};

use framework::scene::image::MAX_IMAGE_SIDE;
use framework::scene::{ImageError, PixelFormat, Pixels};

pub use player_proto::interfaces::map::{MAX_MAP_CELLS, TILE_SIDE};

/// The greys a cell is drawn in: free nearly white, unknown mid grey, occupied nearly black.
pub const FREE_GREY: u8 = 235;
pub const UNKNOWN_GREY: u8 = 150;
pub const OCCUPIED_GREY: u8 = 25;

/// Why a map or one of its tiles cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GridError {
    #[error("the map has no cells ({width}×{height})")]
    Empty { width: u32, height: u32 },
    #[error(
        "the map says {width}×{height} cells, above the limit of {MAX_MAP_CELLS} cells and \
         {MAX_IMAGE_SIDE} on a side"
    )]
    TooLarge { width: u32, height: u32 },
    #[error("the map's resolution, {0} m per cell, is not a positive number")]
    BadScale(f32),
    #[error(
        "the tile at column {col}, row {row} ({width}×{height}) reaches outside the \
         {map_width}×{map_height} map"
    )]
    TileOutside {
        col: u32,
        row: u32,
        width: u32,
        height: u32,
        map_width: u32,
        map_height: u32,
    },
    #[error("the tile at column {col}, row {row}: {source}")]
    Tile {
        col: u32,
        row: u32,
        source: MapError,
    },
}

/// The grid as drawn: one grey byte per cell, row 0 at the map's origin.
#[derive(Debug, Clone)]
pub struct OccupancyGrid {
    info: MapInfo,
    greys: Vec<u8>,
}

impl OccupancyGrid {
    /// An all-unknown grid of the size `info` gives, once that size is believable.
    pub fn new(info: MapInfo) -> Result<OccupancyGrid, GridError> {
        let (width, height) = (info.width, info.height);
        if width == 0 || height == 0 {
            return Err(GridError::Empty { width, height });
        }
        let cells = u64::from(width) * u64::from(height);
        if cells > MAX_MAP_CELLS || width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
            return Err(GridError::TooLarge { width, height });
        }
        if !(info.scale.is_finite() && info.scale > 0.0) {
            return Err(GridError::BadScale(info.scale));
        }
        Ok(OccupancyGrid {
            info,
            greys: vec![UNKNOWN_GREY; cells as usize],
        })
    }

    pub fn info(&self) -> &MapInfo {
        &self.info
    }

    /// The GET_DATA requests that cover the map (see [`MapInfo::tile_requests`]).
    pub fn tiles(&self) -> Vec<MapData> {
        self.info.tile_requests()
    }

    /// Writes a tile's cells into the grid. A tile that lies outside the map or does not
    /// inflate to its own size changes nothing.
    pub fn apply(&mut self, tile: &MapData) -> Result<(), GridError> {
        let (map_width, map_height) = (self.info.width, self.info.height);
        let fits = |start: u32, len: u32, limit: u32| {
            start.checked_add(len).is_some_and(|end| end <= limit)
        };
        if !fits(tile.col, tile.width, map_width) || !fits(tile.row, tile.height, map_height) {
            return Err(GridError::TileOutside {
                col: tile.col,
                row: tile.row,
                width: tile.width,
                height: tile.height,
                map_width,
                map_height,
            });
        }
        let cells = tile.cells().map_err(|source| GridError::Tile {
            col: tile.col,
            row: tile.row,
            source,
        })?;
        if tile.width == 0 {
            return Ok(());
        }
        for (j, line) in cells.chunks_exact(tile.width as usize).enumerate() {
            let start = (tile.row as usize + j) * map_width as usize + tile.col as usize;
            for (grey, &cell) in self.greys[start..start + line.len()].iter_mut().zip(line) {
                *grey = grey_of(cell);
            }
        }
        Ok(())
    }

    /// The grid as a picture (a copy: the grid keeps filling while the scene shows this).
    pub fn pixels(&self) -> Result<Pixels, ImageError> {
        Pixels::new(
            self.info.width,
            self.info.height,
            PixelFormat::Gray8,
            self.greys.clone(),
        )
    }

    /// The grey of the cell under world point (x, y), or `None` outside the map: the map's
    /// origin is cell (0, 0)'s corner, turned by its heading.
    pub fn grey_at(&self, x: f32, y: f32) -> Option<u8> {
        let origin = &self.info.origin;
        let (dx, dy) = (x - origin.px as f32, y - origin.py as f32);
        let (sin, cos) = (-origin.pa as f32).sin_cos();
        let (u, v) = (dx * cos - dy * sin, dx * sin + dy * cos);
        let (col, row) = ((u / self.info.scale).floor(), (v / self.info.scale).floor());
        let inside = |c: f32, limit: u32| c >= 0.0 && c < limit as f32;
        if !inside(col, self.info.width) || !inside(row, self.info.height) {
            return None;
        }
        let index = row as usize * self.info.width as usize + col as usize;
        self.greys.get(index).copied()
    }

    /// The map's extent on the ground, m.
    pub fn size_m(&self) -> (f32, f32) {
        (
            self.info.width as f32 * self.info.scale,
            self.info.height as f32 * self.info.scale,
        )
    }
}

/// Player's cell value as a grey: negative free, zero unknown, positive occupied.
pub fn grey_of(cell: i8) -> u8 {
    match cell {
        c if c < 0 => FREE_GREY,
        0 => UNKNOWN_GREY,
        _ => OCCUPIED_GREY,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::wire::Opaque;

    fn info(width: u32, height: u32) -> MapInfo {
        MapInfo {
            scale: 0.05,
            width,
            height,
            ..MapInfo::default()
        }
    }

    #[test]
    fn tiles_cover_the_map_once_within_the_tile_limit() {
        let grid = OccupancyGrid::new(info(1500, 700)).unwrap();
        let tiles = grid.tiles();
        assert_eq!(tiles.len(), 3 * 2);
        let covered: u64 = tiles
            .iter()
            .map(|t| u64::from(t.width) * u64::from(t.height))
            .sum();
        assert_eq!(covered, 1500 * 700);
        assert!(
            tiles
                .iter()
                .all(|t| t.width <= TILE_SIDE && t.height <= TILE_SIDE)
        );
        let third = &tiles[2];
        assert_eq!(
            (third.col, third.row, third.width, third.height),
            (1280, 0, 220, 640)
        );
    }

    #[test]
    fn cells_land_at_their_column_and_row() {
        let mut grid = OccupancyGrid::new(info(4, 3)).unwrap();
        let tile = MapData::compress(1, 1, 2, 2, 1, &[-1, 1, 0, -1]);
        grid.apply(&tile).unwrap();
        let pixels = grid.pixels().unwrap();
        let (u, f, o) = (UNKNOWN_GREY, FREE_GREY, OCCUPIED_GREY);
        assert_eq!(pixels.bytes(), [u, u, u, u, u, f, o, u, u, u, f, u]);
    }

    #[test]
    fn a_lying_map_or_tile_is_refused_without_allocating() {
        assert!(matches!(
            OccupancyGrid::new(info(u32::MAX, u32::MAX)),
            Err(GridError::TooLarge { .. })
        ));
        assert!(matches!(
            OccupancyGrid::new(info(20_000, 10)),
            Err(GridError::TooLarge { .. })
        ));
        assert!(matches!(
            OccupancyGrid::new(info(0, 10)),
            Err(GridError::Empty { .. })
        ));
        let nan = MapInfo {
            scale: f32::NAN,
            ..info(4, 4)
        };
        assert!(matches!(
            OccupancyGrid::new(nan),
            Err(GridError::BadScale(_))
        ));

        let mut grid = OccupancyGrid::new(info(4, 4)).unwrap();
        let outside = MapData::compress(3, 3, 2, 2, 1, &[1; 4]);
        assert!(matches!(
            grid.apply(&outside),
            Err(GridError::TileOutside { .. })
        ));
        let overflow = MapData {
            col: u32::MAX,
            ..MapData::compress(0, 0, 2, 2, 1, &[1; 4])
        };
        assert!(matches!(
            grid.apply(&overflow),
            Err(GridError::TileOutside { .. })
        ));
        let garbage = MapData {
            data: Opaque::from(vec![1, 2, 3]),
            ..MapData::compress(0, 0, 2, 2, 1, &[1; 4])
        };
        let err = grid.apply(&garbage).unwrap_err();
        assert!(
            err.to_string()
                .starts_with("the tile at column 0, row 0: tile data is not a zlib stream"),
            "{err}"
        );
        assert!(
            grid.pixels()
                .unwrap()
                .bytes()
                .iter()
                .all(|&g| g == UNKNOWN_GREY),
            "nothing written"
        );
    }
}
