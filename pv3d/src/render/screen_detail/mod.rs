//! Level of detail by screen size: what a pixel cannot show is not sent to the GPU.
//!
//! A 361-beam scan of a robot seen among 256 others spans a few dozen pixels: most of its
//! vertices are within a pixel of the line through their neighbours, and Mesa's software
//! renderer pays per primitive, not per pixel. So chains — consecutive segments that share
//! an endpoint, the rims of triangle fans — are simplified on screen (Douglas–Peucker, one
//! pixel), and a point within half a point's size of the last point kept is left out (its
//! centre is painted by that point). Zoom in and the detail comes back. Nothing drawn moves
//! by more than the tolerance, whatever a plugin drew; vertices at or behind the eye, where
//! no screen position exists, are always kept.

use glam::{Mat4, Vec2, Vec3, Vec4Swizzles};

use super::gpu_vertex::GpuVertex;

mod fans;
pub use fans::FanOut;

/// The projection and viewport that decide what a pixel is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScreenDetail {
    view_proj: Mat4,
    half_viewport_px: Vec2,
    /// How far a simplified line may stray from the original, pixels.
    tolerance_px: f32,
    /// Points closer than this to the last point kept are left out, pixels.
    point_spacing_px: f32,
}

impl ScreenDetail {
    /// Detail for a viewport `viewport_px` physical pixels big seen through `view_proj`, where
    /// points are drawn `point_size_px` wide.
    pub fn new(view_proj: Mat4, viewport_px: Vec2, point_size_px: f32) -> ScreenDetail {
        ScreenDetail {
            view_proj,
            half_viewport_px: viewport_px / 2.0,
            tolerance_px: 1.0,
            point_spacing_px: (point_size_px / 2.0).max(1.0),
        }
    }

    /// The viewport's area, pixels².
    fn area_px(&self) -> f32 {
        (4.0 * self.half_viewport_px.x * self.half_viewport_px.y).max(1.0)
    }

    /// Where `pos` lands on screen, in pixels from the centre; NaN at or behind the eye.
    fn screen(&self, pos: [f32; 3]) -> Vec2 {
        let clip = self.view_proj * Vec3::from(pos).extend(1.0);
        if clip.w > 1e-6 {
            clip.xy() / clip.w * self.half_viewport_px
        } else {
            Vec2::NAN
        }
    }
}

/// Simplifies geometry for a [`ScreenDetail`], reusing its buffers from chain to chain and
/// frame to frame.
#[derive(Debug, Default)]
pub struct Simplifier {
    chain: Vec<GpuVertex>,
    at: Vec<Vec2>,
    keep: Vec<bool>,
    spans: Vec<(usize, usize)>,
}

impl Simplifier {
    /// Appends `segments` (vertex pairs) to `out`, chains simplified.
    pub fn append_lines(
        &mut self,
        detail: &ScreenDetail,
        segments: &[GpuVertex],
        out: &mut Vec<GpuVertex>,
    ) {
        let continues = |prev: &[GpuVertex], next: &[GpuVertex]| {
            next[0].pos == prev[1].pos
                && next[0].color == prev[1].color
                && next[1].color == prev[1].color
        };
        self.simplify_runs(detail, segments, 2, continues, |_, a, b| out.extend([a, b]));
    }

    /// Appends `triangles` to `out`, fans simplified: a run of triangles that share their
    /// first vertex, each starting where the one before ended, is a fan around that vertex
    /// whose rim is simplified as a polyline.
    pub fn append_triangles(
        &mut self,
        detail: &ScreenDetail,
        triangles: &[GpuVertex],
        out: &mut Vec<GpuVertex>,
    ) {
        let continues = |prev: &[GpuVertex], next: &[GpuVertex]| {
            next[0] == prev[0] && next[1] == prev[2] && next[2].color == prev[2].color
        };
        self.simplify_runs(detail, triangles, 3, continues, |centre, a, b| {
            out.extend([centre, a, b])
        });
    }

    /// Splits `primitives` (`stride` vertices each) into runs in which each primitive
    /// `continues` the one before; a run's polyline is the second-to-last vertex of its first
    /// primitive followed by the last vertex of each (a segment chain's vertices; a fan's
    /// rim). Each run is simplified and `emit` called with the run's first vertex (a fan's
    /// centre) and every kept pair. A primitive cut short at the end is dropped, as GL would.
    fn simplify_runs(
        &mut self,
        detail: &ScreenDetail,
        primitives: &[GpuVertex],
        stride: usize,
        continues: impl Fn(&[GpuVertex], &[GpuVertex]) -> bool,
        mut emit: impl FnMut(GpuVertex, GpuVertex, GpuVertex),
    ) {
        let primitives = &primitives[..primitives.len() / stride * stride];
        let mut start = 0;
        while start < primitives.len() {
            let mut end = start + stride;
            while end < primitives.len()
                && continues(&primitives[end - stride..end], &primitives[end..])
            {
                end += stride;
            }
            self.chain.clear();
            self.chain.push(primitives[start + stride - 2]);
            self.chain.extend(
                primitives[start..end]
                    .iter()
                    .skip(stride - 1)
                    .step_by(stride),
            );
            self.simplify_chain(detail);
            let kept = self.chain.iter().zip(&self.keep).filter(|(_, k)| **k);
            let mut previous = None;
            for (&v, _) in kept {
                if let Some(p) = previous {
                    emit(primitives[start], p, v);
                }
                previous = Some(v);
            }
            start = end;
        }
    }

    /// Appends `points` to `out`, leaving out each point closer than the point spacing to
    /// the last one kept (of the same colour).
    pub fn append_points(
        &mut self,
        detail: &ScreenDetail,
        points: &[GpuVertex],
        out: &mut Vec<GpuVertex>,
    ) {
        let spacing_squared = detail.point_spacing_px * detail.point_spacing_px;
        let mut last: Option<(GpuVertex, Vec2)> = None;
        for &p in points {
            let at = detail.screen(p.pos);
            if let Some((kept, kept_at)) = last
                && kept.color == p.color
                && kept_at.distance_squared(at) < spacing_squared
            {
                continue; // NaN compares false: a point behind the eye is kept
            }
            out.push(p);
            last = Some((p, at));
        }
    }

    /// Douglas–Peucker over `self.chain` on screen: sets `self.keep` to its ends, every
    /// vertex without a screen position, and as few vertices between as leave every dropped
    /// vertex within the tolerance of the line drawn instead. A straight wall or a far arc
    /// collapses to a few segments.
    fn simplify_chain(&mut self, detail: &ScreenDetail) {
        let n = self.chain.len();
        self.at.clear();
        self.at
            .extend(self.chain.iter().map(|v| detail.screen(v.pos)));
        self.keep.clear();
        self.keep.extend(self.at.iter().map(|p| p.is_nan()));
        if n == 0 {
            return;
        }
        (self.keep[0], self.keep[n - 1]) = (true, true);
        self.spans.clear();
        let mut anchor = 0;
        for i in 1..n {
            if self.keep[i] {
                self.spans.push((anchor, i));
                anchor = i;
            }
        }
        let tolerance_squared = detail.tolerance_px * detail.tolerance_px;
        while let Some((a, b)) = self.spans.pop() {
            let (pa, pb) = (self.at[a], self.at[b]);
            if b - a < 2 || pa.is_nan() || pb.is_nan() {
                continue;
            }
            let segment = Segment::new(pa, pb);
            let (mut farthest, mut farthest_squared) = (a, 0.0);
            for (i, &p) in self.at[a + 1..b].iter().enumerate() {
                let d = segment.distance_squared(p);
                if d > farthest_squared {
                    (farthest, farthest_squared) = (a + 1 + i, d);
                }
            }
            if farthest_squared >= tolerance_squared {
                self.keep[farthest] = true;
                self.spans.extend([(a, farthest), (farthest, b)]);
            }
        }
    }
}

/// A segment on screen, ready for many distance queries (the inner loop of the
/// simplification: one division per span, not per vertex).
struct Segment {
    start: Vec2,
    along: Vec2,
    inverse_length_squared: f32,
}

impl Segment {
    fn new(start: Vec2, end: Vec2) -> Segment {
        let along = end - start;
        let length_squared = along.length_squared();
        Segment {
            start,
            along,
            inverse_length_squared: if length_squared > 0.0 {
                1.0 / length_squared
            } else {
                0.0
            },
        }
    }

    /// The squared distance from `p` to the segment.
    fn distance_squared(&self, p: Vec2) -> f32 {
        let from_start = p - self.start;
        let t = (from_start.dot(self.along) * self.inverse_length_squared).clamp(0.0, 1.0);
        (from_start - self.along * t).length_squared()
    }
}

#[cfg(test)]
mod tests;
