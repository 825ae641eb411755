//! A picture a plugin wants filtered but not drawn: a camera frame under a chain of kernels
//! for the camera's own window. The viewer runs the chain on the GPU, as it does for pictures
//! in the world, and hands the result back through the request's [`ViewOutput`].

use super::filter::FilterChain;
use super::image::Pixels;
use super::virtual_view::ViewOutput;

#[derive(Debug, Clone, PartialEq)]
pub struct FilteredPicture {
    pub pixels: Pixels,
    pub filters: FilterChain,
    /// Where the filtered picture (RGBA, rows bottom-up) is left.
    pub output: ViewOutput,
}
