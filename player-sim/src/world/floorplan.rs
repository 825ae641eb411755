//! Floorplans: bitmaps and Stage `block`s drawn into one occupancy grid, and the walls Stage's
//! `boundary 1` puts around a floorplan's box (Stage's own `map.inc` sets it), so that robots
//! cannot drive off the map.

use std::path::Path;

use super::blocks::{self, Polygon, placed};
use super::models::Model;
use super::properties::{color_of, err, numbers, opt_number, pose_of, ranger_return_of, string};
use super::{Floorplan, OccupancyGrid, Pose, StageBitmap, World};
use crate::worldfile::WorldFileError;

/// Thickness of the `boundary` walls, m (Stage's).
const BOUNDARY_THICKNESS: f64 = 0.01;

impl World {
    /// Reads a floorplan: a bitmap becomes the grid now; blocks and boundary walls wait, in
    /// world coordinates, until every floorplan and the world's resolution are known.
    pub(super) fn floorplan(&mut self, model: &Model, base: &Path) -> Result<(), WorldFileError> {
        self.note_unread(model);
        let bitmap = model.get("bitmap");
        if bitmap.is_none() && !blocks::has_blocks(model) {
            self.ignore("floorplan without a bitmap or blocks", &model.pos);
            return Ok(());
        }
        let size = numbers(model.get("size"), 2, &model.pos)?;
        if !size[..2].iter().all(|s| s.is_finite() && *s > 0.0) {
            let at = model.get("size").map_or(&model.pos, |p| &p.pos);
            return Err(err(
                at,
                format!(
                    "a floorplan's size [{} {}] must be more than nothing each way",
                    size[0], size[1]
                ),
            ));
        }
        let pose = pose_of(model)?;
        self.floor_height = size.get(2).copied().unwrap_or(1.0);
        self.floor_color = color_of(model)?;
        self.floor_ranger_return = ranger_return_of(model)?;
        if opt_number(model, "boundary")?.is_some_and(|b| b != 0.0) {
            for wall in boundary_walls([size[0], size[1]], pose) {
                self.pending_floor.push((wall, model.pos.clone()));
            }
        }
        let Some(bitmap) = bitmap else {
            for polygon in blocks::model_blocks(model, [size[0], size[1]])? {
                self.pending_floor
                    .push((placed(&polygon, pose), model.pos.clone()));
            }
            return Ok(());
        };
        if let Some(block) = model.parts.iter().find(|p| p.kind == "block") {
            self.ignore("block() in a floorplan with a bitmap", &block.pos);
        }
        let file = string(bitmap)?;
        let grid = OccupancyGrid::from_png(&base.join(file), size[0], size[1], pose.x, pose.y)
            .map_err(|e| err(&bitmap.pos, e.to_string()))?;
        // Where the whole image lies (its walls fill `size`; a margin lies beyond).
        let covers = [
            grid.width as f64 * grid.cell.0,
            grid.height as f64 * grid.cell.1,
        ];
        let centre = [
            grid.origin.0 + covers[0] / 2.0,
            grid.origin.1 + covers[1] / 2.0,
        ];
        if pose.a == 0.0 {
            let placed = StageBitmap::new(grid.clone(), [size[0], size[1]], [pose.x, pose.y]);
            self.floor_bitmap = Some(std::sync::Arc::new(placed));
        }
        self.floor = Some(grid);
        self.floorplan = Some(Floorplan {
            bitmap: base.join(file),
            size: covers,
            centre,
            height: self.floor_height,
            color: self.floor_color,
        });
        Ok(())
    }

    /// Draws the pending floorplan polygons into the floor grid: the bitmap's, grown to hold
    /// them, or a new one of the world's resolution. Tells whether that resolution was used.
    pub(super) fn draw_floor_blocks(&mut self) -> Result<bool, WorldFileError> {
        let pending = std::mem::take(&mut self.pending_floor);
        let Some((_, first_at)) = pending.first() else {
            return Ok(false);
        };
        let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for point in pending.iter().flat_map(|(polygon, _)| polygon) {
            for k in 0..2 {
                min[k] = min[k].min(point[k]);
                max[k] = max[k].max(point[k]);
            }
        }
        let (mut grid, new) = match self.floor.take() {
            None => (OccupancyGrid::covering(min, max, self.resolution), true),
            Some(bitmap) => {
                let grown = bitmap.grown_to(min, max).ok_or_else(|| {
                    err(
                        first_at,
                        "block floorplans lie too far from the bitmap floorplan for one grid",
                    )
                })?;
                (grown, false)
            }
        };
        for (polygon, _) in &pending {
            grid.draw_polygon(polygon);
        }
        self.floor = Some(grid);
        self.floor_blocks = pending.into_iter().map(|(polygon, _)| polygon).collect();
        Ok(new)
    }
}

/// Stage's `boundary 1`: four thin walls just inside the edges of a floorplan's box.
fn boundary_walls(size: [f64; 2], pose: Pose) -> Vec<Polygon> {
    let ([hx, hy], t) = ([size[0] / 2.0, size[1] / 2.0], BOUNDARY_THICKNESS);
    let rect = |x0: f64, y0: f64, x1: f64, y1: f64| {
        placed(&[[x0, y0], [x1, y0], [x1, y1], [x0, y1]], pose)
    };
    vec![
        rect(-hx, -hy, -hx + t, hy),
        rect(-hx, -hy, hx, -hy + t),
        rect(-hx, hy - t, hx, hy),
        rect(hx - t, -hy, hx, hy),
    ]
}
