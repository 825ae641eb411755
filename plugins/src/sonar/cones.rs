//! Range cones: one filled sector and its outline per transducer, opening from the
//! transducer's pose along its heading, as long as its reading. Shared by the sonar plugin and
//! the sonar-like rangers (a Stage sonar ring served as `ranger`).

use std::f32::consts::TAU;

use glam::{Vec2, Vec3};
use player_proto::interfaces::common::Pose3d;

use framework::scene::{Geometry, Rgba};

/// Segments of each cone's arc: smooth enough at sonar widths, cheap for a ring of 24.
pub const ARC_SEGMENTS: usize = 8;

/// Drawn length of a reading that is not a number we can draw (NaN, infinite, negative).
const NO_READING: f32 = 0.0;

/// How to draw the cones.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConeStyle {
    /// Fill the sector.
    pub fill: bool,
    /// Outline the sector.
    pub outline: bool,
    pub color: Rgba,
    /// Opacity of the fill, 0–255 (the outline is drawn more opaque).
    pub fill_alpha: u8,
    /// Full opening angle of a cone, rad.
    pub width: f32,
    /// Readings are drawn no longer than this, m (keeps a wild value from filling the view).
    pub max_length: f32,
    /// Readings at or beyond this range are "no echo": drawn as a faint outline only, so that
    /// the cones that did hit something stand out. `f32::INFINITY` when the device does not say.
    pub no_return: f32,
}

impl Default for ConeStyle {
    fn default() -> Self {
        ConeStyle {
            fill: true,
            outline: true,
            color: Rgba::rgb(80, 200, 160),
            fill_alpha: 70,
            width: 15f32.to_radians(),
            max_length: 20.0,
            no_return: f32::INFINITY,
        }
    }
}

/// Where one transducer sits in the drawing's frame, and which way it looks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transducer {
    pub origin: Vec3,
    /// Heading, rad, counter-clockwise from +x.
    pub yaw: f32,
}

impl From<&Pose3d> for Transducer {
    /// Player's 3D pose reduced to what a planar cone needs (roll and pitch are ignored).
    fn from(pose: &Pose3d) -> Transducer {
        Transducer {
            origin: Vec3::new(pose.px as f32, pose.py as f32, pose.pz as f32),
            yaw: pose.pyaw as f32,
        }
    }
}

/// `count` transducers evenly spaced on a ring of `radius`, looking outwards: where a device's
/// transducers are assumed to be while (or if) it does not say.
pub fn evenly_spaced(count: usize, radius: f32) -> Vec<Transducer> {
    (0..count)
        .map(|i| {
            let yaw = i as f32 * TAU / count as f32;
            Transducer {
                origin: Vec3::new(radius * yaw.cos(), radius * yaw.sin(), 0.0),
                yaw,
            }
        })
        .collect()
}

/// Fills `geometry` (cleared first) with one cone per transducer that has a reading. Readings
/// beyond the last transducer (or transducers without a reading) are not drawn.
pub fn cone_geometry(
    transducers: &[Transducer],
    ranges: &[f32],
    style: &ConeStyle,
    geometry: &mut Geometry,
) {
    geometry.clear();
    let half = style.width.clamp(0.0, TAU) / 2.0;
    for (t, &range) in transducers.iter().zip(ranges) {
        let length = if range.is_finite() && range > 0.0 {
            range.min(style.max_length)
        } else {
            NO_READING
        };
        if length <= 0.0 {
            continue;
        }
        let rim: Vec<Vec3> = (0..=ARC_SEGMENTS)
            .map(|k| {
                let a = t.yaw - half + 2.0 * half * k as f32 / ARC_SEGMENTS as f32;
                t.origin + (Vec2::from_angle(a) * length).extend(0.0)
            })
            .collect();
        let echo = range < style.no_return;
        let fill = (style.fill && echo).then(|| style.color.with_alpha(style.fill_alpha));
        let outline = (style.outline || !echo).then(|| {
            let alpha = if echo {
                style.fill_alpha.saturating_mul(2).max(160)
            } else {
                style.fill_alpha / 2
            };
            style.color.with_alpha(alpha)
        });
        geometry.outlined_fan(t.origin, rim, fill, outline);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An outline's segment and its colour.
    type Segment = ([Vec3; 2], Rgba);

    /// The fills' triangles and the outlines' segments of every cone.
    fn drawn(g: &Geometry) -> (Vec<[Vec3; 3]>, Vec<Segment>) {
        let triangles = g.fans.iter().flat_map(|f| f.fill_triangles()).collect();
        let segments = (g.fans.iter())
            .flat_map(|f| f.outline_segments().map(|s| (s, f.outline.unwrap())))
            .collect();
        (triangles, segments)
    }

    #[test]
    fn a_cone_opens_along_the_heading_and_is_as_long_as_the_reading() {
        let t = Transducer {
            origin: Vec3::new(0.2, 0.0, 0.1),
            yaw: std::f32::consts::FRAC_PI_2,
        };
        let mut g = Geometry::default();
        cone_geometry(&[t], &[2.0], &ConeStyle::default(), &mut g);
        let (triangles, segments) = drawn(&g);
        assert_eq!(triangles.len(), ARC_SEGMENTS);
        assert_eq!(segments.len(), ARC_SEGMENTS + 2, "origin, rim, closed");
        // The middle of the arc is 2 m along +y from the transducer.
        let middle = triangles[ARC_SEGMENTS / 2][1];
        assert!(
            (middle - Vec3::new(0.2, 2.0, 0.1)).length() < 1e-5,
            "{middle}"
        );
        for p in triangles.iter().flatten() {
            assert!((*p - t.origin).length() <= 2.0 + 1e-5);
        }
    }

    #[test]
    fn a_reading_without_echo_is_a_faint_outline_only() {
        let style = ConeStyle {
            no_return: 5.0,
            outline: false,
            ..ConeStyle::default()
        };
        let mut g = Geometry::default();
        cone_geometry(&evenly_spaced(2, 0.2), &[5.0, 1.0], &style, &mut g);
        let (triangles, segments) = drawn(&g);
        assert_eq!(triangles.len(), ARC_SEGMENTS, "only the echo is filled");
        assert_eq!(
            segments.len(),
            ARC_SEGMENTS + 2,
            "only the no-echo outlined"
        );
        assert!(segments.iter().all(|(_, c)| c.0[3] < style.fill_alpha));
    }

    #[test]
    fn bad_readings_and_missing_transducers_draw_nothing() {
        let ring = evenly_spaced(3, 0.2);
        let mut g = Geometry::default();
        cone_geometry(&ring, &[f32::NAN, -1.0], &ConeStyle::default(), &mut g);
        assert!(g.is_empty(), "{g:?}");
        cone_geometry(&ring, &[1e9, 0.0, 0.0, 3.0], &ConeStyle::default(), &mut g);
        let (triangles, _) = drawn(&g);
        let furthest = (triangles.iter().flatten())
            .map(|p| p.length())
            .fold(0.0, f32::max);
        assert!(furthest <= 20.0 + 0.2 + 1e-3, "clamped to max_length");
        assert_eq!(triangles.len(), ARC_SEGMENTS, "only the first cone");
    }
}
