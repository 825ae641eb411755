//! Camera frames as Player sends them: the render as raw RGB888, or as a JPEG file when the
//! .cfg passes the camera through Player's `cameracompress` driver.

use image::ExtendedColorType;
use image::codecs::jpeg::JpegEncoder;
use player_proto::interfaces::camera::{COMPRESS_JPEG, COMPRESS_RAW, CameraData, FORMAT_RGB888};

use crate::sim::{Frame, Simulation, render_camera};

/// Player's `cameracompress` default quality (its `image_quality 0.8`), as the JPEG scale.
pub const DEFAULT_JPEG_QUALITY: u8 = 80;

/// Robot `robot`'s camera `camera` this step: raw, or JPEG at `jpeg_quality` (1–100).
pub fn camera_data(
    sim: &Simulation,
    robot: usize,
    camera: usize,
    jpeg_quality: Option<u8>,
) -> CameraData {
    let frame = render_camera(sim, robot, &sim.world.robots[robot].cameras[camera]);
    let raw = |frame: Frame| CameraData {
        width: frame.width,
        height: frame.height,
        bpp: 24,
        format: FORMAT_RGB888,
        fdiv: 0,
        compression: COMPRESS_RAW,
        image: frame.rgb.into(),
    };
    let Some(quality) = jpeg_quality else {
        return raw(frame);
    };
    let mut jpeg = Vec::new();
    let encoded = JpegEncoder::new_with_quality(&mut jpeg, quality.clamp(1, 100)).encode(
        &frame.rgb,
        frame.width,
        frame.height,
        ExtendedColorType::Rgb8,
    );
    match encoded {
        Ok(()) => CameraData {
            compression: COMPRESS_JPEG,
            image: jpeg.into(),
            ..raw(Frame {
                rgb: Vec::new(),
                ..frame
            })
        },
        Err(e) => {
            // Only an impossible size fails; a raw frame is still a correct answer.
            tracing::warn!(
                "camera {camera} of robot {robot}: JPEG encoding failed ({e}); sent raw"
            );
            raw(frame)
        }
    }
}
