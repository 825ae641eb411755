//! A Player map as ROS 2's `nav_msgs/msg/OccupancyGrid`: Player's cells run from -range (free)
//! through 0 (unknown) to +range (occupied); ROS's from 0 (free) to 100 (occupied), -1
//! unknown. Both count rows from cell (0, 0), whose corner is the map's origin.

use player_proto::interfaces::map::{MapData, MapError, MapInfo};

use crate::msgs::{Header, MapMetaData, OccupancyGrid, Pose, Time};

/// One cell, Player's way to ROS's.
pub fn occupancy(value: i8, range: i8) -> i8 {
    if value == 0 {
        return -1;
    }
    let range = f32::from(range.unsigned_abs().max(1));
    let share = (f32::from(value) / range).clamp(-1.0, 1.0);
    (50.0 + 50.0 * share).round() as i8
}

/// Assembles a grid from its info and the tiles a map device answered with.
pub fn grid(info: &MapInfo, tiles: &[MapData], header: Header) -> Result<OccupancyGrid, MapError> {
    let (width, height) = (info.width as usize, info.height as usize);
    let mut data = vec![-1i8; width * height];
    for tile in tiles {
        let cells = tile.cells()?;
        let tile_width = (tile.width as usize).max(1);
        for (r, line) in cells.chunks(tile_width).enumerate() {
            let (row, col) = (tile.row as usize + r, tile.col as usize);
            if row >= height || col >= width {
                continue;
            }
            let start = row * width + col;
            let take = line.len().min(width - col);
            for (to, &from) in data[start..start + take].iter_mut().zip(line) {
                *to = occupancy(from, tile.data_range);
            }
        }
    }
    Ok(OccupancyGrid {
        header,
        info: MapMetaData {
            map_load_time: Time::default(),
            resolution: info.scale,
            width: info.width,
            height: info.height,
            origin: Pose::planar(info.origin.px, info.origin.py, info.origin.pa),
        },
        data,
    })
}

/// A map read as a recording saw it asked: its info, then its tiles one reply at a time; the
/// grid is whole once the tiles cover every cell.
#[derive(Debug, Clone, Default)]
pub struct MapTiles {
    info: Option<MapInfo>,
    tiles: Vec<MapData>,
}

impl MapTiles {
    /// The map's info came (a new reading of the map begins).
    pub fn info(&mut self, info: &MapInfo) {
        self.info = Some(*info);
        self.tiles.clear();
    }

    /// A tile came: the whole grid once this one completes it (then a new reading may begin).
    pub fn tile(&mut self, tile: &MapData, header: Header) -> Option<OccupancyGrid> {
        let info = self.info.as_ref()?;
        self.tiles
            .retain(|t| (t.row, t.col) != (tile.row, tile.col));
        self.tiles.push(tile.clone());
        let (width, height) = (u64::from(info.width), u64::from(info.height));
        let covered: u64 = self
            .tiles
            .iter()
            .map(|t| {
                let w = u64::from(t.width).min(width.saturating_sub(u64::from(t.col)));
                let h = u64::from(t.height).min(height.saturating_sub(u64::from(t.row)));
                w * h
            })
            .sum();
        if covered < width * height {
            return None;
        }
        let whole = grid(info, &self.tiles, header).ok();
        self.tiles.clear();
        whole
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_map_is_whole_once_its_tiles_cover_it() {
        let info = MapInfo {
            scale: 0.5,
            width: 4,
            height: 2,
            ..MapInfo::default()
        };
        let mut tiles = MapTiles::default();
        let tile = |col| MapData::compress(col, 0, 2, 2, 1, &[-1, 1, -1, 1]);
        assert!(
            tiles.tile(&tile(0), Header::default()).is_none(),
            "no info yet"
        );
        tiles.info(&info);
        assert!(tiles.tile(&tile(0), Header::default()).is_none());
        assert!(
            tiles.tile(&tile(0), Header::default()).is_none(),
            "the same tile again"
        );
        let grid = tiles.tile(&tile(2), Header::default()).unwrap();
        assert_eq!(grid.data, [0, 100, 0, 100, 0, 100, 0, 100]);
        assert_eq!((grid.info.width, grid.info.resolution), (4, 0.5));
    }

    #[test]
    fn cells_become_ros_occupancy() {
        assert_eq!(occupancy(-1, 1), 0);
        assert_eq!(occupancy(1, 1), 100);
        assert_eq!(occupancy(0, 1), -1);
        assert_eq!(occupancy(-128, 127), 0, "past the range: as far as it goes");
        assert_eq!(occupancy(64, 127), 75);
    }
}
