//! A [`Fan`] flattened for drawing: its rim moved to the world and, for a screen, simplified
//! once — the fill's triangles and the outline's segments then share the rim's kept
//! vertices. (Expanded first into 180 triangles and 182 segments, a scan's rim was moved and
//! simplified twice, and a thousand of them were a third of the viewer's frame.)

use framework::scene::{Fan, Rgba};
use glam::Affine3A;

use super::super::gpu_vertex::GpuVertex;
use super::{ScreenDetail, Simplifier};

/// Where a fan's pieces go.
pub struct FanOut<'a> {
    /// Opaque fills.
    pub triangles: &'a mut Vec<GpuVertex>,
    /// Fills with some transparency.
    pub translucent: &'a mut Vec<GpuVertex>,
    /// Outlines, two vertices a segment.
    pub lines: &'a mut Vec<GpuVertex>,
    /// Adds how many times over the translucent fills cover the view (their area on screen
    /// over the view's; known only with a screen).
    pub translucent_cover: &'a mut f32,
}

impl Simplifier {
    /// Appends `fan`, placed in the world by `to_world`: with `detail` its rim keeps only the
    /// vertices a pixel can show (as a fan's rim always has), without it every vertex.
    pub fn append_fan(
        &mut self,
        detail: Option<&ScreenDetail>,
        fan: &Fan,
        to_world: &Affine3A,
        out: FanOut<'_>,
    ) {
        let vertex = |pos: [f32; 3], color: Rgba| GpuVertex {
            pos,
            color: color.0,
        };
        let centre = to_world.transform_point3(fan.centre).to_array();
        self.chain.clear();
        self.chain.extend(fan.rim.iter().map(|&p| GpuVertex {
            pos: to_world.transform_point3(p).to_array(),
            color: [0; 4],
        }));
        match detail {
            Some(detail) => self.simplify_chain(detail),
            None => {
                self.keep.clear();
                self.keep.resize(self.chain.len(), true);
            }
        }
        let kept = || {
            self.chain
                .iter()
                .zip(&self.keep)
                .filter(|(_, keep)| **keep)
                .map(|(v, _)| v.pos)
        };
        if let Some(fill) = fan.fill {
            let opaque = fill.0[3] == u8::MAX;
            if let Some(detail) = detail.filter(|_| !opaque) {
                *out.translucent_cover += self.kept_area_px(detail, centre) / detail.area_px();
            }
            let to = if opaque {
                &mut *out.triangles
            } else {
                &mut *out.translucent
            };
            let mut previous = None;
            for p in kept() {
                if let Some(a) = previous {
                    to.extend([vertex(centre, fill), vertex(a, fill), vertex(p, fill)]);
                }
                previous = Some(p);
            }
        }
        if let Some(outline) = fan.outline {
            let mut previous = centre;
            for p in kept() {
                out.lines
                    .extend([vertex(previous, outline), vertex(p, outline)]);
                previous = p;
            }
            if !self.chain.is_empty() {
                out.lines
                    .extend([vertex(previous, outline), vertex(centre, outline)]);
            }
        }
    }
}

impl Simplifier {
    /// The area on screen of the fan from `centre` through the kept rim vertices, pixels²
    /// (vertices without a screen position add nothing).
    fn kept_area_px(&self, detail: &ScreenDetail, centre: [f32; 3]) -> f32 {
        let centre = detail.screen(centre);
        let mut kept = (self.at.iter().zip(&self.keep))
            .filter(|(_, keep)| **keep)
            .map(|(at, _)| *at - centre);
        let Some(mut previous) = kept.next() else {
            return 0.0;
        };
        let mut twice_area = 0.0;
        for p in kept {
            let cross = previous.perp_dot(p).abs();
            if cross.is_finite() {
                twice_area += cross;
            }
            previous = p;
        }
        twice_area / 2.0
    }
}

#[cfg(test)]
mod tests {
    use framework::scene::{Fan, Rgba};
    use glam::camera::rh::proj::opengl;
    use glam::{Affine3A, Vec2, Vec3};

    use super::*;

    fn buffers() -> [Vec<GpuVertex>; 3] {
        [Vec::new(), Vec::new(), Vec::new()]
    }

    fn arc(points: usize, radius: f32) -> Vec<Vec3> {
        (0..points)
            .map(|i| {
                let a = std::f32::consts::PI * i as f32 / (points - 1) as f32;
                (Vec2::from_angle(a) * radius).extend(0.0)
            })
            .collect()
    }

    #[test]
    fn every_vertex_without_a_screen_as_the_fan_says() {
        let fan = Fan {
            centre: Vec3::ZERO,
            rim: arc(5, 1.0),
            fill: Some(Rgba::WHITE.with_alpha(60)),
            outline: Some(Rgba::WHITE),
        };
        let [mut triangles, mut translucent, mut lines] = buffers();
        let mut cover = 0.0;
        let moved = Affine3A::from_translation(Vec3::X);
        Simplifier::default().append_fan(
            None,
            &fan,
            &moved,
            FanOut {
                triangles: &mut triangles,
                translucent: &mut translucent,
                lines: &mut lines,
                translucent_cover: &mut cover,
            },
        );
        assert!(triangles.is_empty(), "a see-through fill is translucent");
        let expected: Vec<[f32; 3]> = (fan.fill_triangles().flatten())
            .map(|p| (p + Vec3::X).to_array())
            .collect();
        let drawn: Vec<[f32; 3]> = translucent.iter().map(|v| v.pos).collect();
        assert_eq!(drawn, expected);
        let expected: Vec<[f32; 3]> = (fan.outline_segments().flatten())
            .map(|p| (p + Vec3::X).to_array())
            .collect();
        let drawn: Vec<[f32; 3]> = lines.iter().map(|v| v.pos).collect();
        assert_eq!(drawn, expected);
    }

    #[test]
    fn a_far_fan_shares_one_simplified_rim_between_fill_and_outline() {
        // A 181-point half circle of 1 m seen from far away: a few pixels across.
        let fan = Fan {
            centre: Vec3::ZERO,
            rim: arc(181, 1.0),
            fill: Some(Rgba::WHITE),
            outline: Some(Rgba::BLACK),
        };
        let view_proj = opengl::orthographic(-100.0, 100.0, -100.0, 100.0, -10.0, 10.0);
        let detail = ScreenDetail::new(view_proj, Vec2::new(400.0, 400.0), 3.0);
        let [mut triangles, mut translucent, mut lines] = buffers();
        let mut cover = 0.0;
        Simplifier::default().append_fan(
            Some(&detail),
            &fan,
            &Affine3A::IDENTITY,
            FanOut {
                triangles: &mut triangles,
                translucent: &mut translucent,
                lines: &mut lines,
                translucent_cover: &mut cover,
            },
        );
        let fills = triangles.len() / 3;
        assert!((1..20).contains(&fills), "{fills} triangles");
        assert!(translucent.is_empty(), "an opaque fill is opaque");
        assert_eq!(lines.len() / 2, fills + 2, "the same rim, closed");
        // The rim's ends are kept: the outline starts and ends where the scan does.
        assert_eq!(lines[1].pos, fan.rim[0].to_array());
        assert_eq!(lines[lines.len() - 2].pos, fan.rim[180].to_array());
    }
}
