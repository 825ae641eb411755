//! Decoding a camera frame to RGBA: raw MONO8, MONO16, RGB565, RGB888, 32-bit, and JPEG.

use image::RgbaImage;

use super::camera::{
    COMPRESS_JPEG, COMPRESS_RAW, CameraData, FORMAT_MONO8, FORMAT_MONO16, FORMAT_RGB565,
    FORMAT_RGB888,
};

/// The largest frame we agree to decode (a 8K frame), so that a lying width and height cannot
/// make us allocate gigabytes.
pub const MAX_PIXELS: u64 = 7680 * 4320;

/// Why a frame cannot be shown.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CameraImageError {
    #[error("{width}×{height} frame is empty or larger than {MAX_PIXELS} pixels")]
    Size { width: u32, height: u32 },
    #[error("{width}×{height} at {bpp} bpp needs {expected} bytes, the frame has {actual}")]
    Length {
        width: u32,
        height: u32,
        bpp: u32,
        expected: u64,
        actual: usize,
    },
    #[error("raw format {format} at {bpp} bpp is not one Player defines")]
    Format { format: u32, bpp: u32 },
    #[error("compression {0} is neither raw (0) nor JPEG (1)")]
    Compression(u32),
    #[error("JPEG does not decode: {0}")]
    Jpeg(String),
    #[error("JPEG is {actual_w}×{actual_h}, the header says {width}×{height}")]
    JpegSize {
        width: u32,
        height: u32,
        actual_w: u32,
        actual_h: u32,
    },
}

impl CameraData {
    /// The frame as RGBA pixels.
    pub fn to_rgba(&self) -> Result<RgbaImage, CameraImageError> {
        let (width, height) = (self.width, self.height);
        let pixels = u64::from(width) * u64::from(height);
        if pixels == 0 || pixels > MAX_PIXELS {
            return Err(CameraImageError::Size { width, height });
        }
        match self.compression {
            COMPRESS_RAW => self.raw_to_rgba(pixels),
            COMPRESS_JPEG => self.jpeg_to_rgba(),
            other => Err(CameraImageError::Compression(other)),
        }
    }

    fn raw_to_rgba(&self, pixels: u64) -> Result<RgbaImage, CameraImageError> {
        let bytes_per_pixel = u64::from(self.bpp / 8);
        let expected = pixels * bytes_per_pixel;
        let data = &self.image[..];
        if bytes_per_pixel == 0 || data.len() as u64 != expected {
            return Err(CameraImageError::Length {
                width: self.width,
                height: self.height,
                bpp: self.bpp,
                expected,
                actual: data.len(),
            });
        }
        let mut out = Vec::with_capacity(pixels as usize * 4);
        match (self.format, self.bpp) {
            (FORMAT_MONO8, 8) => out.extend(data.iter().flat_map(|&v| [v, v, v, 255])),
            // MONO16 is big-endian (network order); show the high byte.
            (FORMAT_MONO16, 16) => {
                out.extend(data.chunks_exact(2).flat_map(|p| [p[0], p[0], p[0], 255]))
            }
            // RGB565 byte order is not fixed by Player; drivers on x86 send little-endian.
            (FORMAT_RGB565, 16) => out.extend(data.chunks_exact(2).flat_map(|p| {
                let v = u16::from_le_bytes([p[0], p[1]]);
                let r = ((v >> 11) & 0x1f) as u8;
                let g = ((v >> 5) & 0x3f) as u8;
                let b = (v & 0x1f) as u8;
                [r << 3 | r >> 2, g << 2 | g >> 4, b << 3 | b >> 2, 255]
            })),
            (FORMAT_RGB888, 24) => {
                out.extend(data.chunks_exact(3).flat_map(|p| [p[0], p[1], p[2], 255]))
            }
            // 32-bit frames carry RGB plus a byte that is not alpha in Player's drivers.
            (_, 32) => out.extend(data.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2], 255])),
            (format, bpp) => return Err(CameraImageError::Format { format, bpp }),
        }
        Ok(RgbaImage::from_raw(self.width, self.height, out).expect("length checked above"))
    }

    fn jpeg_to_rgba(&self) -> Result<RgbaImage, CameraImageError> {
        let mut reader = image::ImageReader::with_format(
            std::io::Cursor::new(&self.image[..]),
            image::ImageFormat::Jpeg,
        );
        // The header's size bounds what the decoder may allocate.
        let mut limits = image::Limits::default();
        limits.max_image_width = Some(self.width);
        limits.max_image_height = Some(self.height);
        limits.max_alloc = Some(u64::from(self.width) * u64::from(self.height) * 8 + (1 << 20));
        reader.limits(limits);
        let decoded = reader
            .decode()
            .map_err(|e| CameraImageError::Jpeg(e.to_string()))?;
        if decoded.width() != self.width || decoded.height() != self.height {
            return Err(CameraImageError::JpegSize {
                width: self.width,
                height: self.height,
                actual_w: decoded.width(),
                actual_h: decoded.height(),
            });
        }
        Ok(decoded.to_rgba8())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::Opaque;

    fn frame(width: u32, height: u32, bpp: u32, format: u32, image: Vec<u8>) -> CameraData {
        CameraData {
            width,
            height,
            bpp,
            format,
            fdiv: 1,
            compression: COMPRESS_RAW,
            image: Opaque::from(image),
        }
    }

    #[test]
    fn raw_formats_decode() {
        let mono = frame(2, 1, 8, FORMAT_MONO8, vec![0x11, 0x22])
            .to_rgba()
            .unwrap();
        assert_eq!(mono.get_pixel(1, 0).0, [0x22, 0x22, 0x22, 255]);
        let rgb = frame(1, 2, 24, FORMAT_RGB888, vec![1, 2, 3, 4, 5, 6])
            .to_rgba()
            .unwrap();
        assert_eq!(rgb.get_pixel(0, 1).0, [4, 5, 6, 255]);
        let m16 = frame(1, 1, 16, FORMAT_MONO16, vec![0xab, 0xcd])
            .to_rgba()
            .unwrap();
        assert_eq!(m16.get_pixel(0, 0).0, [0xab, 0xab, 0xab, 255]);
        // Pure red in RGB565: 0xf800.
        let red = frame(1, 1, 16, FORMAT_RGB565, vec![0x00, 0xf8])
            .to_rgba()
            .unwrap();
        assert_eq!(red.get_pixel(0, 0).0, [255, 0, 0, 255]);
    }

    #[test]
    fn lies_are_refused() {
        assert!(matches!(
            frame(3, 1, 24, FORMAT_RGB888, vec![0; 6]).to_rgba(),
            Err(CameraImageError::Length { .. })
        ));
        assert!(matches!(
            frame(100_000, 100_000, 24, FORMAT_RGB888, vec![]).to_rgba(),
            Err(CameraImageError::Size { .. })
        ));
        assert!(matches!(
            frame(1, 1, 8, 3, vec![0]).to_rgba(),
            Err(CameraImageError::Format { .. })
        ));
        let mut jpeg = frame(2, 2, 24, FORMAT_RGB888, b"not a jpeg".to_vec());
        jpeg.compression = COMPRESS_JPEG;
        assert!(matches!(jpeg.to_rgba(), Err(CameraImageError::Jpeg(_))));
    }
}
