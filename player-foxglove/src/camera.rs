//! Camera frames: JPEG as `foxglove.CompressedImage` (the bytes as sent), raw 8-bit grey and
//! 24-bit colour as `foxglove.RawImage` (the bytes as sent), other raw layouts decoded to RGBA.

use foxglove::messages::{CompressedImage, RawImage, Timestamp};
use player_proto::interfaces::camera::{
    COMPRESS_JPEG, COMPRESS_RAW, CameraData, FORMAT_MONO8, FORMAT_RGB888,
};
use player_proto::interfaces::camera_pixels::CameraImageError;

use crate::FoxgloveMessage;

/// The frame as an image message, or why its pixels cannot be read.
pub fn image(
    time: Timestamp,
    frame: &str,
    data: &CameraData,
) -> Result<FoxgloveMessage, CameraImageError> {
    if data.compression == COMPRESS_JPEG {
        return Ok(FoxgloveMessage::CompressedImage(CompressedImage {
            timestamp: Some(time),
            frame_id: frame.into(),
            data: data.image.0.clone(),
            format: "jpeg".into(),
        }));
    }
    let raw = |encoding: &str, bytes_per_pixel: u32, pixels: bytes::Bytes| RawImage {
        timestamp: Some(time),
        frame_id: frame.into(),
        width: data.width,
        height: data.height,
        encoding: encoding.into(),
        step: data.width.saturating_mul(bytes_per_pixel),
        data: pixels,
    };
    let exact = u64::from(data.width) * u64::from(data.height) * u64::from(data.bpp / 8);
    match (data.compression, data.format, data.bpp) {
        (COMPRESS_RAW, FORMAT_MONO8, 8) if data.image.len() as u64 == exact => Ok(
            FoxgloveMessage::RawImage(raw("mono8", 1, data.image.0.clone())),
        ),
        (COMPRESS_RAW, FORMAT_RGB888, 24) if data.image.len() as u64 == exact => Ok(
            FoxgloveMessage::RawImage(raw("rgb8", 3, data.image.0.clone())),
        ),
        _ => {
            let rgba = data.to_rgba()?;
            Ok(FoxgloveMessage::RawImage(raw(
                "rgba8",
                4,
                bytes::Bytes::from(rgba.into_raw()),
            )))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::wire::Opaque;

    #[test]
    fn rgb_frames_keep_their_bytes_and_jpeg_its_stream() {
        let rgb = CameraData {
            width: 2,
            height: 1,
            bpp: 24,
            format: FORMAT_RGB888,
            compression: COMPRESS_RAW,
            image: Opaque::from(vec![1, 2, 3, 4, 5, 6]),
            ..CameraData::default()
        };
        let FoxgloveMessage::RawImage(image) = image(Timestamp::MIN, "c", &rgb).unwrap() else {
            panic!("not a raw image");
        };
        assert_eq!((image.encoding.as_str(), image.step), ("rgb8", 6));
        assert_eq!(&image.data[..], [1, 2, 3, 4, 5, 6]);
        let jpeg = CameraData {
            compression: COMPRESS_JPEG,
            image: Opaque::from(vec![0xff, 0xd8]),
            ..rgb
        };
        let FoxgloveMessage::CompressedImage(c) = super::image(Timestamp::MIN, "c", &jpeg).unwrap()
        else {
            panic!("not a compressed image");
        };
        assert_eq!(
            (c.format.as_str(), &c.data[..]),
            ("jpeg", &[0xff, 0xd8][..])
        );
    }

    #[test]
    fn a_frame_shorter_than_its_size_says_why() {
        let short = CameraData {
            width: 100,
            height: 100,
            bpp: 24,
            format: FORMAT_RGB888,
            image: Opaque::from(vec![0; 10]),
            ..CameraData::default()
        };
        assert!(image(Timestamp::MIN, "c", &short).is_err());
    }
}
