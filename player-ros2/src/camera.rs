//! A Player camera's picture as ROS 2's: raw pixels as `sensor_msgs/msg/Image` (RGB 5-6-5,
//! which ROS has no encoding for, widened to `rgb8`), a JPEG as `CompressedImage`; beside
//! either, its size as `CameraInfo` (uncalibrated: Player's camera interface says nothing of
//! its lens).

use player_proto::interfaces::camera::{
    COMPRESS_JPEG, CameraData, FORMAT_MONO8, FORMAT_MONO16, FORMAT_RGB565, FORMAT_RGB888,
};

use crate::msgs::{CameraInfo, CompressedImage, Header, Image};
use crate::out::RosOut;

/// The picture's `CameraInfo`: its size, and zeros for the calibration (`k`, `r`, `p` all
/// zero is ROS's "uncalibrated"; image_proc and rviz2 then show the picture as it is).
pub fn info(data: &CameraData, header: Header) -> CameraInfo {
    CameraInfo {
        header,
        height: data.height,
        width: data.width,
        distortion_model: "plumb_bob".into(),
        d: vec![0.0; 5],
        ..CameraInfo::default()
    }
}

/// The ROS 2 message of a picture, or `None` for a pixel format ROS has no name for (or
/// pixels that do not fill the picture).
pub fn picture(data: &CameraData, header: Header) -> Option<RosOut> {
    if data.compression == COMPRESS_JPEG {
        return Some(RosOut::CompressedImage(CompressedImage {
            header,
            format: "jpeg".into(),
            data: data.image.to_vec(),
        }));
    }
    let (width, height) = (data.width, data.height);
    let pixels = u64::from(width) * u64::from(height);
    let (encoding, bytes_per_pixel, pixels_out) = match data.format {
        FORMAT_MONO8 => ("mono8", 1, data.image.to_vec()),
        FORMAT_MONO16 => ("mono16", 2, data.image.to_vec()),
        FORMAT_RGB888 => ("rgb8", 3, data.image.to_vec()),
        FORMAT_RGB565 => ("rgb8", 3, widen_565(&data.image)),
        _ => return None,
    };
    if pixels_out.len() as u64 != pixels * bytes_per_pixel {
        return None;
    }
    Some(RosOut::Image(Image {
        header,
        height,
        width,
        encoding: encoding.into(),
        is_bigendian: 0,
        step: width * bytes_per_pixel as u32,
        data: pixels_out,
    }))
}

/// RGB 5-6-5 (little-endian, as Player's drivers fill it) to 8 bits a channel.
fn widen_565(raw: &[u8]) -> Vec<u8> {
    raw.chunks_exact(2)
        .flat_map(|p| {
            let v = u16::from_le_bytes([p[0], p[1]]);
            let (r, g, b) = ((v >> 11) & 0x1f, (v >> 5) & 0x3f, v & 0x1f);
            [
                (r * 255 / 31) as u8,
                (g * 255 / 63) as u8,
                (b * 255 / 31) as u8,
            ]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn raw(format: u32, bpp: u32, image: Vec<u8>) -> CameraData {
        CameraData {
            width: 2,
            height: 1,
            bpp,
            format,
            image: image.into(),
            ..CameraData::default()
        }
    }

    #[test]
    fn pictures_keep_their_pixels_or_say_none() {
        let Some(RosOut::Image(rgb)) = picture(
            &raw(FORMAT_RGB888, 24, vec![1, 2, 3, 4, 5, 6]),
            Header::default(),
        ) else {
            panic!("an rgb8 image");
        };
        assert_eq!(
            (rgb.encoding.as_str(), rgb.step, rgb.data.len()),
            ("rgb8", 6, 6)
        );
        let Some(RosOut::Image(wide)) = picture(
            &raw(FORMAT_RGB565, 16, vec![0xff, 0xff, 0x00, 0xf8]),
            Header::default(),
        ) else {
            panic!("565 widened");
        };
        assert_eq!(wide.data, [255, 255, 255, 255, 0, 0]);
        assert!(
            picture(&raw(FORMAT_RGB888, 24, vec![1, 2, 3]), Header::default()).is_none(),
            "short"
        );
        let jpeg = CameraData {
            compression: COMPRESS_JPEG,
            image: vec![0xff, 0xd8].into(),
            ..CameraData::default()
        };
        assert!(matches!(
            picture(&jpeg, Header::default()),
            Some(RosOut::CompressedImage(_))
        ));
    }
}
