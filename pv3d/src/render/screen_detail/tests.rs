//! The simplification keeps what a pixel can show and nothing strays more than the tolerance.

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
fn worst_deviation(detail: &ScreenDetail, original: &[GpuVertex], segments: &[GpuVertex]) -> f32 {
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

proptest::proptest! {
    /// Whatever a plugin draws and however far the camera is: every vertex of a chain, a
    /// fan's rim or a point list is within the tolerance of what is drawn instead.
    #[test]
    fn nothing_strays_more_than_the_tolerance(
        xy in proptest::collection::vec((-50.0f32..50.0, -50.0f32..50.0), 2..120),
        metres_per_pixel in 0.001f32..2.0,
    ) {
        let detail = top_view(metres_per_pixel);
        let points: Vec<GpuVertex> = xy.iter().map(|&(x, y)| v(x, y)).collect();

        let mut lines = Vec::new();
        Simplifier::default().append_lines(&detail, &chain(&points), &mut lines);
        proptest::prop_assert!(worst_deviation(&detail, &points, &lines) <= 1.0 + 1e-3);
        proptest::prop_assert_eq!(lines.first(), points.first());
        proptest::prop_assert_eq!(lines.last(), points.last());

        let centre = v(0.0, 0.0);
        let fan: Vec<GpuVertex> =
            points.windows(2).flat_map(|w| [centre, w[0], w[1]]).collect();
        let mut triangles = Vec::new();
        Simplifier::default().append_triangles(&detail, &fan, &mut triangles);
        let rim: Vec<GpuVertex> = triangles.chunks(3).flat_map(|t| [t[1], t[2]]).collect();
        proptest::prop_assert!(worst_deviation(&detail, &points, &rim) <= 1.0 + 1e-3);

        let mut kept = Vec::new();
        Simplifier::default().append_points(&detail, &points, &mut kept);
        let px = |g: &GpuVertex| detail.screen(g.pos);
        for p in &points {
            let nearest = kept
                .iter()
                .map(|k| px(k).distance(px(p)))
                .fold(f32::INFINITY, f32::min);
            proptest::prop_assert!(nearest < detail.point_spacing_px + 1e-3);
        }
    }
}
