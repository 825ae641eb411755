//! A scene label written as math (`$v = \omega r$`) is drawn typeset, in the label's colour on
//! a transparent background, not as its raw text; one that does not typeset falls back to its
//! raw text.

use eframe::egui;
use framework::scene::{Object3D, Rgba, Scene};
use glam::Vec3;
use image::RgbaImage;
use pv3d::app::View3d;
use pv3d::headless::HeadlessUi;

const YELLOW: Rgba = Rgba::rgb(255, 224, 112);

/// The 3-D view of a scene holding one label at the origin, in the top view.
fn render_label(text: &str) -> RgbaImage {
    let mut scene = Scene::new();
    let mut node = Object3D::new("label");
    node.geometry.label(Vec3::ZERO, text, YELLOW);
    scene.add(node);
    let mut ui = HeadlessUi::new(320, 240).expect("headless GL (Mesa EGL)");
    let mut view = View3d::default();
    view.camera.distance = 8.0;
    for _ in 0..3 {
        ui.run(|ui| {
            egui::CentralPanel::default().show(ui, |ui| {
                view.show(ui, &scene);
            });
        });
    }
    ui.read_pixels()
}

/// The bounding box (min x, min y, max x, max y) of the pixels unlike `background`.
fn ink_bounds(image: &RgbaImage, background: image::Rgba<u8>) -> Option<(u32, u32, u32, u32)> {
    image
        .enumerate_pixels()
        .filter(|(_, _, p)| **p != background)
        .fold(None, |b, (x, y, _)| {
            Some(match b {
                None => (x, y, x, y),
                Some((x0, y0, x1, y1)) => (x0.min(x), y0.min(y), x1.max(x), y1.max(y)),
            })
        })
}

#[test]
fn a_math_label_is_typeset_on_a_transparent_background() {
    let math = render_label(r"$v = \omega r$");
    let raw = render_label(r"v = \omega r");
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    math.save(out.join("math_label.png")).unwrap();
    raw.save(out.join("raw_label.png")).unwrap();

    // The view's background, away from the label.
    let background = *math.get_pixel(math.width() / 2 + 100, 30);
    assert_eq!(*raw.get_pixel(raw.width() / 2 + 100, 30), background);
    let (x0, y0, x1, y1) = ink_bounds(&math, background).expect("the formula is drawn");
    let (w, h) = (x1 - x0 + 1, y1 - y0 + 1);
    // Next to its point, the middle of the view: a formula a few dozen pixels wide, one line.
    let (cx, cy) = (math.width() / 2, math.height() / 2);
    assert!(
        x0.abs_diff(cx) < 20 && y1.abs_diff(cy) < 20,
        "at the label's point: {x0},{y0}–{x1},{y1}"
    );
    assert!((31..200).contains(&w) && (6..60).contains(&h), "{w} × {h}");

    // Not the raw text: different pixels, and no backslash-omega spelled out (the raw text
    // is wider than the typeset ω).
    assert_ne!(math, raw, "typeset, not raw text");
    let (rx0, _, rx1, _) = ink_bounds(&raw, background).expect("raw text drawn");
    assert!(
        rx1 - rx0 + 1 > w,
        "the raw text is the wider: {} vs {w}",
        rx1 - rx0 + 1
    );

    // Transparent: between the glyphs the background shows, and the ink is the label's
    // colour blended over it, never a box of another colour.
    let inside: Vec<image::Rgba<u8>> = (y0..=y1)
        .flat_map(|y| (x0..=x1).map(move |x| (x, y)))
        .map(|(x, y)| *math.get_pixel(x, y))
        .collect();
    let clear = inside.iter().filter(|p| **p == background).count();
    assert!(
        clear * 3 > inside.len(),
        "mostly background within the formula's bounds: {clear} of {}",
        inside.len()
    );
    let inked = inside
        .iter()
        .filter(|p| p[0] > 200 && p[1] > 170 && p[2] < 150)
        .count();
    assert!(inked > 20, "ink in the label's yellow: {inked}");
    // Every pixel a mix of the background and the yellow: t of the way from one to the other.
    let mix = |p: &image::Rgba<u8>| {
        let (bg, ink) = (background.0.map(f32::from), YELLOW.0.map(f32::from));
        let t = ((f32::from(p[0]) - bg[0]) / (ink[0] - bg[0])).clamp(0.0, 1.0);
        (0..3).all(|c| (bg[c] + t * (ink[c] - bg[c]) - f32::from(p[c])).abs() <= 16.0)
    };
    let foreign: Vec<_> = inside.iter().filter(|p| !mix(p)).collect();
    assert!(
        foreign.is_empty(),
        "only yellow over the background: {foreign:?}"
    );
}

#[test]
fn a_formula_that_does_not_typeset_shows_its_raw_text() {
    let broken = render_label(r"$\frac{1}{$");
    let plain = render_label(r"\frac{1}{");
    let background = *broken.get_pixel(broken.width() / 2 + 100, 30);
    let (x0, y0, x1, y1) = ink_bounds(&broken, background).expect("something is drawn");
    let (px0, py0, px1, py1) = ink_bounds(&plain, background).expect("the text is drawn");
    // The same text with its two dollar signs: a little wider, as tall, where the text is.
    let (w, pw) = (x1 - x0 + 1, px1 - px0 + 1);
    assert!(
        w > pw && w < pw + 30,
        "raw text: {w} vs {pw} without the dollars"
    );
    assert!(
        (y1 - y0).abs_diff(py1 - py0) <= 3,
        "{y0}–{y1} vs {py0}–{py1}"
    );
    assert!(x0.abs_diff(px0) <= 1, "from the same point");
}
