//! Player's `mapfile` driver: an occupancy grid read from an image the way Player reads it, so
//! that a client gets the same cells from player-sim as from `player` with the same `.cfg`.
//!
//! Player (gdk-pixbuf) averages every channel of a pixel, alpha included when the image has
//! one; `occ = (255 - average) / 255` (or `average / 255` with `negate 1`); above 0.95 is
//! occupied (+1), below 0.1 free (-1), anything between unknown (0). Image row 0 is the map's
//! top row: map row 0 is the lowest y. Without an `origin` the map is centred on (0, 0).

use std::path::Path;
use std::sync::Arc;

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::map::{MAX_TILE_CELLS, MapData, MapInfo};

use crate::image_file::{ImageFileError, Picture};

/// Above this `occ` a pixel is an occupied cell (Player's threshold).
const OCCUPIED_ABOVE: f64 = 0.95;
/// Below this `occ` a pixel is a free cell (Player's threshold).
const FREE_BELOW: f64 = 0.1;
/// Cell values as Player's map interface sends them.
const OCCUPIED: i8 = 1;
const FREE: i8 = -1;
const UNKNOWN: i8 = 0;
/// The largest magnitude of a cell value, as `data_range` tells a client.
const DATA_RANGE: i8 = 1;
/// The brightest channel value of an 8-bit image.
const FULL: f64 = 255.0;

/// A map as `mapfile` serves it.
#[derive(Debug, Clone, PartialEq)]
pub struct GridMap {
    pub width: u32,
    pub height: u32,
    /// Metres per cell.
    pub resolution: f64,
    /// World position of cell (0, 0)'s corner.
    pub origin: (f64, f64),
    /// Row-major, row 0 the lowest y.
    cells: Vec<i8>,
}

/// How a `mapfile` driver block asks for its map.
#[derive(Debug, Clone, PartialEq)]
pub struct MapFileSettings {
    pub resolution: f64,
    pub negate: bool,
    /// `None`: centred on (0, 0), as Player does when no origin is given.
    pub origin: Option<(f64, f64)>,
}

impl GridMap {
    /// Reads `image` as Player's mapfile does.
    pub fn from_image(image: &Path, settings: &MapFileSettings) -> Result<GridMap, ImageFileError> {
        let decoded = image::open(image).map_err(|e| ImageFileError {
            picture: Picture::MapImage,
            path: image.to_path_buf(),
            fault: e.into(),
        })?;
        let (width, height) = (decoded.width(), decoded.height());
        // gdk-pixbuf hands Player RGB, or RGBA when the file has transparency: the average
        // runs over those channels.
        let averages: Vec<f64> = if decoded.color().has_alpha() {
            decoded.to_rgba8().pixels().map(|p| average(&p.0)).collect()
        } else {
            decoded.to_rgb8().pixels().map(|p| average(&p.0)).collect()
        };
        let mut cells = vec![UNKNOWN; averages.len()];
        let w = width as usize;
        for (k, avg) in averages.into_iter().enumerate() {
            let (x, y) = (k % w, k / w);
            let occ = if settings.negate {
                avg / FULL
            } else {
                (FULL - avg) / FULL
            };
            let row = height as usize - 1 - y;
            cells[row * w + x] = if occ > OCCUPIED_ABOVE {
                OCCUPIED
            } else if occ < FREE_BELOW {
                FREE
            } else {
                UNKNOWN
            };
        }
        let origin = settings.origin.unwrap_or((
            -(f64::from(width) / 2.0) * settings.resolution,
            -(f64::from(height) / 2.0) * settings.resolution,
        ));
        Ok(GridMap {
            width,
            height,
            resolution: settings.resolution,
            origin,
            cells,
        })
    }

    /// A map of the given cells (row-major, row 0 the lowest y; Player's values: -1 free,
    /// 0 unknown, +1 occupied), as a map drawn by hand for a test or a tool.
    pub fn from_cells(
        width: u32,
        height: u32,
        resolution: f64,
        origin: (f64, f64),
        cells: Vec<i8>,
    ) -> Option<GridMap> {
        (cells.len() == width as usize * height as usize).then_some(GridMap {
            width,
            height,
            resolution,
            origin,
            cells,
        })
    }

    /// The cell at column `i`, row `j`, or `None` off the map.
    pub fn cell(&self, i: u32, j: u32) -> Option<i8> {
        (i < self.width && j < self.height)
            .then(|| self.cells[j as usize * self.width as usize + i as usize])
    }

    /// The answer to `PLAYER_MAP_REQ_GET_INFO`; the scale travels as a float, as in Player.
    pub fn info(&self) -> MapInfo {
        MapInfo {
            scale: self.resolution as f32,
            width: self.width,
            height: self.height,
            origin: Pose2d::new(self.origin.0, self.origin.1, 0.0),
        }
    }

    /// The answer to `PLAYER_MAP_REQ_GET_DATA`: the asked window, compressed as Player's TCP
    /// layer sends it; cells off the map are unknown, as Player fills them. `None` when the
    /// window is larger than any message may carry.
    pub fn tile(&self, col: u32, row: u32, width: u32, height: u32) -> Option<MapData> {
        let count = u64::from(width) * u64::from(height);
        if count > MAX_TILE_CELLS as u64 {
            return None;
        }
        let mut cells = Vec::with_capacity(count as usize);
        for j in 0..height {
            for i in 0..width {
                let cell = col
                    .checked_add(i)
                    .zip(row.checked_add(j))
                    .and_then(|(x, y)| self.cell(x, y));
                cells.push(cell.unwrap_or(UNKNOWN));
            }
        }
        Some(MapData::compress(
            col, row, width, height, DATA_RANGE, &cells,
        ))
    }
}

fn average(channels: &[u8]) -> f64 {
    channels.iter().map(|&c| f64::from(c)).sum::<f64>() / channels.len() as f64
}

/// A map shared by every device serving it; two are the same when they are the same map.
#[derive(Debug, Clone)]
pub struct SharedMap(pub Arc<GridMap>);

impl PartialEq for SharedMap {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Eq for SharedMap {}

#[cfg(test)]
mod tests {
    use super::*;
    use image::{GrayAlphaImage, GrayImage, LumaA};

    fn settings(negate: bool) -> MapFileSettings {
        MapFileSettings {
            resolution: 0.5,
            negate,
            origin: None,
        }
    }

    #[test]
    fn thresholds_flip_and_centre_as_player_does() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("m.png");
        // Top row: black, a dark grey (occ 0.9: unknown), white; bottom row: a light grey
        // (occ 0.098: free), grey 12 (occ 0.953: occupied), mid grey.
        let mut img = GrayImage::new(3, 2);
        for (x, y, v) in [(0, 0, 0), (1, 0, 25), (2, 0, 255), (0, 1, 230), (1, 1, 12)] {
            img.put_pixel(x, y, image::Luma([v]));
        }
        img.put_pixel(2, 1, image::Luma([128]));
        img.save(&path).unwrap();
        let map = GridMap::from_image(&path, &settings(false)).unwrap();
        assert_eq!((map.width, map.height), (3, 2));
        assert_eq!(map.origin, (-0.75, -0.5));
        // Map row 1 is the image's top row.
        let row = |j| (0..3).map(|i| map.cell(i, j).unwrap()).collect::<Vec<_>>();
        assert_eq!(row(1), vec![1, 0, -1]);
        assert_eq!(row(0), vec![-1, 1, 0]);
        assert_eq!(map.cell(3, 0), None);
        let negated = GridMap::from_image(&path, &settings(true)).unwrap();
        assert_eq!(negated.cell(0, 1), Some(-1));
        assert_eq!(negated.cell(2, 1), Some(1));
    }

    #[test]
    fn alpha_counts_in_the_average_and_tiles_pad_with_unknown() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.png");
        // Black but fully transparent: (0 + 0 + 0 + 0) / 4 = 0, occupied; black and opaque:
        // 255 / 4 = 63.75, occ 0.75, unknown.
        let mut img = GrayAlphaImage::new(2, 1);
        img.put_pixel(0, 0, LumaA([0, 0]));
        img.put_pixel(1, 0, LumaA([0, 255]));
        img.save(&path).unwrap();
        let map = GridMap::from_image(&path, &settings(false)).unwrap();
        assert_eq!((map.cell(0, 0), map.cell(1, 0)), (Some(1), Some(0)));
        let tile = map.tile(1, 0, 2, 2).unwrap();
        assert_eq!(tile.cells().unwrap(), vec![0, 0, 0, 0]);
        assert_eq!(tile.data_range, 1);
        assert!(map.tile(0, 0, u32::MAX, u32::MAX).is_none());
        assert!(map.tile(u32::MAX, u32::MAX, 2, 1).is_some());
    }
}
