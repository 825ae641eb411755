//! Walled worlds for the raster tests: a bitmap of `#` pixels laid out as a world file's
//! `floorplan` model lays its bitmap, centred on the origin.

use crate::world::{Floorplan, OccupancyGrid, World};

/// A world whose floorplan is `rows` (`#` a wall pixel, the first row the north) of `pixel`
/// metres, centred on the origin, its walls on Stage's raster of `resolution`.
pub fn walled(rows: &[String], pixel: f64, resolution: f64) -> World {
    let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
    let size = [rows[0].len() as f64 * pixel, rows.len() as f64 * pixel];
    let mut world = World::default();
    world.resolution = resolution;
    let corner = (-size[0] / 2.0, -size[1] / 2.0);
    world.floor = Some(OccupancyGrid::from_rows(&rows, pixel, corner));
    world.floorplan = Some(Floorplan {
        bitmap: Default::default(),
        size,
        centre: [0.0, 0.0],
        height: 1.0,
        color: [0, 0, 0],
    });
    world
}

/// `columns` × `rows` pixels with a wall of one pixel all round, and within it a wall where
/// `inside(row, column)` says so.
pub fn bordered(
    columns: usize,
    rows: usize,
    mut inside: impl FnMut(usize, usize) -> bool,
) -> Vec<String> {
    (0..rows)
        .map(|r| {
            (0..columns)
                .map(|c| {
                    let border = r == 0 || c == 0 || r == rows - 1 || c == columns - 1;
                    if border || inside(r, c) { '#' } else { '.' }
                })
                .collect()
        })
        .collect()
}
