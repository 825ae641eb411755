//! A ray's nearest box among those about its sensor: each box's bounding circle first, then
//! its cells on the raster (or its exact outline), against the nearest hit so far.

use super::{NearbyBoxes, SolidBox};
use crate::sim::box_cells::{Drawn, RayScene};

impl<'a> NearbyBoxes<'a> {
    /// [`NearbyBoxes::nearest_along`] among the boxes `candidates` lists (indices, in
    /// increasing order): those the scan's per-beam lists (`sim/beams.rs`) have in the ray's
    /// direction.
    pub fn nearest_among(
        &self,
        candidates: &[u32],
        (x, y): (f64, f64),
        (dx, dy): (f64, f64),
        max: f64,
        counts: impl Fn(&SolidBox<'a>) -> bool,
    ) -> Option<(f64, &SolidBox<'a>)> {
        let listed = candidates
            .iter()
            .map(|&k| (&self.boxes[k as usize], self.drawn(k as usize)));
        nearest_of(
            listed.filter(|(b, _)| counts(b)),
            self.scene.as_deref(),
            (x, y),
            (dx, dy),
            max,
        )
    }

    /// The nearest box along the ray from `(x, y)` at `angle`, within `max`: (distance, box).
    pub fn nearest(&self, x: f64, y: f64, angle: f64, max: f64) -> Option<(f64, &SolidBox<'a>)> {
        self.nearest_where(x, y, angle, max, |_| true)
    }

    /// [`NearbyBoxes::nearest`] among the boxes `counts` accepts.
    pub fn nearest_where(
        &self,
        x: f64,
        y: f64,
        angle: f64,
        max: f64,
        counts: impl Fn(&SolidBox<'a>) -> bool,
    ) -> Option<(f64, &SolidBox<'a>)> {
        let (dy, dx) = angle.sin_cos();
        self.nearest_along(x, y, dx, dy, max, counts)
    }

    /// [`NearbyBoxes::nearest_where`] along the unit direction `(dx, dy)`.
    pub fn nearest_along(
        &self,
        x: f64,
        y: f64,
        dx: f64,
        dy: f64,
        max: f64,
        counts: impl Fn(&SolidBox<'a>) -> bool,
    ) -> Option<(f64, &SolidBox<'a>)> {
        nearest_of(
            self.boxes
                .iter()
                .enumerate()
                .map(|(k, b)| (b, self.drawn(k)))
                .filter(|(b, _)| counts(b)),
            self.scene.as_deref(),
            (x, y),
            (dx, dy),
            max,
        )
    }

    /// Every box along the ray within `max`, in no particular order: (distance, box).
    pub fn all_along(
        &self,
        x: f64,
        y: f64,
        angle: f64,
        max: f64,
    ) -> impl Iterator<Item = (f64, &SolidBox<'a>)> {
        let (dy, dx) = angle.sin_cos();
        self.boxes
            .iter()
            .filter(move |b| b.may_hit(x, y, dx, dy, max))
            .filter_map(move |b| {
                b.hit(None, None, x, y, dx, dy)
                    .filter(|&d| d <= max)
                    .map(|d| (d, b))
            })
    }
}

/// The nearest of `boxes` along the ray from `(x, y)` in the unit direction `(dx, dy)`, within
/// `max`; each box's cheap bounding test is made against the nearest hit so far.
fn nearest_of<'b, 'a: 'b>(
    boxes: impl Iterator<Item = (&'b SolidBox<'a>, Option<Drawn<'b>>)>,
    scene: Option<&RayScene>,
    (x, y): (f64, f64),
    (dx, dy): (f64, f64),
    max: f64,
) -> Option<(f64, &'b SolidBox<'a>)> {
    let mut best: Option<(f64, &SolidBox<'a>)> = None;
    for (b, cells) in boxes {
        let limit = best.map_or(max, |(d, _)| d);
        if !b.may_hit(x, y, dx, dy, limit) {
            continue;
        }
        if let Some(d) = b.hit(cells, scene, x, y, dx, dy).filter(|&d| d <= limit) {
            best = Some((d, b));
        }
    }
    best
}
