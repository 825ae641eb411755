//! Turning the scene into a few big vertex arrays in world space, so the whole scene draws in
//! four GL calls however many robots there are. Buffers are reused from frame to frame.

use framework::scene::{
    Facing, FilterChain, FilteredPicture, ImageQuad, Label, Pixels, Sampling, Scene, Vertex,
    VirtualView,
};
use glam::Affine3A;

pub use super::gpu_vertex::{GpuMeshVertex, GpuVertex};
use super::screen_detail::{FanOut, ScreenDetail, Simplifier};

/// A picture placed in world space: its corners (counter-clockwise from row 0, column 0)
/// with their texture coordinates. The pixels are shared with the scene, not copied.
///
/// A billboard's four corners all sit on its anchor, and `offsets` say how far along the
/// viewer's right and up each one goes: which way that is, only the camera drawing knows, so
/// the shader turns it (see [`super::billboard`]) and the batch needs no rebuild when the
/// camera moves. A fixed picture's offsets are zero.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchedImage {
    pub pixels: Pixels,
    pub corners: [([f32; 3], [f32; 2]); 4],
    pub offsets: [[f32; 2]; 4],
    pub sampling: Sampling,
    pub filters: FilterChain,
}

impl BatchedImage {
    fn placed(quad: &ImageQuad, to_world: &Affine3A) -> BatchedImage {
        let (corners, offsets) = match quad.facing {
            Facing::Fixed => (
                quad.corners()
                    .map(|(p, uv)| (to_world.transform_point3(p).to_array(), uv.to_array())),
                [[0.0; 2]; 4],
            ),
            Facing::Viewer { .. } => {
                let anchor = to_world.transform_point3(quad.corner).to_array();
                let around = quad.billboard_offsets();
                (
                    around.map(|(_, uv)| (anchor, uv.to_array())),
                    around.map(|(offset, _)| offset.to_array()),
                )
            }
        };
        BatchedImage {
            pixels: quad.pixels.clone(),
            corners,
            offsets,
            sampling: quad.sampling,
            filters: quad.filters.clone(),
        }
    }
}

/// A virtual camera with its pose in the world, ready to be rendered through.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchedView {
    pub view: VirtualView,
    pub camera_to_world: Affine3A,
}

/// The scene flattened for drawing.
#[derive(Debug, Default)]
pub struct SceneBatch {
    pub lines: Vec<GpuVertex>,
    pub points: Vec<GpuVertex>,
    /// Opaque fills (the ground, walls): drawn first, writing depth.
    pub triangles: Vec<GpuVertex>,
    /// Translucent fills (laser free space, sonar cones): drawn after every opaque thing,
    /// without writing depth, so an opaque fill drawn later cannot hide them.
    pub translucent: Vec<GpuVertex>,
    pub mesh: Vec<GpuMeshVertex>,
    /// Labels with world-space positions, drawn as text over the 3D view.
    pub labels: Vec<Label>,
    /// Pictures, each drawn with its own texture.
    pub images: Vec<BatchedImage>,
    /// Virtual cameras, each rendered off screen before the view.
    pub views: Vec<BatchedView>,
    /// Pictures to filter and hand back, not to draw.
    pub filtered: Vec<FilteredPicture>,
    /// How many times over the translucent fills cover the view (0 when built without a
    /// screen): the renderer draws them at half resolution when they pile up.
    pub translucent_cover: f32,
    /// One object's vertices in world space, before simplification.
    scratch: Vec<GpuVertex>,
    simplifier: Simplifier,
}

impl SceneBatch {
    /// Refills the arrays from `scene`, keeping their capacity; with `detail`, lines, points
    /// and fans finer than a pixel are merged (see [`ScreenDetail`]), without, every vertex
    /// is kept.
    pub fn rebuild(&mut self, scene: &Scene, detail: Option<&ScreenDetail>) {
        self.lines.clear();
        self.points.clear();
        self.triangles.clear();
        self.translucent.clear();
        self.mesh.clear();
        self.labels.clear();
        self.images.clear();
        self.views.clear();
        self.filtered.clear();
        self.translucent_cover = 0.0;
        for (id, object) in scene.iter() {
            let g = &object.geometry;
            if g.is_empty() || !scene.is_shown(id) {
                continue;
            }
            let to_world = scene.world_transform(id);
            let (scratch, simplifier) = (&mut self.scratch, &mut self.simplifier);
            to_world_space(scratch, &g.lines, &to_world);
            match detail {
                Some(detail) => simplifier.append_lines(detail, scratch, &mut self.lines),
                None => self.lines.extend_from_slice(scratch),
            }
            to_world_space(scratch, &g.points, &to_world);
            match detail {
                Some(detail) => simplifier.append_points(detail, scratch, &mut self.points),
                None => self.points.extend_from_slice(scratch),
            }
            let start = self.triangles.len();
            to_world_space(scratch, &g.triangles, &to_world);
            match detail {
                Some(detail) => simplifier.append_triangles(detail, scratch, &mut self.triangles),
                None => self.triangles.extend_from_slice(scratch),
            }
            move_translucent(&mut self.triangles, start, &mut self.translucent);
            for fan in &g.fans {
                let out = FanOut {
                    triangles: &mut self.triangles,
                    translucent: &mut self.translucent,
                    lines: &mut self.lines,
                    translucent_cover: &mut self.translucent_cover,
                };
                simplifier.append_fan(detail, fan, &to_world, out);
            }
            self.mesh.extend(g.mesh.iter().map(|v| {
                GpuMeshVertex {
                    pos: to_world.transform_point3(v.pos).to_array(),
                    normal: to_world
                        .transform_vector3(v.normal)
                        .normalize_or_zero()
                        .to_array(),
                    color: v.color.0,
                }
            }));
            self.labels.extend(g.labels.iter().map(|l| Label {
                pos: to_world.transform_point3(l.pos),
                ..l.clone()
            }));
            self.images
                .extend(g.images.iter().map(|i| BatchedImage::placed(i, &to_world)));
            self.views.extend(g.views.iter().map(|v| BatchedView {
                view: v.clone(),
                camera_to_world: to_world * v.pose,
            }));
            self.filtered.extend(g.filtered.iter().cloned());
        }
    }

    /// Line segments in the batch.
    pub fn segment_count(&self) -> usize {
        self.lines.len() / 2
    }
}

/// Moves the triangles from `from` on whose vertices are not all opaque to `translucent`,
/// keeping both in order.
fn move_translucent(triangles: &mut Vec<GpuVertex>, from: usize, translucent: &mut Vec<GpuVertex>) {
    let mut kept = from;
    for t in (from..triangles.len()).step_by(3) {
        let Some(triangle) = triangles.get(t..t + 3) else {
            break; // an incomplete last triangle draws nothing either way
        };
        let triangle: [GpuVertex; 3] = [triangle[0], triangle[1], triangle[2]];
        if triangle.iter().all(|v| v.color[3] == u8::MAX) {
            triangles[kept..kept + 3].copy_from_slice(&triangle);
            kept += 3;
        } else {
            translucent.extend_from_slice(&triangle);
        }
    }
    triangles.truncate(kept);
}

/// Replaces `out`'s contents with `vertices` moved to world space.
fn to_world_space(out: &mut Vec<GpuVertex>, vertices: &[Vertex], to_world: &Affine3A) {
    out.clear();
    if *to_world == Affine3A::IDENTITY {
        out.extend(vertices.iter().map(|v| GpuVertex {
            pos: v.pos.to_array(),
            color: v.color.0,
        }));
    } else {
        out.extend(vertices.iter().map(|v| GpuVertex {
            pos: to_world.transform_point3(v.pos).to_array(),
            color: v.color.0,
        }));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use framework::scene::{Object3D, Rgba};
    use glam::Vec3;

    #[test]
    fn geometry_lands_in_world_space() {
        let mut scene = Scene::new();
        let mut robot = Object3D::new("robot");
        robot.transform = Affine3A::from_translation(Vec3::new(1.0, 2.0, 0.0));
        robot.geometry.line(Vec3::ZERO, Vec3::X, Rgba::WHITE);
        let robot = scene.add(robot);
        let mut hidden = Object3D::new("hidden");
        hidden.parent = Some(robot);
        hidden.visible = false;
        hidden.geometry.point(Vec3::ZERO, Rgba::WHITE);
        scene.add(hidden);

        let mut batch = SceneBatch::default();
        batch.rebuild(&scene, None);
        assert_eq!(batch.segment_count(), 1);
        assert_eq!(batch.lines[1].pos, [2.0, 2.0, 0.0]);
        assert!(batch.points.is_empty(), "hidden objects are not drawn");
    }

    #[test]
    fn translucent_fills_are_drawn_apart_from_opaque_ones() {
        let mut scene = Scene::new();
        let mut cspace = Object3D::new("laser free space");
        let glass = Rgba::rgb(255, 0, 0).with_alpha(60);
        cspace
            .geometry
            .triangle(Vec3::ZERO, Vec3::X, Vec3::Y, glass);
        cspace
            .geometry
            .triangle(Vec3::ZERO, Vec3::X, Vec3::NEG_Y, Rgba::WHITE);
        scene.add(cspace);
        let mut ground = Object3D::new("ground");
        ground
            .geometry
            .triangle(Vec3::ZERO, Vec3::X, Vec3::Y, Rgba::WHITE);
        scene.add(ground);

        let mut batch = SceneBatch::default();
        batch.rebuild(&scene, None);
        assert_eq!(batch.triangles.len(), 6, "two opaque triangles");
        assert_eq!(batch.translucent.len(), 3, "one translucent triangle");
        assert!(batch.translucent.iter().all(|v| v.color[3] == 60));
        assert_eq!(
            batch.triangles[2].pos,
            [0.0, -1.0, 0.0],
            "opaque kept in order"
        );
        assert_eq!(
            batch.triangles[5].pos,
            [0.0, 1.0, 0.0],
            "the ground after it"
        );
    }
}
