//! A beam's one walk through the walls and the boxes about its sensor together
//! (`sim/joint_walk.rs`): the boxes in its direction whose cells its path may meet are drawn
//! and walked with the walls; a box too large for cells is met on its exact outline.

use smallvec::SmallVec;

use super::{Near, NearbyBoxes, SolidBox};
use crate::sim::box_cells::BoxCells;
use crate::sim::joint_walk::{Met, walk_joint};
use crate::sim::raster_walk::Ray;
use crate::sim::wall_raster::WallRaster;

impl<'a> NearbyBoxes<'a> {
    /// What the ray from `(x, y)` along the unit `(dx, dy)` meets first within `max`: `walls`
    /// (`None` where the beam cannot meet them) or one of the boxes `candidates` lists (those
    /// `counts` accepts), walked on Stage's path through the scan's regions
    /// ([`NearbyBoxes::walked_in`]) on a raster of `resolution`. The distance, and the wall or
    /// the box met.
    pub(in crate::sim) fn nearest_joint(
        &self,
        candidates: &[u32],
        (walls, resolution): (Option<&WallRaster>, f64),
        (x, y): (f64, f64),
        (dx, dy): (f64, f64),
        max: f64,
        counts: impl Fn(&SolidBox<'a>) -> bool,
    ) -> Option<(f64, Option<&SolidBox<'a>>)> {
        let scene = self.scene.as_deref()?;
        let mut cells: SmallVec<[(&BoxCells, &SolidBox<'a>); 4]> = SmallVec::new();
        // The nearest box met on its exact outline, if any is.
        let mut exact: Option<(f64, &SolidBox<'a>)> = None;
        // How far the farthest box walked may be met: its far side, plus two cells for the
        // path's steps.
        let mut farthest = 0.0f64;
        for &k in candidates {
            let b = &self.boxes[k as usize];
            if !counts(b) || !b.may_hit(x, y, dx, dy, max) {
                continue;
            }
            match b.near(self.drawn(k as usize), (x, y), (dx, dy)) {
                Near::Beside => {}
                Near::Cells(drawn) => {
                    let far = b.far_side((x, y), (dx, dy)) + 2.0 * resolution;
                    farthest = farthest.max(far);
                    cells.push((drawn, b));
                }
                Near::Exact(d) => {
                    if let Some(d) = d.filter(|&d| d <= max)
                        && exact.is_none_or(|(e, _)| d <= e)
                    {
                        exact = Some((d, b));
                    }
                }
            }
        }
        // A beam that cannot meet a wall meets nothing past its farthest box: its walk ends
        // there (most of the swarm's walked beams pass beside the robot they were walked for,
        // and went on across empty regions to their range).
        let stop = if walls.is_none() {
            farthest.min(max)
        } else {
            max
        };
        let walked = if walls.is_none() && cells.is_empty() {
            None
        } else {
            let per_metre = 1.0 / resolution;
            Ray::new(per_metre, (x, y), (dx, dy), scene.range)
                .and_then(|ray| walk_joint(walls, &cells, &scene.regions, &ray, stop))
        };
        let walked = walked.map(|(d, met)| match met {
            Met::Wall => (d, None),
            Met::Body(k) => (d, Some(cells[k].1)),
        });
        match (walked, exact) {
            // A box on its outline as near as the walk's cell is met (as a box met as near as
            // a wall always was).
            (Some((w, _)), Some((e, b))) if e <= w => Some((e, Some(b))),
            (None, Some((e, b))) => Some((e, Some(b))),
            (walked, _) => walked,
        }
    }
}
