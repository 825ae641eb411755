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

use super::batch::GpuVertex;

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
mod tests {
    use super::*;
    use glam::camera::rh::proj::opengl;

    /// A top-down orthographic view, `metres_per_pixel`, on a 1000-pixel square.
    fn top_view(metres_per_pixel: f32) -> ScreenDetail {
        let half = 500.0 * metres_per_pixel;
        let proj = opengl::orthographic(-half, half, -half, half, -10.0, 10.0);
        ScreenDetail::new(proj, Vec2::splat(1000.0), 2.0)
    }

    fn v(x: f32, y: f32) -> GpuVertex {
        GpuVertex {
            pos: [x, y, 0.0],
            color: [255, 0, 0, 255],
        }
    }

    /// A polyline as segments through `points`.
    fn chain(points: &[GpuVertex]) -> Vec<GpuVertex> {
        points.windows(2).flat_map(|w| [w[0], w[1]]).collect()
    }

    /// Points on an arc of `radius` m, one per degree from 0 to `degrees`.
    fn arc(radius: f32, degrees: usize) -> Vec<GpuVertex> {
        (0..=degrees)
            .map(|d| {
                let a = (d as f32).to_radians();
                v(a.cos() * radius, a.sin() * radius)
            })
            .collect()
    }

    /// The largest distance, in pixels of `detail`, from any of `original` to the polyline
    /// drawn as `segments`.
    fn worst_deviation(
        detail: &ScreenDetail,
        original: &[GpuVertex],
        segments: &[GpuVertex],
    ) -> f32 {
        let px = |g: &GpuVertex| detail.screen(g.pos);
        original
            .iter()
            .map(|p| {
                segments
                    .chunks(2)
                    .map(|s| {
                        Segment::new(px(&s[0]), px(&s[1]))
                            .distance_squared(px(p))
                            .sqrt()
                    })
                    .fold(f32::INFINITY, f32::min)
            })
            .fold(0.0, f32::max)
    }

    #[test]
    fn a_straight_chain_becomes_one_segment() {
        let points: Vec<GpuVertex> = (0..=100).map(|i| v(i as f32 * 0.1, 0.0)).collect();
        let mut out = Vec::new();
        Simplifier::default().append_lines(&top_view(0.01), &chain(&points), &mut out); // even at 10 pixels a step
        assert_eq!(out, vec![points[0], points[100]]);
    }

    #[test]
    fn an_arc_keeps_what_a_pixel_can_show_and_never_strays_a_pixel() {
        let points = arc(2.0, 180);
        let segments = chain(&points);
        let mut kept_before = usize::MAX;
        for metres_per_pixel in [0.0001, 0.001, 0.01, 0.05, 0.2] {
            let detail = top_view(metres_per_pixel);
            let mut out = Vec::new();
            Simplifier::default().append_lines(&detail, &segments, &mut out);
            let kept = out.len() / 2;
            assert!(worst_deviation(&detail, &points, &out) < 1.0);
            for pair in out.chunks(2).collect::<Vec<_>>().windows(2) {
                assert_eq!(pair[0][1], pair[1][0], "still one connected chain");
            }
            assert_eq!(out[0], points[0]);
            assert_eq!(out.last(), points.last());
            if metres_per_pixel == 0.0001 {
                // A 20 000-pixel radius: a degree's chord sags 0.8 pixels from the arc.
                assert!(kept >= 90, "zoomed in, most vertices show: {kept}");
            }
            if metres_per_pixel == 0.2 {
                assert!(kept <= 6, "a 10-pixel half circle: {kept} segments");
            }
            assert!(kept < kept_before, "fewer vertices for fewer pixels");
            kept_before = kept;
        }
    }

    #[test]
    fn a_zigzag_bigger_than_a_pixel_is_kept() {
        let points: Vec<GpuVertex> = (0..20)
            .map(|i| v(i as f32, (i % 2) as f32 * 0.05))
            .collect();
        let mut out = Vec::new();
        Simplifier::default().append_lines(&top_view(0.01), &chain(&points), &mut out); // 5-pixel teeth
        assert_eq!(out, chain(&points));
        out.clear();
        Simplifier::default().append_lines(&top_view(0.1), &chain(&points), &mut out); // half-pixel teeth
        assert_eq!(out, vec![points[0], points[19]]);
    }

    #[test]
    fn separate_segments_and_colour_changes_are_never_merged() {
        let mut segments = vec![v(0.0, 0.0), v(0.1, 0.0), v(0.2, 0.0), v(0.3, 0.0)];
        let mut out = Vec::new();
        Simplifier::default().append_lines(&top_view(1.0), &segments, &mut out);
        assert_eq!(out, segments, "no shared endpoint: not a chain");
        segments[2] = segments[1];
        segments[3].color = [0, 255, 0, 255];
        out.clear();
        Simplifier::default().append_lines(&top_view(1.0), &segments, &mut out);
        assert_eq!(out, segments, "shared endpoint but another colour");
    }

    #[test]
    fn points_within_a_pixel_collapse_to_the_first() {
        let points: Vec<GpuVertex> = (0..10).map(|i| v(i as f32 * 0.1, 0.0)).collect();
        let mut out = Vec::new();
        Simplifier::default().append_points(&top_view(0.35), &points, &mut out);
        let xs: Vec<f32> = out.iter().map(|p| p.pos[0]).collect();
        assert_eq!(xs.len(), 3, "{xs:?}");
        assert!(xs.windows(2).all(|w| w[1] - w[0] >= 0.35 - 1e-4), "{xs:?}");
        out.clear();
        Simplifier::default().append_points(&top_view(0.01), &points, &mut out);
        assert_eq!(out, points, "ten pixels apart: all kept");
    }

    #[test]
    fn a_fan_keeps_its_centre_and_a_rim_within_a_pixel() {
        let rim = arc(2.0, 90);
        let centre = v(0.0, 0.0);
        let fan: Vec<GpuVertex> = rim.windows(2).flat_map(|w| [centre, w[0], w[1]]).collect();
        let detail = top_view(0.02); // a 100-pixel radius
        let mut out = Vec::new();
        Simplifier::default().append_triangles(&detail, &fan, &mut out);
        let triangles = out.len() / 3;
        assert!((4..=30).contains(&triangles), "{triangles} triangles");
        assert!(out.chunks(3).all(|t| t[0] == centre));
        let drawn_rim: Vec<GpuVertex> = out.chunks(3).flat_map(|t| [t[1], t[2]]).collect();
        assert!(worst_deviation(&detail, &rim, &drawn_rim) < 1.0);
        assert_eq!(out[1], rim[0]);
        assert_eq!(out.last(), rim.last(), "the rim ends where it did");
    }

    #[test]
    fn quads_on_screen_keep_both_triangles() {
        let (a, b, c, d) = (v(0.0, 0.0), v(5.0, 0.0), v(5.0, 5.0), v(0.0, 5.0));
        let quad = vec![a, b, c, a, c, d];
        let mut out = Vec::new();
        Simplifier::default().append_triangles(&top_view(0.1), &quad, &mut out);
        assert_eq!(out, quad);
    }

    #[test]
    fn vertices_behind_the_eye_are_kept() {
        let proj = opengl::perspective(1.0, 1.0, 0.1, 100.0);
        let detail = ScreenDetail::new(proj, Vec2::splat(100.0), 2.0);
        // Looking down -z: these are behind the eye (z > 0), in a straight line, one
        // millimetre apart.
        let points: Vec<GpuVertex> = (0..5)
            .map(|i| GpuVertex {
                pos: [i as f32 * 0.001, 0.0, 1.0],
                color: [255; 4],
            })
            .collect();
        let mut out = Vec::new();
        Simplifier::default().append_points(&detail, &points, &mut out);
        assert_eq!(out, points);
        out.clear();
        Simplifier::default().append_lines(&detail, &chain(&points), &mut out);
        assert_eq!(out, chain(&points));
    }
}
