//! Why a picture a world or a configuration names — a floorplan bitmap, a map driver's image —
//! could not be read: the file and what was wrong with it, so that the world file's error
//! (which adds file:line) says which picture to fix and why.

use std::path::PathBuf;

/// What kind of picture it was, as the error names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Picture {
    Bitmap,
    MapImage,
}

#[derive(Debug, thiserror::Error)]
#[error("cannot read {} {}: {fault}", match .picture {
    Picture::Bitmap => "bitmap",
    Picture::MapImage => "map image",
}, .path.display())]
pub struct ImageFileError {
    pub picture: Picture,
    pub path: PathBuf,
    pub fault: ImageFault,
}

#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ImageFault {
    #[error("{0}")]
    Open(#[from] std::io::Error),
    #[error("{0}")]
    Decode(#[from] image::ImageError),
    #[error("it is {width} x {height} pixels")]
    Empty { width: u32, height: u32 },
    #[error("it is {width} x {height} pixels, more than the {most} a floorplan may have")]
    TooLarge { width: u32, height: u32, most: u64 },
}
