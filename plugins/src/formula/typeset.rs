//! LaTeX math typeset to a picture with a transparent background, for labels and billboards in
//! the world: `$v = \omega r$` next to a robot in a classroom.
//!
//! `latex-rust` does the typesetting: pure Rust with the STIX Two Math font built in, so no TeX
//! installation, no JavaScript engine and no system font is needed, and a formula that does not
//! parse comes back as an error rather than a wrong picture.

use std::sync::OnceLock;

use framework::scene::{PixelFormat, Pixels, Rgba};
use latex_rust::{Dim, MathFont, PngBackground, PngOptions};

pub use super::error::FormulaError;
pub use super::resolution::{DEFAULT_DPI, FONT_SIZE_PT, MAX_DPI, dpi_for_em};

/// The math between a label's dollar signs (`$…$`), or `None` for plain text.
pub fn math_of(text: &str) -> Option<&str> {
    let inner = text.trim().strip_prefix('$')?.strip_suffix('$')?;
    let inner = inner.trim();
    (!inner.is_empty()).then_some(inner)
}

/// The font, read once: parsing its tables for every label would be wasted work.
fn font() -> Result<&'static MathFont, FormulaError> {
    static FONT: OnceLock<Result<MathFont, String>> = OnceLock::new();
    FONT.get_or_init(|| MathFont::stix_two_math().map_err(|e| e.to_string()))
        .as_ref()
        .map_err(|e| FormulaError::Font(e.clone()))
}

/// `text` (`$…$`) typeset in `colour` at `dpi`, on a transparent background, rows bottom-up
/// as the scene's pictures are. Typeset once per process: the same arguments again give the
/// same picture (see [`super::cache`]).
pub fn typeset(text: &str, colour: Rgba, dpi: u32) -> Result<Pixels, FormulaError> {
    super::cache::typeset_once(text, colour, dpi, || typeset_now(text, colour, dpi))
}

fn typeset_now(text: &str, colour: Rgba, dpi: u32) -> Result<Pixels, FormulaError> {
    let latex = math_of(text).ok_or_else(|| FormulaError::NotMath { text: text.into() })?;
    if !(1..=MAX_DPI).contains(&dpi) {
        return Err(FormulaError::BadResolution(dpi));
    }
    let [r, g, b, alpha] = colour.0;
    let options = PngOptions {
        font_size_pt: Dim::from_i64(i64::from(FONT_SIZE_PT)),
        dpi: Dim::from_i64(i64::from(dpi)),
        color: latex_rust::Color::rgb(r, g, b),
        background: PngBackground::Transparent,
        ..PngOptions::new()
    };
    let png =
        latex_rust::latex_to_png(latex, font()?, &options).map_err(|e| FormulaError::Typeset {
            latex: latex.into(),
            reason: e.to_string(),
        })?;
    let mut image = image::load_from_memory_with_format(&png, image::ImageFormat::Png)
        .map_err(|e| FormulaError::Decode(e.to_string()))?
        .to_rgba8();
    if alpha != u8::MAX {
        for p in image.pixels_mut() {
            p[3] = (u16::from(p[3]) * u16::from(alpha) / u16::from(u8::MAX)) as u8;
        }
    }
    image::imageops::flip_vertical_in_place(&mut image);
    let (w, h) = image.dimensions();
    Pixels::new(w, h, PixelFormat::Rgba8, image.into_raw())
        .map_err(|e| FormulaError::Decode(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_formula_renders_ink_on_a_transparent_background() {
        let pixels = typeset(r"$v = \omega r$", Rgba::WHITE, DEFAULT_DPI).unwrap();
        assert!(
            pixels.width() > pixels.height(),
            "a formula on one line is wide"
        );
        let alphas: Vec<u8> = pixels.bytes().chunks_exact(4).map(|p| p[3]).collect();
        let inked = alphas.iter().filter(|&&a| a > 200).count();
        let clear = alphas.iter().filter(|&&a| a == 0).count();
        assert!(inked > 50, "some ink: {inked} pixels");
        assert!(
            clear > alphas.len() / 2,
            "mostly transparent: {clear} of {}",
            alphas.len()
        );
        let corner = &pixels.bytes()[..4];
        assert_eq!(corner[3], 0, "the background is transparent: {corner:?}");
        let ink = pixels
            .bytes()
            .chunks_exact(4)
            .find(|p| p[3] == u8::MAX)
            .unwrap();
        assert_eq!(&ink[..3], &[255, 255, 255], "ink in the colour asked for");
    }

    #[test]
    fn a_formula_is_typeset_once_and_its_picture_shared() {
        let text = r"$\sum_{i=1}^{1024} robot_i$";
        let first = typeset(text, Rgba::WHITE, DEFAULT_DPI).unwrap();
        let again = typeset(text, Rgba::WHITE, DEFAULT_DPI).unwrap();
        assert_eq!(first.generation(), again.generation(), "one picture");
        let (kept, bytes) = super::super::cache::kept_now();
        assert!(kept >= 1 && bytes >= first.bytes().len());
        let other_colour = typeset(text, Rgba([255, 0, 0, 255]), DEFAULT_DPI).unwrap();
        assert_ne!(other_colour.generation(), first.generation());
        // Errors are kept too, and stay errors.
        let broken = r"$\frac{1}{$";
        assert_eq!(
            typeset(broken, Rgba::WHITE, DEFAULT_DPI),
            typeset(broken, Rgba::WHITE, DEFAULT_DPI)
        );
    }

    #[test]
    fn text_without_dollars_or_broken_math_is_a_clear_error() {
        assert!(matches!(
            typeset("v = wr", Rgba::WHITE, DEFAULT_DPI),
            Err(FormulaError::NotMath { .. })
        ));
        let broken = typeset(r"$\frac{1}{$", Rgba::WHITE, DEFAULT_DPI).unwrap_err();
        assert!(matches!(broken, FormulaError::Typeset { .. }), "{broken}");
        assert!(broken.to_string().contains(r"\frac"), "{broken}");
        assert!(matches!(
            typeset("$x$", Rgba::WHITE, 0),
            Err(FormulaError::BadResolution(0))
        ));
    }

    #[test]
    fn only_text_between_dollars_is_math() {
        assert_eq!(math_of(r" $v = \omega r$ "), Some(r"v = \omega r"));
        assert_eq!(math_of("$$"), None);
        assert_eq!(math_of("speed"), None);
    }
}
