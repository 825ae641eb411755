//! Every built-in kernel run through GL on Mesa's software renderer agrees with the CPU
//! reference within a byte or two (the GPU's float sums round differently in the last bit);
//! a GLSL file kernel runs with its parameters; one that does not compile says which and
//! where.

use std::sync::Arc;

use eframe::glow::{self, HasContext};
use framework::scene::{FilterChain, GlslKernel, Kernel, PixelFormat, Pixels};
use pv3d::headless::HeadlessGl;
use pv3d::render::gl_error::GlError;
use pv3d::render::kernels::{KernelError, KernelRunner, reference};
use pv3d::render::texture::{self, GpuTexture};

/// The most a channel may differ from the reference, out of 255.
const TOLERANCE: u8 = 2;

/// A picture with smooth gradients, hard edges, a thin line and a dot, so that every kernel
/// has something to change.
fn test_picture(width: u32, height: u32) -> Vec<u8> {
    let mut rgba = Vec::with_capacity((width * height * 4) as usize);
    for y in 0..height {
        for x in 0..width {
            let inside_square = (10..26).contains(&x) && (8..20).contains(&y);
            let on_line = x == 40 || (x + y) % 17 == 0;
            let dot = x == 50 && y == 30;
            let (r, g, b) = if dot {
                (255, 255, 255)
            } else if inside_square {
                (220, 40, 30)
            } else if on_line {
                (20, 20, 200)
            } else {
                ((x * 4) as u8, (y * 5) as u8, ((x * y) % 256) as u8)
            };
            rgba.extend_from_slice(&[r, g, b, 255]);
        }
    }
    rgba
}

/// The texture's pixels, rows as uploaded (bottom-up).
fn read_texture(gl: &glow::Context, texture: &GpuTexture) -> Vec<u8> {
    let mut out = vec![0u8; (texture.width * texture.height * 4) as usize];
    // SAFETY: a framebuffer made and deleted here; the buffer holds exactly the texture.
    unsafe {
        let fbo = gl.create_framebuffer().unwrap();
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        gl.framebuffer_texture_2d(
            glow::FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::TEXTURE_2D,
            Some(texture.texture),
            0,
        );
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
        gl.read_pixels(
            0,
            0,
            texture.width as i32,
            texture.height as i32,
            glow::RGBA,
            glow::UNSIGNED_BYTE,
            glow::PixelPackData::Slice(Some(&mut out)),
        );
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.delete_framebuffer(fbo);
    }
    out
}

/// Runs `chain` over `pixels` through GL and returns the result's bytes.
fn on_gpu(
    gl: &HeadlessGl,
    runner: &mut KernelRunner,
    pixels: &Pixels,
    chain: &FilterChain,
) -> Vec<u8> {
    let source = texture::upload(&gl.gl, pixels).expect("upload");
    let filtered = runner
        .run(&gl.gl, &source, chain)
        .expect("the chain runs")
        .expect("the chain changes the picture");
    let out = read_texture(&gl.gl, &filtered);
    // SAFETY: textures made for this test.
    unsafe {
        gl.gl.delete_texture(source.texture);
        gl.gl.delete_texture(filtered.texture);
    }
    out
}

/// The largest channel difference and where it is.
fn worst_difference(a: &[u8], b: &[u8], width: u32) -> (u8, (u32, u32)) {
    let mut worst = (0, (0, 0));
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        let d = x.abs_diff(*y);
        if d > worst.0 {
            let pixel = i as u32 / 4;
            worst = (d, (pixel % width, pixel / width));
        }
    }
    worst
}

#[test]
fn every_builtin_agrees_with_the_cpu_reference() {
    let (w, h) = (61, 37); // odd sizes: rows not a multiple of 4 bytes, no symmetry to hide in
    let gl = HeadlessGl::new(8, 8).expect("headless GL (Mesa EGL)");
    let mut runner = KernelRunner::new(&gl.gl).expect("runner");
    let rgba = test_picture(w, h);
    let pixels = Pixels::new(w, h, PixelFormat::Rgba8, rgba.clone()).unwrap();
    let chains = [
        vec![Kernel::Blur { radius: 2 }],
        vec![Kernel::Sharpen { amount: 0.8 }],
        vec![Kernel::SobelEdges],
        vec![Kernel::Laplacian],
        vec![Kernel::Erode { radius: 1 }],
        vec![Kernel::Dilate { radius: 3 }],
        vec![
            Kernel::Dilate { radius: 2 },
            Kernel::SobelEdges,
            Kernel::Blur { radius: 1 },
        ],
    ];
    for kernels in chains {
        let chain = FilterChain(kernels);
        let gpu = on_gpu(&gl, &mut runner, &pixels, &chain);
        let cpu = reference::apply(w, h, &rgba, &chain).unwrap();
        assert_ne!(
            cpu,
            rgba,
            "{}: the test picture must change",
            chain.describe()
        );
        let (worst, at) = worst_difference(&gpu, &cpu, w);
        assert!(
            worst <= TOLERANCE,
            "{}: differs by {worst} at {at:?}",
            chain.describe()
        );
    }
    runner.destroy(&gl.gl);
}

#[test]
fn a_grey_grid_is_filtered_as_grey() {
    // An occupancy grid: free 230, unknown 150, one occupied cell 30. Erosion grows the dark
    // obstacle into a square, as a robot's configuration space.
    let (w, h) = (9, 7);
    let mut grid = vec![230u8; (w * h) as usize];
    grid[..9].fill(150);
    grid[(3 * w + 4) as usize] = 30;
    let gl = HeadlessGl::new(8, 8).expect("headless GL (Mesa EGL)");
    let mut runner = KernelRunner::new(&gl.gl).expect("runner");
    let pixels = Pixels::new(w, h, PixelFormat::Gray8, grid.clone()).unwrap();
    let chain = FilterChain(vec![Kernel::Erode { radius: 1 }]);
    let gpu = on_gpu(&gl, &mut runner, &pixels, &chain);
    let cpu = reference::apply(w, h, &reference::gray_to_rgba(&grid), &chain).unwrap();
    assert_eq!(gpu, cpu, "min and max are exact");
    let dark = gpu.chunks_exact(4).filter(|p| p[0] == 30).count();
    assert_eq!(dark, 9, "one occupied cell grows to 3 × 3");
    runner.destroy(&gl.gl);
}

#[test]
fn a_glsl_kernel_runs_with_its_parameters_and_a_broken_one_is_named() {
    let gl = HeadlessGl::new(8, 8).expect("headless GL (Mesa EGL)");
    let mut runner = KernelRunner::new(&gl.gl).expect("runner");
    let pixels = Pixels::new(
        2,
        1,
        PixelFormat::Rgba8,
        vec![100, 50, 0, 255, 200, 10, 20, 255],
    )
    .unwrap();
    let invert = FilterChain(vec![Kernel::Glsl(GlslKernel {
        name: "configs/kernels/scale.glsl".into(),
        source: Arc::from(
            "uniform float gain;\nvec4 filter_pixel(ivec2 at) {\n    return vec4(pixel(at).rgb * gain, 1.0);\n}\n",
        ),
        params: vec![("gain".into(), 0.5)],
    })]);
    let out = on_gpu(&gl, &mut runner, &pixels, &invert);
    assert_eq!(out, [50, 25, 0, 255, 100, 5, 10, 255]);

    let broken = FilterChain(vec![Kernel::Glsl(GlslKernel {
        name: "configs/kernels/broken.glsl".into(),
        source: Arc::from("vec4 filter_pixel(ivec2 at) {\n    return pixel(at) * ;\n}\n"),
        params: vec![],
    })]);
    let source = texture::upload(&gl.gl, &pixels).unwrap();
    let err = runner.run(&gl.gl, &source, &broken).unwrap_err();
    let KernelError::Compile {
        kernel,
        source: GlError::Compile { stage, log },
    } = &err
    else {
        panic!("{err}");
    };
    assert_eq!(*stage, "fragment shader");
    assert_eq!(kernel, "configs/kernels/broken.glsl");
    // The driver's log counts lines from the kernel's own first line: the error is on line 2.
    assert!(log.contains(":2("), "{log}");
    assert!(
        err.to_string()
            .starts_with("kernel configs/kernels/broken.glsl does not compile")
    );
    runner.destroy(&gl.gl);
}
