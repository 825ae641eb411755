//! Filter chains on the GPU: each kernel of a scene picture's [`FilterChain`] becomes one or
//! two fragment passes (separable kernels run along rows, then columns), drawn into
//! ping-pong textures the size of the picture. The result is cached by the picture renderer
//! until the picture or its chain changes; [`reference`] computes the same on the CPU for the
//! tests.
//!
//! [`FilterChain`]: framework::scene::FilterChain

pub mod reference;
mod runner;
mod sources;

use std::sync::Arc;

use framework::scene::Kernel;

pub use runner::KernelRunner;

use super::gl_error::GlError;
use super::texture::TextureError;

/// Why a chain could not run.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum KernelError {
    #[error("kernel {kernel} does not compile: {source}")]
    Compile { kernel: String, source: GlError },
    #[error("kernel {kernel}: {source}")]
    Texture {
        kernel: String,
        source: TextureError,
    },
    #[error("kernel {kernel}: {source}")]
    Gl { kernel: String, source: GlError },
}

/// Which shader a pass runs.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
enum ShaderKey {
    BoxBlur,
    MinMax,
    Sharpen,
    Laplacian,
    Sobel,
    /// A kernel from a file, by its source.
    Glsl(Arc<str>),
}

/// A uniform's value.
#[derive(Debug, Clone, PartialEq)]
enum Uniform {
    Int(i32),
    Step([i32; 2]),
    Float(f32),
}

/// One fragment pass of a kernel.
#[derive(Debug, Clone, PartialEq)]
struct Pass {
    shader: ShaderKey,
    uniforms: Vec<(String, Uniform)>,
    /// The kernel's name, for errors.
    kernel: String,
}

const ALONG_ROWS: [i32; 2] = [1, 0];
const ALONG_COLUMNS: [i32; 2] = [0, 1];

/// The passes that run `kernel`; none for one that changes nothing (a radius of 0).
fn passes_of(kernel: &Kernel) -> Vec<Pass> {
    let pass = |shader: ShaderKey, uniforms: Vec<(&str, Uniform)>| Pass {
        shader,
        uniforms: uniforms
            .into_iter()
            .map(|(n, u)| (n.to_string(), u))
            .collect(),
        kernel: kernel.name().to_string(),
    };
    let separable = |shader: ShaderKey, radius: u32, extra: Vec<(&str, Uniform)>| {
        if radius == 0 {
            return Vec::new();
        }
        let radius = Uniform::Int(i32::try_from(radius).unwrap_or(i32::MAX));
        [ALONG_ROWS, ALONG_COLUMNS]
            .into_iter()
            .map(|step| {
                let mut uniforms = vec![
                    ("u_step", Uniform::Step(step)),
                    ("u_radius", radius.clone()),
                ];
                uniforms.extend(extra.iter().cloned());
                pass(shader.clone(), uniforms)
            })
            .collect()
    };
    match kernel {
        Kernel::Blur { radius } => separable(ShaderKey::BoxBlur, *radius, vec![]),
        Kernel::Erode { radius } => separable(
            ShaderKey::MinMax,
            *radius,
            vec![("u_take_max", Uniform::Int(0))],
        ),
        Kernel::Dilate { radius } => separable(
            ShaderKey::MinMax,
            *radius,
            vec![("u_take_max", Uniform::Int(1))],
        ),
        Kernel::Sharpen { amount } => vec![pass(
            ShaderKey::Sharpen,
            vec![("u_amount", Uniform::Float(*amount))],
        )],
        Kernel::Laplacian => vec![pass(ShaderKey::Laplacian, vec![])],
        Kernel::SobelEdges => vec![pass(ShaderKey::Sobel, vec![])],
        Kernel::Glsl(glsl) => vec![Pass {
            shader: ShaderKey::Glsl(glsl.source.clone()),
            uniforms: glsl
                .params
                .iter()
                .map(|(n, v)| (n.clone(), Uniform::Float(*v)))
                .collect(),
            kernel: glsl.name.clone(),
        }],
    }
}

/// The kernel source of a shader, between the prelude and `main`.
fn kernel_source(shader: &ShaderKey) -> String {
    match shader {
        ShaderKey::BoxBlur => sources::BOX_BLUR.to_string(),
        ShaderKey::MinMax => sources::MIN_MAX.to_string(),
        ShaderKey::Sharpen => sources::sharpen(),
        ShaderKey::Laplacian => sources::laplacian(),
        ShaderKey::Sobel => sources::SOBEL.to_string(),
        ShaderKey::Glsl(source) => source.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn separable_kernels_take_two_passes_and_a_zero_radius_none() {
        assert_eq!(passes_of(&Kernel::Blur { radius: 2 }).len(), 2);
        let dilate = passes_of(&Kernel::Dilate { radius: 3 });
        assert_eq!(dilate[0].uniforms[0].1, Uniform::Step(ALONG_ROWS));
        assert_eq!(dilate[1].uniforms[0].1, Uniform::Step(ALONG_COLUMNS));
        assert!(
            dilate[1]
                .uniforms
                .contains(&("u_take_max".into(), Uniform::Int(1)))
        );
        assert!(passes_of(&Kernel::Erode { radius: 0 }).is_empty());
        assert_eq!(passes_of(&Kernel::SobelEdges).len(), 1);
    }
}
