//! Geometry a node carries: coloured line segments, points, triangles, text labels and
//! pictures, in the node's own frame. Plain data, no OpenGL: the viewer batches it for drawing.

use glam::Vec3;

use super::filtered_picture::FilteredPicture;
use super::image::ImageQuad;
use super::virtual_view::VirtualView;

/// An sRGB colour with alpha, 0–255 per channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Rgba(pub [u8; 4]);

impl Rgba {
    pub const WHITE: Rgba = Rgba([255, 255, 255, 255]);
    pub const BLACK: Rgba = Rgba([0, 0, 0, 255]);

    pub const fn rgb(r: u8, g: u8, b: u8) -> Rgba {
        Rgba([r, g, b, 255])
    }

    pub const fn with_alpha(self, a: u8) -> Rgba {
        Rgba([self.0[0], self.0[1], self.0[2], a])
    }
}

/// A vertex of a line, point or unlit triangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vertex {
    pub pos: Vec3,
    pub color: Rgba,
}

/// A vertex of a lit mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshVertex {
    pub pos: Vec3,
    pub normal: Vec3,
    pub color: Rgba,
}

/// Text drawn at a point, facing the viewer.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    pub pos: Vec3,
    pub text: String,
    pub color: Rgba,
}

/// A polygon seen from a point inside it — the free space a scan saw, a sonar's cone — as
/// its centre and rim, filled, outlined or both. Kept whole rather than as triangles and
/// segments: the viewer moves the rim to the world and simplifies it once for the fill and
/// the outline alike (a thousand robots' scans as 180 triangles and 182 segments each were a
/// third of the frame).
#[derive(Debug, Clone, PartialEq)]
pub struct Fan {
    pub centre: Vec3,
    /// The rim, in order: the fill is a triangle from the centre to each pair of neighbours.
    pub rim: Vec<Vec3>,
    /// The fill's colour, see-through when its alpha is below 255.
    pub fill: Option<Rgba>,
    /// The outline's colour: centre, along the rim, back to the centre.
    pub outline: Option<Rgba>,
}

impl Fan {
    /// The fill as triangles, three vertices each (none without a fill).
    pub fn fill_triangles(&self) -> impl Iterator<Item = [Vec3; 3]> + '_ {
        let rim = if self.fill.is_some() {
            &self.rim[..]
        } else {
            &[]
        };
        rim.windows(2).map(|pair| [self.centre, pair[0], pair[1]])
    }

    /// The outline as segments (none without an outline).
    pub fn outline_segments(&self) -> impl Iterator<Item = [Vec3; 2]> + '_ {
        let rim = if self.outline.is_some() {
            &self.rim[..]
        } else {
            &[]
        };
        let around = rim.first().map(|&first| [self.centre, first]);
        let back = rim.last().map(|&last| [last, self.centre]);
        around
            .into_iter()
            .chain(rim.windows(2).map(|pair| [pair[0], pair[1]]))
            .chain(back)
    }
}

/// Everything one node draws. Each list is cleared and refilled when its data changes.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Geometry {
    /// Pairs of vertices, one segment per pair.
    pub lines: Vec<Vertex>,
    pub points: Vec<Vertex>,
    /// Unlit triangles (the ground, arrows), three vertices each.
    pub triangles: Vec<Vertex>,
    /// Filled and outlined polygons around a centre (free space, cones).
    pub fans: Vec<Fan>,
    /// Lit triangles (robot bodies, OBJ skins), three vertices each.
    pub mesh: Vec<MeshVertex>,
    pub labels: Vec<Label>,
    /// Pictures lying in the node's x–y plane (maps, floor bitmaps), each its own texture.
    pub images: Vec<ImageQuad>,
    /// Cameras the viewer renders the scene through, off screen (see [`VirtualView`]).
    pub views: Vec<VirtualView>,
    /// Pictures to be filtered and handed back, not drawn (see [`FilteredPicture`]).
    pub filtered: Vec<FilteredPicture>,
}

impl Geometry {
    pub fn clear(&mut self) {
        self.lines.clear();
        self.points.clear();
        self.triangles.clear();
        self.fans.clear();
        self.mesh.clear();
        self.labels.clear();
        self.images.clear();
        self.views.clear();
        self.filtered.clear();
    }

    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
            && self.points.is_empty()
            && self.triangles.is_empty()
            && self.fans.is_empty()
            && self.mesh.is_empty()
            && self.labels.is_empty()
            && self.images.is_empty()
            && self.views.is_empty()
            && self.filtered.is_empty()
    }

    pub fn line(&mut self, a: Vec3, b: Vec3, color: Rgba) {
        self.lines.push(Vertex { pos: a, color });
        self.lines.push(Vertex { pos: b, color });
    }

    pub fn point(&mut self, pos: Vec3, color: Rgba) {
        self.points.push(Vertex { pos, color });
    }

    pub fn triangle(&mut self, a: Vec3, b: Vec3, c: Vec3, color: Rgba) {
        for pos in [a, b, c] {
            self.triangles.push(Vertex { pos, color });
        }
    }

    /// A closed polyline through `points`.
    pub fn polygon_outline(&mut self, points: &[Vec3], color: Rgba) {
        for (i, &a) in points.iter().enumerate() {
            self.line(a, points[(i + 1) % points.len()], color);
        }
    }

    /// A filled fan from `centre` through `rim` (a sector, a polygon seen from inside).
    pub fn fan(&mut self, centre: Vec3, rim: Vec<Vec3>, color: Rgba) {
        self.outlined_fan(centre, rim, Some(color), None);
    }

    /// A fan from `centre` through `rim`, filled, outlined (centre, rim, back), or both.
    pub fn outlined_fan(
        &mut self,
        centre: Vec3,
        rim: Vec<Vec3>,
        fill: Option<Rgba>,
        outline: Option<Rgba>,
    ) {
        if rim.is_empty() || (fill.is_none() && outline.is_none()) {
            return;
        }
        self.fans.push(Fan {
            centre,
            rim,
            fill,
            outline,
        });
    }

    /// A lit box centred on `centre` with the given full sizes.
    pub fn cuboid(&mut self, centre: Vec3, size: Vec3, color: Rgba) {
        let h = size / 2.0;
        let faces: [(Vec3, Vec3, Vec3); 6] = [
            (Vec3::X, Vec3::Y, Vec3::Z),
            (Vec3::NEG_X, Vec3::NEG_Y, Vec3::Z),
            (Vec3::Y, Vec3::NEG_X, Vec3::Z),
            (Vec3::NEG_Y, Vec3::X, Vec3::Z),
            (Vec3::Z, Vec3::X, Vec3::Y),
            (Vec3::NEG_Z, Vec3::NEG_X, Vec3::Y),
        ];
        for (normal, u, v) in faces {
            let c = centre + normal * h;
            let (du, dv) = (u * h, v * h);
            let corners = [c - du - dv, c + du - dv, c + du + dv, c - du + dv];
            for i in [0, 1, 2, 0, 2, 3] {
                self.mesh.push(MeshVertex {
                    pos: corners[i],
                    normal,
                    color,
                });
            }
        }
    }

    pub fn label(&mut self, pos: Vec3, text: impl Into<String>, color: Rgba) {
        self.labels.push(Label {
            pos,
            text: text.into(),
            color,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fan_is_its_triangles_and_its_closed_outline() {
        let mut g = Geometry::default();
        let rim = vec![Vec3::X, Vec3::Y, Vec3::NEG_X];
        g.outlined_fan(Vec3::ZERO, rim, Some(Rgba::WHITE), Some(Rgba::BLACK));
        let fan = &g.fans[0];
        let triangles: Vec<_> = fan.fill_triangles().collect();
        assert_eq!(
            triangles,
            [
                [Vec3::ZERO, Vec3::X, Vec3::Y],
                [Vec3::ZERO, Vec3::Y, Vec3::NEG_X]
            ]
        );
        let segments: Vec<_> = fan.outline_segments().collect();
        assert_eq!(segments.len(), 4, "centre to rim, two along it, back");
        assert_eq!(segments[0], [Vec3::ZERO, Vec3::X]);
        assert_eq!(segments[3], [Vec3::NEG_X, Vec3::ZERO]);

        g.fan(Vec3::ZERO, vec![Vec3::X, Vec3::Y], Rgba::WHITE);
        assert_eq!(g.fans[1].outline_segments().count(), 0, "filled only");
        g.outlined_fan(Vec3::ZERO, Vec::new(), Some(Rgba::WHITE), None);
        g.outlined_fan(Vec3::ZERO, vec![Vec3::X], None, None);
        assert_eq!(g.fans.len(), 2, "nothing to draw is not kept");
    }

    #[test]
    fn a_cuboid_has_outward_normals_and_twelve_triangles() {
        let mut g = Geometry::default();
        g.cuboid(
            Vec3::new(1.0, 0.0, 0.5),
            Vec3::new(2.0, 1.0, 1.0),
            Rgba::WHITE,
        );
        assert_eq!(g.mesh.len(), 36);
        for v in &g.mesh {
            let from_centre = v.pos - Vec3::new(1.0, 0.0, 0.5);
            assert!(from_centre.dot(v.normal) > 0.0, "{v:?}");
        }
    }
}
