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

/// Everything one node draws. Each list is cleared and refilled when its data changes.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Geometry {
    /// Pairs of vertices, one segment per pair.
    pub lines: Vec<Vertex>,
    pub points: Vec<Vertex>,
    /// Unlit triangles (filled free-space polygons, ground), three vertices each.
    pub triangles: Vec<Vertex>,
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

    /// A triangle fan from `centre` through `rim` (a filled sector or polygon).
    pub fn fan(&mut self, centre: Vec3, rim: &[Vec3], color: Rgba) {
        for pair in rim.windows(2) {
            self.triangle(centre, pair[0], pair[1], color);
        }
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
