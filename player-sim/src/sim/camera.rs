//! What a robot's camera sees, as a first-person column render: one ray per image column
//! against the floorplan's walls, the boxes and the other robots; each thing hit drawn as a
//! vertical span in its own colour, as tall as its height at that distance looks, darker
//! farther away; sky above and floor below. Cheap (one ray per column) and deterministic.

use super::nearby::NearbyBoxes;
use super::{Simulation, on_robot};
use crate::world::{CameraSpec, Face};

/// An RGB888 image, rows top first.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
}

const SKY_TOP: [u8; 3] = [110, 160, 225];
const SKY_HORIZON: [u8; 3] = [200, 220, 240];
const FLOOR_NEAR: [u8; 3] = [150, 140, 120];
const FLOOR_HORIZON: [u8; 3] = [90, 85, 75];

fn mix(a: [u8; 3], b: [u8; 3], t: f64) -> [u8; 3] {
    let t = t.clamp(0.0, 1.0);
    std::array::from_fn(|i| (f64::from(a[i]) * (1.0 - t) + f64::from(b[i]) * t).round() as u8)
}

fn shade(color: [u8; 3], distance: f64, max_range: f64) -> [u8; 3] {
    // From full colour at the camera to 60 % at its maximum range: depth a person can read.
    let k = 1.0 - 0.4 * (distance / max_range.max(1e-6)).clamp(0.0, 1.0);
    color.map(|c| (f64::from(c) * k).round() as u8)
}

/// A thing a column's ray meets: its distance along the ray, its height and colour.
struct Span {
    distance: f64,
    height: f64,
    color: [u8; 3],
}

/// Renders robot `robot`'s camera `camera`.
pub fn render_camera(sim: &Simulation, robot: usize, camera: &CameraSpec) -> Frame {
    let (w, h) = (camera.width_px as usize, camera.height_px as usize);
    let eye = on_robot(sim.robots[robot].pose, camera.pose);
    let half_w = w as f64 / 2.0;
    let half_h = h as f64 / 2.0;
    // Focal lengths in pixels from the fields of view.
    let focal_x = half_w / (camera.fov_h / 2.0).tan().max(1e-6);
    let focal_y = half_h / (camera.fov_v / 2.0).tan().max(1e-6);
    let mut rgb = vec![0u8; w * h * 3];
    for row in 0..h {
        let up = (half_h - (row as f64 + 0.5)) / half_h;
        let color = if up >= 0.0 {
            mix(SKY_HORIZON, SKY_TOP, up)
        } else {
            mix(FLOOR_HORIZON, FLOOR_NEAR, -up)
        };
        for col in 0..w {
            rgb[(row * w + col) * 3..][..3].copy_from_slice(&color);
        }
    }
    let boxes = NearbyBoxes::around(sim, Some(robot), eye.x, eye.y, camera.max_range);
    let (walls, wall_color) = (sim.world.floor_height, sim.world.floor_color);
    let mut spans: Vec<Span> = Vec::new();
    for col in 0..w {
        // Column 0 is the leftmost, which is the largest angle (counter-clockwise).
        let offset = ((half_w - (col as f64 + 0.5)) / focal_x).atan();
        let angle = eye.a + offset;
        let wall = sim
            .world
            .floor
            .as_ref()
            .and_then(|g| g.raycast_face(eye.x, eye.y, angle, camera.max_range));
        spans.clear();
        spans.extend(wall.map(|(distance, face)| Span {
            distance,
            height: walls,
            // North and south faces a little darker, so that corners show.
            color: match face {
                Face::EastWest => wall_color,
                Face::NorthSouth => wall_color.map(|c| (u16::from(c) * 4 / 5) as u8),
            },
        }));
        let reach = wall.map_or(camera.max_range, |(d, _)| d);
        spans.extend(
            boxes
                .all_along(eye.x, eye.y, angle, reach)
                .map(|(distance, b)| Span {
                    distance,
                    height: b.height,
                    color: b.color,
                }),
        );
        // Far to near, so that nearer things cover farther ones.
        spans.sort_by(|a, b| b.distance.total_cmp(&a.distance));
        for span in &spans {
            // Depth along the view axis, not along the ray: walls stay straight.
            let depth = (span.distance * offset.cos()).max(1e-3);
            let top = half_h - (span.height - camera.height) * focal_y / depth;
            let bottom = half_h + camera.height * focal_y / depth;
            let (top, bottom) = (top.max(0.0).round() as usize, bottom.min(h as f64).round());
            let color = shade(span.color, span.distance, camera.max_range);
            for row in top..(bottom.max(0.0) as usize).min(h) {
                rgb[(row * w + col) * 3..][..3].copy_from_slice(&color);
            }
        }
    }
    Frame {
        width: camera.width_px,
        height: camera.height_px,
        rgb,
    }
}
