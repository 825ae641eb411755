//! Plane polygons for zones: is a point inside, and triangles that fill one (any simple
//! polygon, convex or not, either winding).

use glam::Vec2;

/// Whether `p` lies inside `polygon` (even-odd rule; a point on an edge may go either way).
pub fn contains(polygon: &[Vec2], p: Vec2) -> bool {
    let mut inside = false;
    let mut j = polygon.len().wrapping_sub(1);
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[j];
        if (a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x {
            inside = !inside;
        }
        j = i;
    }
    inside
}

/// Twice the signed area: positive when the corners run anticlockwise.
fn signed_area2(polygon: &[Vec2]) -> f32 {
    let mut sum = 0.0;
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        sum += a.perp_dot(b);
    }
    sum
}

/// The triangles (as corner indices) that fill a simple polygon, by ear clipping. A polygon
/// that crosses itself gets as many triangles as can be clipped; it never loops forever.
pub fn triangulate(polygon: &[Vec2]) -> Vec<[usize; 3]> {
    let mut left: Vec<usize> = (0..polygon.len()).collect();
    if signed_area2(polygon) < 0.0 {
        left.reverse();
    }
    let mut triangles = Vec::new();
    let mut misses = 0;
    let mut i = 0;
    while left.len() > 3 && misses < left.len() {
        let n = left.len();
        let (a, b, c) = (left[(i + n - 1) % n], left[i % n], left[(i + 1) % n]);
        if is_ear(polygon, &left, a, b, c) {
            triangles.push([a, b, c]);
            left.remove(i % n);
            misses = 0;
        } else {
            i += 1;
            misses += 1;
        }
    }
    if left.len() == 3 {
        triangles.push([left[0], left[1], left[2]]);
    }
    triangles
}

fn is_ear(polygon: &[Vec2], left: &[usize], a: usize, b: usize, c: usize) -> bool {
    let (pa, pb, pc) = (polygon[a], polygon[b], polygon[c]);
    if (pb - pa).perp_dot(pc - pb) <= 0.0 {
        return false; // a reflex (or flat) corner
    }
    !left
        .iter()
        .filter(|&&k| k != a && k != b && k != c)
        .any(|&k| contains(&[pa, pb, pc], polygon[k]))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(polygon: &[Vec2], triangles: &[[usize; 3]]) -> f32 {
        triangles
            .iter()
            .map(|t| (polygon[t[1]] - polygon[t[0]]).perp_dot(polygon[t[2]] - polygon[t[0]]) / 2.0)
            .sum()
    }

    #[test]
    fn an_l_shaped_room_is_filled_exactly_and_knows_its_inside() {
        // An L: 2 x 2 with the top-right 1 x 1 missing; clockwise, to test the winding.
        let l: Vec<Vec2> = [
            (0.0, 0.0),
            (0.0, 2.0),
            (1.0, 2.0),
            (1.0, 1.0),
            (2.0, 1.0),
            (2.0, 0.0),
        ]
        .iter()
        .map(|&(x, y)| Vec2::new(x, y))
        .collect();
        let triangles = triangulate(&l);
        assert_eq!(triangles.len(), 4);
        assert!(
            (area(&l, &triangles) - 3.0).abs() < 1e-5,
            "covers 3 m², no more"
        );
        assert!(contains(&l, Vec2::new(0.5, 1.5)));
        assert!(contains(&l, Vec2::new(1.5, 0.5)));
        assert!(
            !contains(&l, Vec2::new(1.5, 1.5)),
            "the missing corner is outside"
        );
        assert!(!contains(&l, Vec2::new(-0.1, 0.5)));
    }

    #[test]
    fn a_self_crossing_polygon_ends() {
        let bow: Vec<Vec2> = [(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0), (0.5, 2.0)]
            .iter()
            .map(|&(x, y)| Vec2::new(x, y))
            .collect();
        assert!(triangulate(&bow).len() <= 3);
    }
}
