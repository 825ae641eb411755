//! LaTeX math in the viewer's own text: a scene label or an item-tree title written between
//! dollar signs is shown as the typeset formula, an egui texture with a transparent background.
//!
//! Typesetting takes milliseconds, and labels are drawn on every frame, so each distinct
//! (text, colour, size) is typeset once and its texture kept; a formula that does not typeset
//! is remembered too, warned about once and shown as its raw text. The typesetting itself is
//! the formula plugin's (`plugins::formula::typeset`): pv3d already depends on the plugins, and
//! keeping `latex-rust` and its embedded font out of `framework` keeps every other plugin's
//! dependency light.

use std::collections::HashMap;

use eframe::egui;
use framework::scene::{PixelFormat, Pixels, Rgba};
use plugins::formula::typeset::{self, FormulaError};

/// How a formula becomes pixels: `plugins::formula::typeset::typeset` but in the tests.
pub type Typesetter = fn(&str, Rgba, u32) -> Result<Pixels, FormulaError>;

/// More distinct formulas than this (a plugin writing a new number into a math label on every
/// frame) and the oldest are forgotten: the cache is for a classroom's handful.
const MAX_FORMULAS: usize = 256;

#[derive(Debug, Clone, PartialEq, Eq, Hash)]
struct Key {
    text: String,
    colour: [u8; 4],
    /// The em in physical pixels: a new zoom of the UI typesets again, sharp.
    em_px: u32,
}

/// A typeset formula ready for egui.
#[derive(Clone)]
pub struct Formula {
    pub texture: egui::TextureHandle,
    /// Its size in points at the scale it was typeset for.
    pub size: egui::Vec2,
}

/// The typeset formulas shown so far, by text, colour and size.
pub struct FormulaTextures {
    typeset: Typesetter,
    /// `None`: it did not typeset (warned once); shown as raw text.
    formulas: HashMap<Key, Option<Formula>>,
    /// Keys in the order they were first typeset, for forgetting the oldest.
    order: Vec<Key>,
}

impl Default for FormulaTextures {
    fn default() -> Self {
        FormulaTextures::with_typesetter(typeset::typeset)
    }
}

impl FormulaTextures {
    pub fn with_typesetter(typeset: Typesetter) -> FormulaTextures {
        FormulaTextures {
            typeset,
            formulas: HashMap::new(),
            order: Vec::new(),
        }
    }

    /// `text` typeset in `colour` with an em of `em_points`, if it is math (`$…$`) and
    /// typesets; `None` means: draw the text as it is.
    pub fn get(
        &mut self,
        ctx: &egui::Context,
        text: &str,
        colour: Rgba,
        em_points: f32,
    ) -> Option<Formula> {
        typeset::math_of(text)?;
        let scale = ctx.pixels_per_point();
        let key = Key {
            text: text.to_string(),
            colour: colour.0,
            em_px: (em_points * scale).round().max(1.0) as u32,
        };
        if let Some(known) = self.formulas.get(&key) {
            return known.clone();
        }
        let dpi = typeset::dpi_for_em(key.em_px as f32);
        // A label is text from anywhere (a zone's name, a plugin's title): should the
        // typesetter panic on some input, the label shows as text and the viewer goes on.
        let typeset = self.typeset;
        let outcome = std::panic::catch_unwind(|| typeset(text, colour, dpi));
        let made = match outcome {
            Ok(Ok(pixels)) => Some(to_texture(ctx, &key, &pixels, scale)),
            Ok(Err(e)) => {
                tracing::warn!("{text:?} is shown as text: {e}");
                None
            }
            Err(_) => {
                tracing::warn!("{text:?} is shown as text: the typesetter failed on it");
                None
            }
        };
        if self.order.len() >= MAX_FORMULAS {
            let oldest = self.order.remove(0);
            self.formulas.remove(&oldest);
        }
        self.order.push(key.clone());
        self.formulas.insert(key, made.clone());
        made
    }

    /// Formulas typeset (or tried) and kept.
    pub fn len(&self) -> usize {
        self.formulas.len()
    }

    pub fn is_empty(&self) -> bool {
        self.formulas.is_empty()
    }
}

/// The picture (rows bottom-up, as the scene keeps them) as an egui texture (top row first).
fn to_texture(ctx: &egui::Context, key: &Key, pixels: &Pixels, scale: f32) -> Formula {
    let (w, h) = (pixels.width() as usize, pixels.height() as usize);
    let rgba: Vec<u8> = match pixels.format() {
        PixelFormat::Rgba8 => pixels
            .bytes()
            .chunks_exact(w * 4)
            .rev()
            .flatten()
            .copied()
            .collect(),
        PixelFormat::Gray8 => pixels
            .bytes()
            .chunks_exact(w)
            .rev()
            .flatten()
            .flat_map(|&g| [g, g, g, g])
            .collect(),
    };
    let image = egui::ColorImage::from_rgba_unmultiplied([w, h], &rgba);
    let texture = ctx.load_texture(
        format!("formula {} {:?} {}", key.text, key.colour, key.em_px),
        image,
        egui::TextureOptions::LINEAR,
    );
    Formula {
        texture,
        size: egui::vec2(w as f32, h as f32) / scale,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    static TYPESET: AtomicUsize = AtomicUsize::new(0);

    fn counting(text: &str, colour: Rgba, dpi: u32) -> Result<Pixels, FormulaError> {
        TYPESET.fetch_add(1, Ordering::SeqCst);
        typeset::typeset(text, colour, dpi)
    }

    #[test]
    fn each_formula_is_typeset_once_per_text_colour_and_size() {
        let ctx = egui::Context::default();
        let mut formulas = FormulaTextures::with_typesetter(counting);
        let v = r"$v = \omega r$";
        let first = formulas.get(&ctx, v, Rgba::WHITE, 16.0).expect("typeset");
        assert!(first.size.x > first.size.y, "{:?}", first.size);
        for _ in 0..10 {
            let again = formulas.get(&ctx, v, Rgba::WHITE, 16.0).unwrap();
            assert_eq!(again.texture.id(), first.texture.id(), "the same texture");
        }
        assert_eq!(TYPESET.load(Ordering::SeqCst), 1, "typeset once");
        formulas.get(&ctx, v, Rgba::rgb(255, 0, 0), 16.0).unwrap();
        formulas.get(&ctx, v, Rgba::WHITE, 32.0).unwrap();
        formulas.get(&ctx, "$x^2$", Rgba::WHITE, 16.0).unwrap();
        assert_eq!(TYPESET.load(Ordering::SeqCst), 4, "once per distinct one");
        assert_eq!(formulas.len(), 4);

        // Plain text is never typeset; a broken formula is tried once and shown as text.
        assert!(formulas.get(&ctx, "r0", Rgba::WHITE, 16.0).is_none());
        for _ in 0..3 {
            assert!(
                formulas
                    .get(&ctx, r"$\frac{1}{$", Rgba::WHITE, 16.0)
                    .is_none()
            );
        }
        assert_eq!(TYPESET.load(Ordering::SeqCst), 5);
    }

    fn panicking(_: &str, _: Rgba, _: u32) -> Result<Pixels, FormulaError> {
        panic!("a typesetter bug")
    }

    #[test]
    fn a_typesetter_that_panics_leaves_the_text_as_it_is() {
        let ctx = egui::Context::default();
        let mut formulas = FormulaTextures::with_typesetter(panicking);
        assert!(formulas.get(&ctx, "$x$", Rgba::WHITE, 16.0).is_none());
        assert_eq!(formulas.len(), 1, "remembered, not tried again");
    }
}
