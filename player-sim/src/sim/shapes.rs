//! Footprints drawn with Stage blocks: rays and overlaps against the polygons themselves, so
//! that a triangular crate or a pointed robot is hit where it is, not across its whole box.
//! The box of the model's size (the polygons' bounding box) stays the cheap first test.

use crate::world::Polygon;

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn edges(polygon: &[[f64; 2]]) -> impl Iterator<Item = ([f64; 2], [f64; 2])> + '_ {
    (0..polygon.len()).map(move |i| (polygon[i], polygon[(i + 1) % polygon.len()]))
}

/// Is `(x, y)` inside any of the polygons (even-odd rule within each)?
pub(crate) fn polygons_contain(shape: &[Polygon], x: f64, y: f64) -> bool {
    shape.iter().any(|polygon| {
        edges(polygon)
            .filter(|(a, b)| {
                (a[1] <= y) != (b[1] <= y) && x < a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
            })
            .count()
            % 2
            == 1
    })
}

/// Where the ray from `(ox, oy)` along the unit `(dx, dy)` first meets the polygons: 0 when it
/// starts inside one, `None` when it misses them all.
pub(crate) fn ray_into_polygons(
    shape: &[Polygon],
    ox: f64,
    oy: f64,
    dx: f64,
    dy: f64,
) -> Option<f64> {
    if polygons_contain(shape, ox, oy) {
        return Some(0.0);
    }
    let d = [dx, dy];
    shape
        .iter()
        .flat_map(|polygon| edges(polygon))
        .filter_map(|(p, q)| {
            let e = [q[0] - p[0], q[1] - p[1]];
            let denominator = cross(d, e);
            if denominator.abs() < 1e-15 {
                return None;
            }
            let w = [p[0] - ox, p[1] - oy];
            let t = cross(w, e) / denominator;
            let s = cross(w, d) / denominator;
            (t >= 0.0 && (0.0..=1.0).contains(&s)).then_some(t)
        })
        .min_by(f64::total_cmp)
}

/// Do the segments touch or cross?
fn segments_meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let side = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        cross([q[0] - p[0], q[1] - p[1]], [r[0] - p[0], r[1] - p[1]])
    };
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    let within = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    ((d1 > 0.0) != (d2 > 0.0)
        && (d3 > 0.0) != (d4 > 0.0)
        && d1 != 0.0
        && d2 != 0.0
        && d3 != 0.0
        && d4 != 0.0)
        || (d1 == 0.0 && within(c, d, a))
        || (d2 == 0.0 && within(c, d, b))
        || (d3 == 0.0 && within(a, b, c))
        || (d4 == 0.0 && within(a, b, d))
}

/// Do two sets of polygons (in one frame) overlap: an edge of one crossing an edge of the
/// other, or one lying wholly inside the other?
pub(crate) fn outlines_overlap(a: &[Polygon], b: &[Polygon]) -> bool {
    let inside = |outer: &[Polygon], inner: &[Polygon]| {
        inner
            .iter()
            .filter_map(|p| p.first())
            .any(|&[x, y]| polygons_contain(outer, x, y))
    };
    inside(a, b)
        || inside(b, a)
        || a.iter().flat_map(|p| edges(p)).any(|(p, q)| {
            b.iter()
                .flat_map(|p| edges(p))
                .any(|(r, s)| segments_meet(p, q, r, s))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn triangle() -> Vec<Polygon> {
        vec![vec![[-1.0, -1.0], [1.0, -1.0], [-1.0, 1.0]]]
    }

    #[test]
    fn rays_meet_the_polygon_not_its_box() {
        let t = triangle();
        // Along y = 0.5 from the east: the box's face is at x = 1, the slope at x = -0.5.
        let hit = ray_into_polygons(&t, 3.0, 0.5, -1.0, 0.0).unwrap();
        assert!((hit - 3.5).abs() < 1e-12, "{hit}");
        assert_eq!(ray_into_polygons(&t, 3.0, 0.5, 1.0, 0.0), None);
        assert_eq!(ray_into_polygons(&t, -0.5, -0.5, 1.0, 0.0), Some(0.0));
        // Through the empty half of the box, parallel to the slope: a miss.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert_eq!(ray_into_polygons(&t, 1.5, -0.2, -s, s), None);
    }

    #[test]
    fn overlaps_by_crossing_edges_or_containment() {
        let t = triangle();
        let square = |x: f64, y: f64, h: f64| {
            vec![vec![
                [x - h, y - h],
                [x + h, y - h],
                [x + h, y + h],
                [x - h, y + h],
            ]]
        };
        assert!(outlines_overlap(&t, &square(0.0, -0.5, 0.2)), "crossing");
        assert!(outlines_overlap(&t, &square(-0.6, -0.6, 0.1)), "inside");
        assert!(outlines_overlap(&square(0.0, 0.0, 5.0), &t), "around");
        assert!(
            !outlines_overlap(&t, &square(0.7, 0.7, 0.2)),
            "the empty corner"
        );
    }
}
