//! Walls from a floorplan bitmap (the Stage world's): dark pixels stand up as boxes, one box per
//! horizontal run of wall pixels so that a whole wall is a handful of triangles.

use std::path::Path;

use glam::Vec3;

use framework::scene::{Geometry, Rgba};

/// A floorplan bitmap that cannot be read, and which.
#[derive(Debug, thiserror::Error)]
#[error("cannot read floorplan {}: {source}", path.display())]
pub struct FloorplanError {
    pub path: std::path::PathBuf,
    pub source: image::ImageError,
}

/// Where a bitmap lies: its size in metres and the position of its centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    pub size: (f32, f32),
    pub centre: (f32, f32),
    pub wall_height: f32,
}

/// Adds the bitmap's walls to `geometry`. The top row of the image is the north edge.
pub fn walls_from_bitmap(
    path: &Path,
    placement: Placement,
    color: Rgba,
    geometry: &mut Geometry,
) -> Result<usize, FloorplanError> {
    let image = image::open(path)
        .map_err(|source| FloorplanError {
            path: path.to_path_buf(),
            source,
        })?
        .to_luma_alpha8();
    let (w, h) = image.dimensions();
    let (cell_x, cell_y) = (placement.size.0 / w as f32, placement.size.1 / h as f32);
    let west = placement.centre.0 - placement.size.0 / 2.0;
    let north = placement.centre.1 + placement.size.1 / 2.0;
    let mut boxes = 0;
    for y in 0..h {
        let mut x = 0;
        while x < w {
            let wall = |x: u32| {
                let p = image.get_pixel(x, y);
                p[1] > 127 && p[0] < 128
            };
            if !wall(x) {
                x += 1;
                continue;
            }
            let start = x;
            while x < w && wall(x) {
                x += 1;
            }
            let length = (x - start) as f32 * cell_x;
            let centre = Vec3::new(
                west + start as f32 * cell_x + length / 2.0,
                north - (y as f32 + 0.5) * cell_y,
                placement.wall_height / 2.0,
            );
            geometry.cuboid(
                centre,
                Vec3::new(length, cell_y, placement.wall_height),
                color,
            );
            boxes += 1;
        }
    }
    Ok(boxes)
}
