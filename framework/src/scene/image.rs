//! Pictures that lie in a node's plane: an occupancy grid on the ground, a floor bitmap, a
//! camera frame. The pixels are plain bytes behind an `Arc`, so a plugin can hand the same
//! picture to several quads, and the scene can be cloned, without copying megabytes; the GPU
//! side lives in `pv3d`'s renderer.
//!
//! Rows run bottom-up: row 0 is the quad's lower edge (y = 0 in its frame), as in Player's
//! maps and OpenGL's textures. A picture read from a file (top row first) is flipped once when
//! it is loaded, never per frame.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::{Vec2, Vec3};

use super::filter::FilterChain;

/// The widest or tallest picture accepted, pixels: what every desktop GL and Mesa's software
/// renderer can hold as one texture, so that a picture the scene accepts can be drawn.
pub const MAX_IMAGE_SIDE: u32 = 16_384;

/// How a pixel is stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PixelFormat {
    /// Red, green, blue, alpha, one byte each (sRGB, unpremultiplied).
    Rgba8,
    /// One grey byte: occupancy grids and floor bitmaps, a quarter of the memory.
    Gray8,
}

impl PixelFormat {
    pub const fn bytes_per_pixel(self) -> usize {
        match self {
            PixelFormat::Rgba8 => 4,
            PixelFormat::Gray8 => 1,
        }
    }
}

/// How the picture is sampled between pixels when drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Sampling {
    /// Each pixel a sharp square: grids, where a blurred cell edge would lie about occupancy.
    #[default]
    Nearest,
    /// Smooth between pixels: photographs.
    Linear,
    /// Sharp cells up close; zoomed out, where several cells share a screen pixel, the
    /// darkest of them shows, so a wall one cell thick never vanishes from a large map.
    Grid,
}

/// Why bytes do not make a picture.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ImageError {
    #[error("a {width}×{height} image has no pixels")]
    Empty { width: u32, height: u32 },
    #[error("a {width}×{height} image is larger than {MAX_IMAGE_SIDE} pixels on a side")]
    TooLarge { width: u32, height: u32 },
    #[error("a {width}×{height} {format:?} image needs {expected} bytes, {actual} were given")]
    WrongLength {
        width: u32,
        height: u32,
        format: PixelFormat,
        expected: usize,
        actual: usize,
    },
}

/// Hands out a new stamp for every picture made, in the whole process.
static NEXT_GENERATION: AtomicU64 = AtomicU64::new(1);

/// An immutable picture. Its [`Pixels::generation`] names its content: a plugin that changes
/// the picture makes new `Pixels` (and so a new generation), which is how the renderer knows
/// to upload again — and knows not to while the generation stays.
#[derive(Debug, Clone)]
pub struct Pixels {
    width: u32,
    height: u32,
    format: PixelFormat,
    bytes: Arc<[u8]>,
    generation: u64,
}

impl Pixels {
    /// A picture of `width` × `height` pixels, rows bottom-up, each row tightly packed.
    pub fn new(
        width: u32,
        height: u32,
        format: PixelFormat,
        bytes: impl Into<Arc<[u8]>>,
    ) -> Result<Pixels, ImageError> {
        if width == 0 || height == 0 {
            return Err(ImageError::Empty { width, height });
        }
        if width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
            return Err(ImageError::TooLarge { width, height });
        }
        let bytes = bytes.into();
        let expected = width as usize * height as usize * format.bytes_per_pixel();
        if bytes.len() != expected {
            return Err(ImageError::WrongLength {
                width,
                height,
                format,
                expected,
                actual: bytes.len(),
            });
        }
        Ok(Pixels {
            width,
            height,
            format,
            bytes,
            generation: NEXT_GENERATION.fetch_add(1, Ordering::Relaxed),
        })
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    pub fn height(&self) -> u32 {
        self.height
    }

    pub fn format(&self) -> PixelFormat {
        self.format
    }

    /// Rows bottom-up, tightly packed.
    pub fn bytes(&self) -> &[u8] {
        &self.bytes
    }

    /// Unique to this content in this process; copies share it.
    pub fn generation(&self) -> u64 {
        self.generation
    }
}

/// Same generation, same picture: comparing megabytes of bytes is never needed.
impl PartialEq for Pixels {
    fn eq(&self, other: &Self) -> bool {
        self.generation == other.generation
    }
}

/// Which way a picture faces. The scene only says what is wanted; which way the viewer looks
/// is known to the renderer alone, so it is the renderer that turns a billboard, every frame
/// and for every camera (the main view and the virtual ones alike).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Facing {
    /// In the node's x–y plane, turning with the node: a map, a floor bitmap, a projection.
    #[default]
    Fixed,
    /// A billboard: turned towards whoever looks, so that a formula or a camera's picture
    /// reads from any side. In a perspective view it stands upright and turns about the
    /// vertical; in the top view it lies flat, north up. `corner` is then the anchor, a point
    /// in the node's frame, and `pivot` the point of the picture pinned to it (0 0 its lower
    /// left corner, 0.5 0 the middle of its lower edge, as shares of `size`). Only the node's
    /// position applies: its turn would undo the facing, and `size` stays in metres.
    Viewer { pivot: Vec2 },
}

/// A picture drawn as a rectangle in its node's x–y plane (or turned towards the viewer, see
/// [`Facing`]), optionally through a chain of filters the renderer runs on the GPU.
#[derive(Debug, Clone, PartialEq)]
pub struct ImageQuad {
    pub pixels: Pixels,
    /// The corner where row 0, column 0 lies, in the node's frame; a billboard's anchor.
    pub corner: Vec3,
    /// Extent along the node's x (columns) and y (rows), m.
    pub size: Vec2,
    pub sampling: Sampling,
    /// Applied in order before drawing; empty draws the pixels as they are.
    pub filters: FilterChain,
    pub facing: Facing,
}

impl ImageQuad {
    /// `pixels` lying from `corner` over `size`, unfiltered, sampled as `sampling`.
    pub fn new(pixels: Pixels, corner: Vec3, size: Vec2, sampling: Sampling) -> ImageQuad {
        ImageQuad {
            pixels,
            corner,
            size,
            sampling,
            filters: FilterChain::default(),
            facing: Facing::Fixed,
        }
    }

    /// `pixels` as a billboard `size` metres big, turned towards the viewer, with the point
    /// `pivot` (shares of its size from its lower left corner) at `anchor` in the node's frame.
    pub fn billboard(
        pixels: Pixels,
        anchor: Vec3,
        pivot: Vec2,
        size: Vec2,
        sampling: Sampling,
    ) -> ImageQuad {
        ImageQuad {
            facing: Facing::Viewer { pivot },
            ..ImageQuad::new(pixels, anchor, size, sampling)
        }
    }

    /// The four corners in the node's frame, counter-clockwise from row 0, column 0, with the
    /// texture coordinate of each. A billboard's are where the top view shows it, flat around
    /// its anchor: enough to frame the view, which is all they are used for.
    pub fn corners(&self) -> [(Vec3, Vec2); 4] {
        let origin = self.corner + self.billboard_offsets()[0].0.extend(0.0);
        let (x, y) = (Vec3::X * self.size.x, Vec3::Y * self.size.y);
        [
            (origin, Vec2::new(0.0, 0.0)),
            (origin + x, Vec2::new(1.0, 0.0)),
            (origin + x + y, Vec2::new(1.0, 1.0)),
            (origin + y, Vec2::new(0.0, 1.0)),
        ]
    }

    /// A billboard's corners as offsets from its anchor along the viewer's right and up, m,
    /// counter-clockwise from row 0, column 0, with their texture coordinates; all zero offsets
    /// from the corner for a fixed picture.
    pub fn billboard_offsets(&self) -> [(Vec2, Vec2); 4] {
        let uv = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
        match self.facing {
            Facing::Fixed => uv.map(|uv| (Vec2::ZERO, uv)),
            Facing::Viewer { pivot } => uv.map(|uv| ((uv - pivot) * self.size, uv)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bytes_must_match_the_size_and_format() {
        assert!(Pixels::new(2, 3, PixelFormat::Gray8, vec![0u8; 6]).is_ok());
        assert_eq!(
            Pixels::new(2, 3, PixelFormat::Rgba8, vec![0u8; 6]).unwrap_err(),
            ImageError::WrongLength {
                width: 2,
                height: 3,
                format: PixelFormat::Rgba8,
                expected: 24,
                actual: 6
            }
        );
        assert!(matches!(
            Pixels::new(0, 3, PixelFormat::Gray8, Vec::new()),
            Err(ImageError::Empty { .. })
        ));
        // A lying size is refused before anything is multiplied out or allocated.
        assert!(matches!(
            Pixels::new(u32::MAX, u32::MAX, PixelFormat::Rgba8, Vec::new()),
            Err(ImageError::TooLarge { .. })
        ));
    }

    #[test]
    fn each_picture_has_its_own_generation_and_copies_share_it() {
        let a = Pixels::new(1, 1, PixelFormat::Gray8, vec![7u8]).unwrap();
        let b = Pixels::new(1, 1, PixelFormat::Gray8, vec![7u8]).unwrap();
        assert_ne!(a.generation(), b.generation(), "new pixels, new upload");
        assert_ne!(a, b);
        let copy = a.clone();
        assert_eq!(copy, a);
        assert_eq!(copy.generation(), a.generation());
    }

    #[test]
    fn a_quad_spans_its_size_from_its_corner() {
        let pixels = Pixels::new(4, 2, PixelFormat::Gray8, vec![0u8; 8]).unwrap();
        let quad = ImageQuad::new(
            pixels,
            Vec3::new(1.0, 2.0, 0.0),
            Vec2::new(4.0, 2.0),
            Sampling::Nearest,
        );
        let corners = quad.corners();
        assert_eq!(corners[0], (Vec3::new(1.0, 2.0, 0.0), Vec2::ZERO));
        assert_eq!(corners[2], (Vec3::new(5.0, 4.0, 0.0), Vec2::ONE));
        assert!(
            quad.billboard_offsets()
                .iter()
                .all(|(o, _)| *o == Vec2::ZERO)
        );
    }

    #[test]
    fn a_billboard_hangs_from_its_pivot() {
        let pixels = Pixels::new(4, 2, PixelFormat::Gray8, vec![0u8; 8]).unwrap();
        let anchor = Vec3::new(1.0, 2.0, 3.0);
        let quad = ImageQuad::billboard(
            pixels,
            anchor,
            Vec2::new(0.5, 0.0),
            Vec2::new(4.0, 2.0),
            Sampling::Linear,
        );
        let offsets = quad.billboard_offsets();
        // The middle of its lower edge on the anchor: 2 m to either side, 2 m up.
        assert_eq!(offsets[0], (Vec2::new(-2.0, 0.0), Vec2::ZERO));
        assert_eq!(offsets[2], (Vec2::new(2.0, 2.0), Vec2::ONE));
        // Seen from above, it lies around its anchor.
        assert_eq!(quad.corners()[0].0, Vec3::new(-1.0, 2.0, 3.0));
        assert_eq!(quad.corners()[2].0, Vec3::new(3.0, 4.0, 3.0));
    }
}
