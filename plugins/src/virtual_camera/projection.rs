//! A camera's picture put back into the world: laid on the ground where each of its pixels
//! looks (the frustum's footprint, as a slide projector would throw it), or held up as a
//! billboard above the robot. Both are ordinary scene pictures; the ground one is resampled
//! here, on the CPU, because its footprint is a trapezoid and the scene's pictures are
//! rectangles — the pixels outside the footprint are left transparent. The billboard is a
//! [`framework::scene::Facing::Viewer`] picture: pv3d's renderer turns it to the eye.

use framework::scene::{ImageQuad, PixelFormat, Pixels, Sampling, VirtualView};
use glam::{Affine3A, Vec2, Vec3};

/// How far above the ground the projection lies, m: above the floor bitmap, below the lines
/// drawn on the ground.
pub const GROUND_LIFT: f32 = 0.005;
/// Points sampled along each edge of the picture to find the footprint's extent.
const EDGE_SAMPLES: u32 = 8;

/// Where the camera's picture is shown in the world.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Placement {
    None,
    /// On the ground, along the frustum.
    Ground,
    /// Above the robot, turned towards the viewer.
    Billboard,
}

impl Placement {
    pub fn parse(text: &str) -> Option<Placement> {
        match text {
            "none" => Some(Placement::None),
            "ground" => Some(Placement::Ground),
            "billboard" => Some(Placement::Billboard),
            _ => None,
        }
    }
}

/// The picture resampled onto the ground within `max_distance` of the camera, as a quad in
/// world coordinates whose longer side has `resolution` pixels; `None` when the camera sees no
/// ground (it looks up, or the picture is not RGBA).
pub fn onto_ground(
    view: &VirtualView,
    camera_to_world: Affine3A,
    picture: &Pixels,
    max_distance: f32,
    resolution: u32,
) -> Option<ImageQuad> {
    if picture.format() != PixelFormat::Rgba8 || resolution == 0 {
        return None;
    }
    let (lo, hi) = footprint_bounds(view, camera_to_world, max_distance)?;
    let extent = hi - lo;
    let metres_per_pixel = extent.max_element() / resolution as f32;
    if metres_per_pixel.is_nan() || metres_per_pixel <= 0.0 {
        return None;
    }
    let columns = ((extent.x / metres_per_pixel).ceil() as u32).clamp(1, resolution);
    let rows = ((extent.y / metres_per_pixel).ceil() as u32).clamp(1, resolution);
    let eye = camera_to_world.transform_point3(Vec3::ZERO);
    let mut bytes = vec![0u8; columns as usize * rows as usize * 4];
    let scale = Vec2::new(
        picture.width() as f32 / view.width as f32,
        picture.height() as f32 / view.height as f32,
    );
    for row in 0..rows {
        for column in 0..columns {
            let ground = lo + (Vec2::new(column as f32, row as f32) + 0.5) * metres_per_pixel;
            let point = ground.extend(0.0);
            if point.distance(eye) > max_distance {
                continue;
            }
            let Some(pixel) = view.pixel_of(camera_to_world, point) else {
                continue;
            };
            let source = (pixel * scale).as_uvec2();
            let from = (source.y as usize * picture.width() as usize + source.x as usize) * 4;
            let to = (row as usize * columns as usize + column as usize) * 4;
            bytes[to..to + 4].copy_from_slice(&picture.bytes()[from..from + 4]);
        }
    }
    let pixels = Pixels::new(columns, rows, PixelFormat::Rgba8, bytes).ok()?;
    let size = Vec2::new(columns as f32, rows as f32) * metres_per_pixel;
    Some(ImageQuad::new(
        pixels,
        lo.extend(GROUND_LIFT),
        size,
        Sampling::Linear,
    ))
}

/// The ground rectangle that holds every ground point the camera sees within `max_distance`.
fn footprint_bounds(
    view: &VirtualView,
    camera_to_world: Affine3A,
    max_distance: f32,
) -> Option<(Vec2, Vec2)> {
    let eye = camera_to_world.transform_point3(Vec3::ZERO);
    if eye.z <= 0.0 {
        return None;
    }
    let (w, h) = (view.width as f32, view.height as f32);
    // Beyond the ground a ray meets, or for a ray above the horizon, the farthest ground seen
    // lies `max_distance` from the eye, this far out horizontally.
    let horizontal_reach = (max_distance * max_distance - eye.z * eye.z)
        .max(0.0)
        .sqrt();
    let mut points = Vec::new();
    let mut sees_ground = false;
    // Samples along the picture's edges: the footprint's far side is an arc, bulging between
    // the corners.
    let border = (0..=EDGE_SAMPLES).flat_map(|k| {
        let t = k as f32 / EDGE_SAMPLES as f32;
        [
            Vec2::new(t * w, 0.0),
            Vec2::new(t * w, h),
            Vec2::new(0.0, t * h),
            Vec2::new(w, t * h),
        ]
    });
    for pixel in border {
        let ray = camera_to_world.transform_vector3(view.ray_through(pixel));
        let hit = (ray.z < 0.0).then(|| eye + ray * (-eye.z / ray.z));
        sees_ground |= hit.is_some();
        match hit {
            Some(hit) if hit.distance(eye) <= max_distance => points.push(hit.truncate()),
            _ => {
                let across = ray.truncate().normalize_or_zero() * horizontal_reach;
                points.push(eye.truncate() + across);
            }
        }
    }
    if !sees_ground {
        return None;
    }
    points.push(eye.truncate());
    let lo = points.iter().copied().reduce(Vec2::min)?;
    let hi = points.iter().copied().reduce(Vec2::max)?;
    Some((lo, hi))
}

/// The picture as a billboard `width` metres wide, the middle of its lower edge on the node:
/// the renderer turns it towards whoever looks, so the camera's view reads from any side.
pub fn billboard(picture: &Pixels, width: f32) -> ImageQuad {
    let aspect = picture.height() as f32 / picture.width() as f32;
    ImageQuad::billboard(
        picture.clone(),
        Vec3::ZERO,
        Vec2::new(0.5, 0.0),
        Vec2::new(width, width * aspect),
        Sampling::Linear,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A camera 2 m up looking straight down, its top (+x of the camera frame... rows up)
    /// towards world +x.
    fn looking_down() -> (VirtualView, Affine3A) {
        let view = VirtualView::new(Affine3A::IDENTITY, 60f32.to_radians(), 40, 40).unwrap();
        let pose = Affine3A::from_rotation_translation(
            glam::Quat::from_rotation_y(std::f32::consts::FRAC_PI_2),
            Vec3::new(0.0, 0.0, 2.0),
        );
        (view, pose)
    }

    /// Left half (columns < 20) red, right half blue.
    fn halves() -> Pixels {
        let bytes: Vec<u8> = (0..40 * 40)
            .flat_map(|k| {
                if k % 40 < 20 {
                    [255, 0, 0, 255]
                } else {
                    [0, 0, 255, 255]
                }
            })
            .collect();
        Pixels::new(40, 40, PixelFormat::Rgba8, bytes).unwrap()
    }

    fn ground_colour(quad: &ImageQuad, world: Vec2) -> [u8; 4] {
        let p = quad.pixels.clone();
        let at = (world - quad.corner.truncate()) / quad.size
            * Vec2::new(p.width() as f32, p.height() as f32);
        let from = (at.y as usize * p.width() as usize + at.x as usize) * 4;
        p.bytes()[from..from + 4].try_into().unwrap()
    }

    #[test]
    fn a_camera_looking_down_lays_its_left_on_its_left() {
        let (view, pose) = looking_down();
        let quad = onto_ground(&view, pose, &halves(), 10.0, 64).expect("it sees the ground");
        // Looking down with its top towards +x, the camera's left is world +y.
        assert_eq!(ground_colour(&quad, Vec2::new(0.0, 0.5)), [255, 0, 0, 255]);
        assert_eq!(ground_colour(&quad, Vec2::new(0.0, -0.5)), [0, 0, 255, 255]);
        // The footprint is 2·2·tan 30° ≈ 2.3 m across: around it nothing is drawn.
        let half = 2.0 * (30f32).to_radians().tan();
        assert!((quad.size.x - 2.0 * half).abs() < 0.1, "{}", quad.size);
        assert_eq!(quad.corner.z, GROUND_LIFT);
    }

    #[test]
    fn a_camera_looking_up_projects_nothing() {
        let (view, _) = looking_down();
        let up = Affine3A::from_rotation_translation(
            glam::Quat::from_rotation_y(-std::f32::consts::FRAC_PI_2),
            Vec3::new(0.0, 0.0, 2.0),
        );
        assert!(onto_ground(&view, up, &halves(), 10.0, 64).is_none());
    }

    #[test]
    fn ahead_of_a_level_camera_the_footprint_stops_at_the_distance_given() {
        let view = VirtualView::new(Affine3A::IDENTITY, 60f32.to_radians(), 40, 30).unwrap();
        let pose = Affine3A::from_translation(Vec3::new(0.0, 0.0, 0.5));
        let quad = onto_ground(&view, pose, &halves(), 5.0, 64).unwrap();
        let far = quad.corner.x + quad.size.x;
        assert!(far <= 5.0 + 0.1 && far > 4.0, "{far}");
        // Beyond the horizon's distance, pixels stay transparent.
        let transparent = quad.pixels.bytes().chunks_exact(4).filter(|p| p[3] == 0);
        assert!(transparent.count() > 0);
    }

    #[test]
    fn the_billboard_stands_on_the_middle_of_its_lower_edge() {
        let quad = billboard(&halves(), 2.0);
        assert_eq!(
            quad.facing,
            framework::scene::Facing::Viewer {
                pivot: Vec2::new(0.5, 0.0)
            }
        );
        assert_eq!(quad.size, Vec2::new(2.0, 2.0));
        assert_eq!(quad.corner, Vec3::ZERO);
    }

    #[test]
    fn placements_parse_and_others_do_not() {
        assert_eq!(Placement::parse("ground"), Some(Placement::Ground));
        assert_eq!(Placement::parse("billboard"), Some(Placement::Billboard));
        assert_eq!(Placement::parse("wall"), None);
    }
}
