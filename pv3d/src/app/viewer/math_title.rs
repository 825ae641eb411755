//! Item-tree titles with LaTeX math in them (`Formula $v = \omega r$`, or a title that is a
//! formula alone): the math between each pair of dollar signs shows typeset, the rest as text,
//! so the tree names a formula the way the world shows it. The source is the entry's hover
//! text, for copying or checking.

use eframe::egui::{self, Ui};
use framework::scene::Rgba;
use plugins::formula::typeset::math_of;

use crate::app::formula_textures::FormulaTextures;

/// How much larger than the tree's text a formula's em is: math sets its subscripts and
/// exponents smaller still.
const FORMULA_SCALE: f32 = 1.2;

/// A run of a title: plain text, or math with its dollar signs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Segment<'a> {
    Text(&'a str),
    Math(&'a str),
}

/// `title` cut into text and math. A lone dollar sign, or an empty pair, stays text.
pub fn segments(title: &str) -> Vec<Segment<'_>> {
    let mut out = Vec::new();
    let mut text_from = 0;
    let mut at = 0;
    while let Some(open) = title[at..].find('$').map(|i| at + i) {
        let Some(close) = title[open + 1..].find('$').map(|i| open + 1 + i) else {
            break;
        };
        let math = &title[open..=close];
        if math_of(math).is_some() {
            if open > text_from {
                out.push(Segment::Text(&title[text_from..open]));
            }
            out.push(Segment::Math(math));
            text_from = close + 1;
        }
        at = close + 1;
    }
    if text_from < title.len() {
        out.push(Segment::Text(&title[text_from..]));
    }
    out
}

/// Whether `title` holds any math to typeset.
pub fn has_math(title: &str) -> bool {
    segments(title)
        .iter()
        .any(|s| matches!(s, Segment::Math(_)))
}

/// Shows `title` in a row, its math typeset in the tree's text colour; math that does not
/// typeset shows as its source (the cache warned once). The row answers clicks (under `id`,
/// the entry's), so that it opens and closes its entry as a plain title does.
pub fn show(
    ui: &mut Ui,
    id: egui::Id,
    formulas: &mut FormulaTextures,
    title: &str,
) -> egui::Response {
    // The colour CollapsingHeader gives a plain title, so a typeset one does not look greyed.
    let text_colour = ui.visuals().widgets.inactive.text_color();
    let colour = Rgba(text_colour.to_srgba_unmultiplied());
    let em = egui::TextStyle::Body.resolve(ui.style()).size * FORMULA_SCALE;
    ui.spacing_mut().item_spacing.x = 0.0;
    for segment in segments(title) {
        match segment {
            Segment::Text(text) => {
                ui.label(egui::RichText::new(text).color(text_colour));
            }
            Segment::Math(math) => match formulas.get(ui.ctx(), math, colour, em) {
                Some(f) => {
                    ui.image((f.texture.id(), f.size));
                }
                None => {
                    ui.label(egui::RichText::new(math).color(text_colour));
                }
            },
        }
    }
    ui.interact(ui.min_rect(), id.with("math title"), egui::Sense::click())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_title_is_cut_into_text_and_math() {
        use Segment::{Math, Text};
        assert_eq!(
            segments(r"Formula $v = \omega r$  (active)"),
            vec![
                Text("Formula "),
                Math(r"$v = \omega r$"),
                Text("  (active)")
            ]
        );
        assert_eq!(segments(r"$\dot\theta$"), vec![Math(r"$\dot\theta$")]);
        assert_eq!(
            segments("$a$ and $b$"),
            vec![Math("$a$"), Text(" and "), Math("$b$")]
        );
        assert_eq!(segments("costs $5"), vec![Text("costs $5")]);
        assert_eq!(segments("$$ x"), vec![Text("$$ x")]);
        assert!(has_math("Formula $x$"));
        assert!(!has_math("Laser laser:0@localhost:6665"));
    }
}
