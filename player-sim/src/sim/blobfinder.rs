//! Stage's blobfinder: one ray per image column over the field of view; runs of neighbouring
//! columns that hit things of one colour make a blob, whose height in the image follows from
//! its mean range as if everything were 0.6 m tall. The finder sees everything but its own
//! robot (and what that robot holds), walls included.

use super::Simulation;
use super::body_pose::on_robot;
use super::nearby::NearbyBoxes;
use crate::world::BlobfinderSpec;

/// The height Stage gives every seen thing to size its blob, m.
const ASSUMED_HEIGHT: f64 = 0.6;

/// A blob as Stage finds it: image columns (left of the image first), rows, and mean range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Blob {
    pub color: [u8; 3],
    pub left: u32,
    pub right: u32,
    pub top: u32,
    pub bottom: u32,
    pub range: f64,
}

/// What robot `robot`'s blobfinder sees now.
pub fn blobs(sim: &Simulation, robot: usize, finder: &BlobfinderSpec) -> Vec<Blob> {
    let at = on_robot(sim.robots[robot].pose, finder.pose);
    let boxes = NearbyBoxes::around(sim, Some(robot), at.x, at.y, finder.range);
    let width = finder.width as usize;
    let spacing = if width > 1 {
        finder.fov / (width - 1) as f64
    } else {
        0.0
    };
    // Column 0 is the rightmost ray, as Stage casts them.
    let samples: Vec<Option<(f64, [u8; 3])>> = (0..width)
        .map(|s| {
            let angle = at.a + finder.pan - finder.fov / 2.0 + s as f64 * spacing;
            let wall = sim
                .world
                .floor
                .as_ref()
                .and_then(|g| g.raycast(at.x, at.y, angle, finder.range))
                .map(|d| (d, sim.world.floor_color));
            let limit = wall.map_or(finder.range, |(d, _)| d);
            boxes
                .nearest(at.x, at.y, angle, limit)
                .map(|(d, b)| (d, b.color))
                .or(wall)
        })
        .collect();
    let radians_per_row = finder.fov / f64::from(finder.height);
    let middle = (finder.height / 2) as i64;
    let mut found = Vec::new();
    let mut s = 0;
    while s < width {
        let Some((_, color)) = samples[s] else {
            s += 1;
            continue;
        };
        let first = s;
        while s < width && samples[s].is_some_and(|(_, c)| c == color) {
            s += 1;
        }
        let last = s - 1;
        // Stage steps past the column that ended the run: a blob needs a gap of two columns
        // to end, so the first column of a touching blob of another colour is lost.
        s += 1;
        if !finder.colors.is_empty() && !finder.colors.contains(&color) {
            continue;
        }
        let run = &samples[first..=last];
        let range = run.iter().flatten().map(|(d, _)| d).sum::<f64>() / run.len() as f64;
        let half_angle = (ASSUMED_HEIGHT / 2.0).atan2(range);
        let rows = (half_angle / radians_per_row) as i64;
        let top = (middle - rows).max(0);
        let bottom = (middle + rows).min(i64::from(finder.height));
        found.push(Blob {
            color,
            left: (width - last - 1) as u32,
            right: (width - first - 1) as u32,
            top: top as u32,
            bottom: bottom as u32,
            range,
        });
    }
    found
}
