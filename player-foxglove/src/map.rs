//! A map as `foxglove.Grid`: its size, scale and origin from the map's info, its cells from
//! the tiles a client asked for, put together; a grid is sent each time the last missing cell
//! arrives (and again when a client fetches the map anew).

use foxglove::messages::packed_element_field::NumericType;
use foxglove::messages::{Grid, PackedElementField, Timestamp, Vector2};
use player_proto::interfaces::map::{MapData, MapError, MapInfo};

use crate::frames::{WORLD, pose2d};

/// The most cells a map may have to be put together (a 8 192 × 8 192 map at 5 cm is 400 m
/// square): a lying info cannot make a converter allocate without bound.
pub const MAX_CELLS: u64 = 1 << 26;

/// Why a map or a tile cannot be put together.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum MapStateError {
    #[error("a {width}×{height} map is empty or above {MAX_CELLS} cells")]
    Size { width: u32, height: u32 },
    #[error("a tile does not decode: {0}")]
    Tile(#[from] MapError),
    #[error(
        "a {width}×{height} tile at ({col}, {row}) is outside the {map_width}×{map_height} map"
    )]
    Outside {
        width: u32,
        height: u32,
        col: u32,
        row: u32,
        map_width: u32,
        map_height: u32,
    },
}

/// A map being put together.
#[derive(Debug, Clone)]
pub struct MapState {
    info: MapInfo,
    /// Row-major, row 0 at the origin; one i8 per cell (negative free, 0 unknown, positive
    /// occupied).
    cells: Vec<u8>,
    have: Vec<bool>,
    missing: u64,
}

impl MapState {
    /// A new map of this size, or why not.
    pub fn new(info: MapInfo) -> Result<MapState, MapStateError> {
        let cells = u64::from(info.width) * u64::from(info.height);
        if cells == 0 || cells > MAX_CELLS {
            return Err(MapStateError::Size {
                width: info.width,
                height: info.height,
            });
        }
        Ok(MapState {
            info,
            cells: vec![0; cells as usize],
            have: vec![false; cells as usize],
            missing: cells,
        })
    }

    pub fn info(&self) -> &MapInfo {
        &self.info
    }

    /// Puts a tile in; the whole grid once no cell is missing.
    pub fn tile(&mut self, time: Timestamp, tile: &MapData) -> Result<Option<Grid>, MapStateError> {
        let cells = tile.cells()?;
        let (width, height) = (self.info.width, self.info.height);
        let fits = tile.col.checked_add(tile.width).is_some_and(|e| e <= width)
            && tile
                .row
                .checked_add(tile.height)
                .is_some_and(|e| e <= height);
        if !fits {
            return Err(MapStateError::Outside {
                width: tile.width,
                height: tile.height,
                col: tile.col,
                row: tile.row,
                map_width: width,
                map_height: height,
            });
        }
        for (i, &cell) in cells.iter().enumerate() {
            let (x, y) = (i as u32 % tile.width, i as u32 / tile.width);
            let at = ((tile.row + y) as usize) * width as usize + (tile.col + x) as usize;
            self.cells[at] = cell as u8;
            if !std::mem::replace(&mut self.have[at], true) {
                self.missing -= 1;
            }
        }
        Ok((self.missing == 0).then(|| self.grid(time)))
    }

    fn grid(&self, time: Timestamp) -> Grid {
        let scale = f64::from(self.info.scale);
        Grid {
            timestamp: Some(time),
            frame_id: WORLD.into(),
            pose: Some(pose2d(&self.info.origin)),
            column_count: self.info.width,
            cell_size: Some(Vector2 { x: scale, y: scale }),
            row_stride: self.info.width,
            cell_stride: 1,
            fields: vec![PackedElementField {
                name: "occupancy".into(),
                offset: 0,
                r#type: NumericType::Int8 as i32,
            }],
            data: bytes::Bytes::from(self.cells.clone()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn info(width: u32, height: u32) -> MapInfo {
        MapInfo {
            scale: 0.5,
            width,
            height,
            ..MapInfo::default()
        }
    }

    #[test]
    fn tiles_make_a_grid_once_every_cell_is_there() {
        let mut map = MapState::new(info(4, 2)).unwrap();
        let left = MapData::compress(0, 0, 2, 2, 1, &[-1, 1, -1, 1]);
        let right = MapData::compress(2, 0, 2, 2, 1, &[0, 0, 1, 1]);
        assert_eq!(map.tile(Timestamp::MIN, &left).unwrap(), None);
        let grid = map.tile(Timestamp::MIN, &right).unwrap().expect("complete");
        assert_eq!(grid.column_count, 4);
        let cells: Vec<i8> = grid.data.iter().map(|&b| b as i8).collect();
        assert_eq!(cells, [-1, 1, 0, 0, -1, 1, 1, 1]);
    }

    #[test]
    fn lying_sizes_are_refused() {
        assert!(matches!(
            MapState::new(info(1 << 20, 1 << 20)),
            Err(MapStateError::Size { .. })
        ));
        let mut map = MapState::new(info(2, 2)).unwrap();
        let outside = MapData::compress(1, 1, 2, 2, 1, &[0; 4]);
        assert!(matches!(
            map.tile(Timestamp::MIN, &outside),
            Err(MapStateError::Outside { col: 1, .. })
        ));
    }
}
