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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_become_ros_occupancy() {
        assert_eq!(occupancy(-1, 1), 0);
        assert_eq!(occupancy(1, 1), 100);
        assert_eq!(occupancy(0, 1), -1);
        assert_eq!(occupancy(-128, 127), 0, "past the range: as far as it goes");
        assert_eq!(occupancy(64, 127), 75);
    }
}
