//! The built-in kernels computed on the CPU, pass by pass as the GPU runs them (rounded to
//! bytes after every pass, edges clamped), so that the tests can check what GL drew against
//! sums written a second, independent way. Slow and plain on purpose.

use framework::scene::{FilterChain, Kernel};

/// An RGBA picture of floats 0–1, rows as given.
struct Picture {
    width: usize,
    height: usize,
    pixels: Vec<[f32; 4]>,
}

impl Picture {
    /// The pixel at (x, y), the nearest edge pixel outside.
    fn at(&self, x: isize, y: isize) -> [f32; 4] {
        let x = x.clamp(0, self.width as isize - 1) as usize;
        let y = y.clamp(0, self.height as isize - 1) as usize;
        self.pixels[y * self.width + x]
    }

    /// A new picture of `f` at every pixel, each channel stored as a byte would store it.
    fn map(&self, f: impl Fn(isize, isize) -> [f32; 4]) -> Picture {
        let mut pixels = Vec::with_capacity(self.pixels.len());
        for y in 0..self.height as isize {
            for x in 0..self.width as isize {
                pixels.push(f(x, y).map(quantize));
            }
        }
        Picture {
            width: self.width,
            height: self.height,
            pixels,
        }
    }
}

/// What an 8-bit colour attachment keeps of a value: clamped, to the nearest 1/255.
fn quantize(v: f32) -> f32 {
    (v.clamp(0.0, 1.0) * 255.0).round() / 255.0
}

/// A grey picture as the renderer's swizzle shows it: grey, grey, grey, opaque.
pub fn gray_to_rgba(gray: &[u8]) -> Vec<u8> {
    gray.iter().flat_map(|&g| [g, g, g, u8::MAX]).collect()
}

/// `chain` applied to a `width` × `height` RGBA picture; `None` if it holds a GLSL kernel,
/// which only the GPU runs.
pub fn apply(width: u32, height: u32, rgba: &[u8], chain: &FilterChain) -> Option<Vec<u8>> {
    let mut picture = Picture {
        width: width as usize,
        height: height as usize,
        pixels: rgba
            .chunks_exact(4)
            .map(|p| [0, 1, 2, 3].map(|i| f32::from(p[i]) / 255.0))
            .collect(),
    };
    for kernel in chain.kernels() {
        picture = match kernel {
            Kernel::Blur { radius } => separable(&picture, *radius, |samples| {
                let n = samples.len() as f32;
                [0, 1, 2, 3].map(|c| samples.iter().map(|p| p[c]).sum::<f32>() / n)
            }),
            Kernel::Erode { radius } => separable(&picture, *radius, |samples| {
                [0, 1, 2, 3].map(|c| samples.iter().map(|p| p[c]).fold(f32::MAX, f32::min))
            }),
            Kernel::Dilate { radius } => separable(&picture, *radius, |samples| {
                [0, 1, 2, 3].map(|c| samples.iter().map(|p| p[c]).fold(f32::MIN, f32::max))
            }),
            Kernel::Sharpen { amount } => picture.map(|x, y| {
                let (c, ring) = (picture.at(x, y), ring(&picture, x, y));
                let s = |i: usize| c[i] + amount * (4.0 * c[i] - ring[i]);
                [s(0), s(1), s(2), c[3]]
            }),
            Kernel::Laplacian => picture.map(|x, y| {
                let (c, ring) = (picture.at(x, y), ring(&picture, x, y));
                let l = |i: usize| (4.0 * c[i] - ring[i]).abs();
                [l(0), l(1), l(2), c[3]]
            }),
            Kernel::SobelEdges => picture.map(|x, y| {
                let l = |dx: isize, dy: isize| luma(picture.at(x + dx, y + dy));
                let gx = l(1, -1) + 2.0 * l(1, 0) + l(1, 1) - l(-1, -1) - 2.0 * l(-1, 0) - l(-1, 1);
                let gy = l(-1, 1) + 2.0 * l(0, 1) + l(1, 1) - l(-1, -1) - 2.0 * l(0, -1) - l(1, -1);
                let m = gx.hypot(gy);
                [m, m, m, picture.at(x, y)[3]]
            }),
            Kernel::Glsl(_) => return None,
        };
    }
    Some(
        picture
            .pixels
            .iter()
            .flat_map(|p| p.map(|v| (v * 255.0).round() as u8))
            .collect(),
    )
}

fn luma(p: [f32; 4]) -> f32 {
    0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]
}

fn ring(p: &Picture, x: isize, y: isize) -> [f32; 4] {
    let n = [
        p.at(x + 1, y),
        p.at(x - 1, y),
        p.at(x, y + 1),
        p.at(x, y - 1),
    ];
    [0, 1, 2, 3].map(|c| n.iter().map(|q| q[c]).sum())
}

/// `combine` over `2r + 1` pixels along rows, then along columns; unchanged for r = 0.
fn separable(p: &Picture, radius: u32, combine: impl Fn(&[[f32; 4]]) -> [f32; 4]) -> Picture {
    if radius == 0 {
        return p.map(|x, y| p.at(x, y));
    }
    let r = radius as isize;
    let rows = p.map(|x, y| {
        let samples: Vec<[f32; 4]> = (-r..=r).map(|i| p.at(x + i, y)).collect();
        combine(&samples)
    });
    rows.map(|x, y| {
        let samples: Vec<[f32; 4]> = (-r..=r).map(|i| rows.at(x, y + i)).collect();
        combine(&samples)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gray(width: u32, values: &[u8], chain: Vec<Kernel>) -> Vec<u8> {
        let height = values.len() as u32 / width;
        let out = apply(width, height, &gray_to_rgba(values), &FilterChain(chain)).unwrap();
        out.chunks_exact(4).map(|p| p[0]).collect()
    }

    #[test]
    fn a_bright_dot_grows_under_dilation_and_vanishes_under_erosion() {
        let mut dot = vec![0u8; 25];
        dot[12] = 255;
        let grown = gray(5, &dot, vec![Kernel::Dilate { radius: 1 }]);
        assert_eq!(
            grown.iter().filter(|&&v| v == 255).count(),
            9,
            "a 3 × 3 square"
        );
        assert!(
            gray(5, &dot, vec![Kernel::Erode { radius: 1 }])
                .iter()
                .all(|&v| v == 0)
        );
    }

    #[test]
    fn blur_keeps_the_mean_of_a_flat_picture_and_edges_find_a_step() {
        assert!(
            gray(4, &[100; 16], vec![Kernel::Blur { radius: 2 }])
                .iter()
                .all(|&v| v == 100)
        );
        let step: Vec<u8> = (0..16).map(|i| if i % 4 < 2 { 0 } else { 255 }).collect();
        let edges = gray(4, &step, vec![Kernel::SobelEdges]);
        assert_eq!(
            &edges[..4],
            &[0, 255, 255, 0],
            "the step lies between columns 1 and 2"
        );
        let laplacian = gray(4, &step, vec![Kernel::Laplacian]);
        assert_eq!(&laplacian[..4], &[0, 255, 255, 0]);
    }
}
