//! Reading a picture file into scene pixels: grey files stay one byte per pixel, the rest
//! become RGBA; rows are flipped once here, since files list the top row first and the scene
//! the bottom one.

use std::path::{Path, PathBuf};

use framework::scene::image::MAX_IMAGE_SIDE;
use framework::scene::{ImageError, PixelFormat, Pixels};

/// Why a picture file cannot be shown.
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    #[error("{path}: {source}")]
    Read {
        path: PathBuf,
        source: image::ImageError,
    },
    #[error("{path}: {source}")]
    Picture { path: PathBuf, source: ImageError },
}

/// The picture in `path`, bottom row first. A file larger than a texture can hold is refused
/// from its header, before it is decoded.
pub fn load_picture(path: &Path) -> Result<Pixels, LoadError> {
    let read = |source| LoadError::Read {
        path: path.to_path_buf(),
        source,
    };
    let mut reader = image::ImageReader::open(path)
        .map_err(|e| read(image::ImageError::IoError(e)))?
        .with_guessed_format()
        .map_err(|e| read(image::ImageError::IoError(e)))?;
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_IMAGE_SIDE);
    limits.max_image_height = Some(MAX_IMAGE_SIDE);
    reader.limits(limits);
    let decoded = reader.decode().map_err(read)?.flipv();
    let (width, height) = (decoded.width(), decoded.height());
    let pixels = if decoded.color().channel_count() == 1 {
        Pixels::new(
            width,
            height,
            PixelFormat::Gray8,
            decoded.into_luma8().into_raw(),
        )
    } else {
        Pixels::new(
            width,
            height,
            PixelFormat::Rgba8,
            decoded.into_rgba8().into_raw(),
        )
    };
    pixels.map_err(|source| LoadError::Picture {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grey_floor_plan_stays_grey_and_bottom_row_first() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/bitmaps/room.png");
        let pixels = load_picture(&path).unwrap();
        assert_eq!(pixels.format(), PixelFormat::Gray8);
        assert_eq!((pixels.width(), pixels.height()), (100, 80));
        let file = image::open(&path).unwrap().into_luma8();
        let bottom_row_in_file = &file.as_raw()[79 * 100..80 * 100];
        assert_eq!(&pixels.bytes()[..100], bottom_row_in_file);
    }

    #[test]
    fn a_missing_or_broken_file_names_itself() {
        let err = load_picture(Path::new("no/such.png"))
            .unwrap_err()
            .to_string();
        assert!(err.starts_with("no/such.png:"), "{err}");
        let dir = std::env::temp_dir().join(format!("pv3d-image-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let broken = dir.join("broken.png");
        std::fs::write(&broken, b"\x89PNG\r\n\x1a\nnot really").unwrap();
        let err = load_picture(&broken).unwrap_err().to_string();
        assert!(err.contains("broken.png"), "{err}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
