//! Image filters a plugin asks for, as data: which kernels, in which order, with which
//! parameters. `pv3d` runs them on the GPU as fragment passes; here they are only named, so
//! that a plugin stays free of OpenGL and a test can compare chains.
//!
//! The built-ins sample outside the picture as its nearest edge pixel (clamp to edge).

use std::sync::Arc;

/// The widest neighbourhood a kernel may look at, pixels from the centre: beyond it a pass on
/// a large map costs seconds on a software renderer, and no use here needs more.
pub const MAX_KERNEL_RADIUS: u32 = 64;

/// One filter of a chain.
#[derive(Debug, Clone, PartialEq)]
pub enum Kernel {
    /// The mean of a (2r+1)² square, in two passes (rows, then columns).
    Blur { radius: u32 },
    /// The centre pushed away from its four neighbours: `c + amount · (4c − n − s − e − w)`.
    Sharpen { amount: f32 },
    /// The Sobel gradient magnitude of the luminance, as grey.
    SobelEdges,
    /// `|4c − n − s − e − w|` per channel: where brightness bends.
    Laplacian,
    /// The minimum of a (2r+1)² square, per channel: dark regions grow.
    Erode { radius: u32 },
    /// The maximum of a (2r+1)² square, per channel: bright regions grow.
    Dilate { radius: u32 },
    /// A kernel written in GLSL (see [`GlslKernel`]).
    Glsl(GlslKernel),
}

/// Every built-in kernel by the name a composition uses.
pub const BUILTIN_NAMES: [&str; 6] = ["blur", "sharpen", "sobel", "laplacian", "erode", "dilate"];

impl Kernel {
    /// The built-in called `name` with its default parameters (radius 1, amount 1).
    pub fn builtin(name: &str) -> Option<Kernel> {
        Some(match name {
            "blur" => Kernel::Blur { radius: 1 },
            "sharpen" => Kernel::Sharpen { amount: 1.0 },
            "sobel" => Kernel::SobelEdges,
            "laplacian" => Kernel::Laplacian,
            "erode" => Kernel::Erode { radius: 1 },
            "dilate" => Kernel::Dilate { radius: 1 },
            _ => return None,
        })
    }

    /// The name shown in labels and logs (a GLSL kernel's file).
    pub fn name(&self) -> &str {
        match self {
            Kernel::Blur { .. } => "blur",
            Kernel::Sharpen { .. } => "sharpen",
            Kernel::SobelEdges => "sobel",
            Kernel::Laplacian => "laplacian",
            Kernel::Erode { .. } => "erode",
            Kernel::Dilate { .. } => "dilate",
            Kernel::Glsl(k) => &k.name,
        }
    }

    /// The radius of a kernel that has one, to set it.
    pub fn radius_mut(&mut self) -> Option<&mut u32> {
        match self {
            Kernel::Blur { radius } | Kernel::Erode { radius } | Kernel::Dilate { radius } => {
                Some(radius)
            }
            _ => None,
        }
    }
}

/// A kernel in GLSL, from a file named in the composition.
///
/// The source defines `vec4 filter_pixel(ivec2 at)`, the output for the pixel at column,
/// row `at`. It may call `vec4 pixel(ivec2 at)` (the input, clamped to its edges), read
/// `u_image` (a `sampler2D`) and `v_uv` (0–1 across the picture), and declare
/// `uniform float NAME;` for each of its parameters. The renderer adds the `#version` line,
/// those declarations and `main`.
#[derive(Debug, Clone, PartialEq)]
pub struct GlslKernel {
    /// Where the source came from (its path), for labels and compile errors.
    pub name: String,
    pub source: Arc<str>,
    /// Values for the source's `uniform float` parameters.
    pub params: Vec<(String, f32)>,
}

/// Kernels applied one after the other.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FilterChain(pub Vec<Kernel>);

impl FilterChain {
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    pub fn kernels(&self) -> &[Kernel] {
        &self.0
    }

    /// The kernels' names joined by `→`, for labels: `dilate → sobel`.
    pub fn describe(&self) -> String {
        let names: Vec<&str> = self.0.iter().map(Kernel::name).collect();
        names.join(" → ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_builtin_name_makes_its_kernel_and_names_it_back() {
        for name in BUILTIN_NAMES {
            let kernel = Kernel::builtin(name).unwrap();
            assert_eq!(kernel.name(), name);
        }
        assert!(Kernel::builtin("emboss").is_none());
    }

    #[test]
    fn chains_compare_by_kernel_and_parameter() {
        let a = FilterChain(vec![Kernel::Dilate { radius: 3 }, Kernel::SobelEdges]);
        let mut b = a.clone();
        assert_eq!(a, b);
        *b.0[0].radius_mut().unwrap() = 4;
        assert_ne!(a, b, "a new radius is a new chain, filtered again");
        assert_eq!(a.describe(), "dilate → sobel");
        assert!(Kernel::SobelEdges.clone().radius_mut().is_none());
    }
}
