//! A Stage blobfinder as Player's Stage plugin serves it: blobs with their colour, bounding
//! box, centre, area and range; the image size only when there are blobs (the plugin leaves
//! it zero otherwise); every request NACKed.

use player_proto::interfaces::blobfinder::{Blob, BlobfinderData};

use crate::sim::{Simulation, blobs};

pub(super) fn data(sim: &Simulation, robot: usize, finder: usize) -> BlobfinderData {
    let spec = &sim.world.robots[robot].blobfinders[finder];
    let found = blobs(sim, robot, spec);
    if found.is_empty() {
        return BlobfinderData {
            width: 0,
            height: 0,
            blobs: Vec::new(),
        };
    }
    let blobs = found
        .iter()
        .map(|b| {
            // Signed as the plugin computes them: the rows run top down, so dy is negative.
            let dx = i64::from(b.right) - i64::from(b.left);
            let dy = i64::from(b.top) - i64::from(b.bottom);
            let [r, g, bl] = b.color.map(u32::from);
            Blob {
                id: 0,
                color: (r << 16) | (g << 8) | bl,
                area: (dx * dy).unsigned_abs() as u32,
                x: (i64::from(b.left) + dx / 2) as u32,
                y: (i64::from(b.bottom) + dy / 2) as u32,
                left: b.left,
                right: b.right,
                top: b.top,
                bottom: b.bottom,
                range: b.range as f32,
            }
        })
        .collect();
    BlobfinderData {
        width: spec.width,
        height: spec.height,
        blobs,
    }
}
