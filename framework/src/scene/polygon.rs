//! Plane polygons (zones, block walls): is a point inside, triangles that fill one (any
//! simple polygon, convex or not, either winding), and a polygon stood up as a solid prism.

use glam::{Vec2, Vec3};

use super::{Geometry, MeshVertex, Rgba};

/// Why a wall's or zone's corners cannot be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum CornersError {
    #[error("corners must be numbers, x y x y …; found {0:?}")]
    NotNumbers(String),
    #[error("needs three corners or more as x y pairs; found {0} numbers")]
    TooFew(usize),
}

/// Reads corners written as `x y  x y  x y …` (spaces or commas): three or more.
pub fn parse_corners(text: &str) -> Result<Vec<Vec2>, CornersError> {
    let numbers: Vec<f32> = text
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<f32>().ok().filter(|v| v.is_finite()))
        .collect::<Option<_>>()
        .ok_or_else(|| CornersError::NotNumbers(text.trim().to_string()))?;
    if !numbers.len().is_multiple_of(2) || numbers.len() < 6 {
        return Err(CornersError::TooFew(numbers.len()));
    }
    Ok(numbers
        .chunks(2)
        .map(|xy| Vec2::new(xy[0], xy[1]))
        .collect())
}

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

/// A polygon on the ground extruded to `height`: lit side faces and a top cap, as solid walls
/// drawn with Stage `block`s are.
pub fn prism(polygon: &[Vec2], height: f32, color: Rgba, geometry: &mut Geometry) {
    if polygon.len() < 3 {
        return;
    }
    let anticlockwise = signed_area2(polygon) > 0.0;
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        let edge = b - a;
        let outward = if anticlockwise {
            Vec2::new(edge.y, -edge.x)
        } else {
            Vec2::new(-edge.y, edge.x)
        };
        let normal = outward.normalize_or_zero().extend(0.0);
        let corners = [
            a.extend(0.0),
            b.extend(0.0),
            b.extend(height),
            a.extend(height),
        ];
        for k in [0, 1, 2, 0, 2, 3] {
            geometry.mesh.push(MeshVertex {
                pos: corners[k],
                normal,
                color,
            });
        }
    }
    for [a, b, c] in triangulate(polygon) {
        for k in [a, b, c] {
            geometry.mesh.push(MeshVertex {
                pos: polygon[k].extend(height),
                normal: Vec3::Z,
                color,
            });
        }
    }
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
    fn a_prism_has_a_wall_per_edge_and_a_cap() {
        let square = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
        let mut g = Geometry::default();
        prism(&square, 0.8, Rgba::WHITE, &mut g);
        assert_eq!(
            g.mesh.len(),
            4 * 6 + 2 * 3,
            "four walls, a two-triangle cap"
        );
        // The wall along y = 0 faces south, away from the square, whatever the winding.
        let south = g.mesh[..6].iter().map(|v| v.normal).next().unwrap();
        assert!((south - Vec3::NEG_Y).length() < 1e-6, "{south}");
        let mut reversed = square;
        reversed.reverse();
        let mut h = Geometry::default();
        prism(&reversed, 0.8, Rgba::WHITE, &mut h);
        assert!(
            h.mesh[..24].iter().all(|v| {
                let mid = Vec2::new(0.5, 0.5);
                (v.pos.truncate() - mid).dot(v.normal.truncate()) > 0.0
            }),
            "outward for either winding"
        );
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
