//! What a localizer's estimate looks like in the scene: each hypothesis as an arrow at its
//! mean inside its 95 % ellipse (the best one bold, the others faint), the particles as
//! points, and the pose being given by hand as an outlined arrow.

use glam::{Vec2, Vec3};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::localize::{LocalizeData, LocalizeParticle};

use super::ellipse::Ellipse;
use framework::scene::{Geometry, Rgba};

/// Height above the floor everything is drawn at, m: clear of the floor's own lines.
pub const LIFT: f32 = 0.03;
/// Segments of an ellipse's outline.
const ELLIPSE_SEGMENTS: usize = 48;
/// The pose arrow's length and half width, m.
const ARROW_LENGTH: f32 = 0.45;
const ARROW_HALF_WIDTH: f32 = 0.15;
/// Opacity of the best ellipse's fill and of the other hypotheses' outlines.
const FILL_ALPHA: u8 = 50;
const FAINT_ALPHA: u8 = 110;

fn on_floor(p: Vec2) -> Vec3 {
    p.extend(LIFT)
}

/// The arrow's three corners: tip ahead along `heading`, base behind `at`.
fn arrow(at: Vec2, heading: f32) -> [Vec3; 3] {
    let ahead = Vec2::from_angle(heading);
    let side = ahead.perp() * ARROW_HALF_WIDTH;
    let tail = at - ahead * (ARROW_LENGTH / 3.0);
    [
        on_floor(at + ahead * (ARROW_LENGTH * 2.0 / 3.0)),
        on_floor(tail + side),
        on_floor(tail - side),
    ]
}

fn pose_point(pose: &Pose2d) -> Vec2 {
    Vec2::new(pose.px as f32, pose.py as f32)
}

/// Fills `geometry` (cleared first) with every hypothesis; the heaviest is drawn solid with
/// its share of the message's weights beside it (a driver's raw weight may be any number).
pub fn hypotheses(geometry: &mut Geometry, data: &LocalizeData, color: Rgba) {
    geometry.clear();
    let best = data.best().copied();
    for hypothesis in &data.hypoths {
        let centre = pose_point(&hypothesis.mean);
        let rim: Vec<Vec3> = Ellipse::of_covariance(&hypothesis.cov)
            .outline(centre, ELLIPSE_SEGMENTS)
            .into_iter()
            .map(on_floor)
            .collect();
        if Some(*hypothesis) == best {
            let mut closed = rim.clone();
            closed.push(rim[0]);
            geometry.fan(on_floor(centre), closed, color.with_alpha(FILL_ALPHA));
            geometry.polygon_outline(&rim, color);
            let [tip, left, right] = arrow(centre, hypothesis.mean.pa as f32);
            geometry.triangle(tip, left, right, color);
            geometry.label(
                on_floor(centre + Vec2::new(0.3, 0.3)),
                data.share_of(hypothesis).to_string(),
                color,
            );
        } else {
            geometry.polygon_outline(&rim, color.with_alpha(FAINT_ALPHA));
        }
    }
}

/// Fills `geometry` (cleared first) with one point per particle.
pub fn particles(geometry: &mut Geometry, particles: &[LocalizeParticle], color: Rgba) {
    geometry.clear();
    for particle in particles {
        geometry.point(on_floor(pose_point(&particle.pose)), color);
    }
}

/// The pose being given by hand: a ring at the position and, once dragged far enough, an
/// outlined arrow along the heading.
pub fn hand_pose(geometry: &mut Geometry, at: Vec2, heading: Option<f32>, color: Rgba) {
    let ring: Vec<Vec3> = Ellipse {
        major: f64::from(ARROW_HALF_WIDTH),
        minor: f64::from(ARROW_HALF_WIDTH),
        angle: 0.0,
    }
    .outline(at, ELLIPSE_SEGMENTS / 2)
    .into_iter()
    .map(on_floor)
    .collect();
    geometry.polygon_outline(&ring, color);
    if let Some(heading) = heading {
        geometry.polygon_outline(&arrow(at, heading), color);
    }
}
