//! A bitmap floorplan's pixels where Stage puts them, to the last bit. Stage traces the dark
//! pixels' outlines in pixel units (rows counted down from the top, so y is the row negated),
//! centres them on the dark pixels' bounding box, scales them by the model's size over that
//! box, adds the model's pose, and floors each corner times the cells per metre. A pixel edge
//! that lies on a cell border (every fifth of cave.png's, 1.6 cells a pixel) falls on one side
//! or the other by the rounding of that arithmetic, so the walls' raster computes each edge the
//! same way (`sim/wall_raster.rs`) rather than from the grid's origin and cell size, whose
//! rounding put some edges a cell west or south of Stage's.

use super::OccupancyGrid;

/// The bitmap's own pixels (before any block or `boundary` wall is drawn into the grid) and
/// where Stage places their edges.
#[derive(Debug, Clone)]
pub struct StageBitmap {
    /// Dark pixels, rows from the south, as the floor grid holds them.
    pub pixels: OccupancyGrid,
    /// Per axis, in Stage's pixel units: the dark pixels' bounding box's middle, and metres per
    /// pixel (the model's size over the box).
    offset: [f64; 2],
    scale: [f64; 2],
    /// The model's position.
    centre: [f64; 2],
}

impl StageBitmap {
    /// The placement of `pixels` (as read, rows from the south) over `size` metres at `centre`
    /// (an unrotated floorplan).
    pub fn new(pixels: OccupancyGrid, size: [f64; 2], centre: [f64; 2]) -> StageBitmap {
        let (w, h) = (pixels.width, pixels.height);
        let (mut low, mut high) = ((w, h), (0, 0));
        for row in 0..h {
            for column in 0..w {
                if pixels.occupied[row * w + column] {
                    low = (low.0.min(column), low.1.min(row));
                    high = (high.0.max(column), high.1.max(row));
                }
            }
        }
        if low.0 > high.0 {
            (low, high) = ((0, 0), (w.max(1) - 1, h.max(1) - 1));
        }
        // Stage's y of a pixel edge is minus its row from the top: the box runs from minus the
        // lowest dark row's bottom edge up to minus the highest's top edge.
        let (top_row, bottom_row) = (h - 1 - high.1, h - 1 - low.1);
        let extent = [
            (high.0 + 1 - low.0) as f64,
            (bottom_row + 1 - top_row) as f64,
        ];
        let bottom = -((bottom_row + 1) as f64);
        StageBitmap {
            pixels,
            offset: [low.0 as f64 + extent[0] / 2.0, bottom + extent[1] / 2.0],
            scale: [size[0] / extent[0], size[1] / extent[1]],
            centre,
        }
    }

    /// Metres east of the origin of the edge west of pixel column `column` (`width`: the last
    /// column's east edge).
    pub fn x(&self, column: usize) -> f64 {
        self.centre[0] + (column as f64 - self.offset[0]) * self.scale[0]
    }

    /// Metres north of the origin of the edge south of grid row `row` (rows from the south;
    /// `height`: the top row's north edge).
    pub fn y(&self, row: usize) -> f64 {
        let from_top = self.pixels.height - row;
        self.centre[1] + (-(from_top as f64) - self.offset[1]) * self.scale[1]
    }
}
