//! The command line over the 3D view's bottom left: a text field for sentences such as
//! "robot1 go to charging", and the reply or the error of the last one beside it. It floats
//! over the view rather than taking a panel, so the view keeps its size.

use eframe::egui::{self, Color32, Ui};

/// Colours of the reply: what was done, and why not.
const REPLY_COLOR: Color32 = Color32::from_rgb(120, 200, 120);
const ERROR_COLOR: Color32 = Color32::from_rgb(230, 110, 90);
/// How wide the text field is, in points.
const FIELD_WIDTH: f32 = 320.0;
/// Distance from the view's edges, in points.
const MARGIN: f32 = 10.0;

#[derive(Debug, Default)]
pub struct CommandLine {
    text: String,
    last: Option<Result<String, String>>,
}

impl CommandLine {
    /// Shows the outcome of a sentence, wherever it came from.
    pub fn show(&mut self, outcome: Result<String, String>) {
        self.last = Some(outcome);
    }

    /// Draws the line over the bottom left of `view`; returns the sentence entered, if any.
    pub fn over_view(&mut self, egui_ctx: &egui::Context, view: egui::Rect) -> Option<String> {
        let mut entered = None;
        egui::Area::new(egui::Id::unique("pv3d-command-line"))
            .pivot(egui::Align2::LEFT_BOTTOM)
            .fixed_pos(view.left_bottom() + egui::vec2(MARGIN, -MARGIN))
            .show(egui_ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| entered = self.ui(ui));
            });
        entered
    }

    /// Draws the line; returns the sentence the person entered (Enter or "Say"), if any.
    pub fn ui(&mut self, ui: &mut Ui) -> Option<String> {
        let mut entered = None;
        ui.horizontal(|ui| {
            ui.label("Command:");
            let field = ui.add(
                egui::TextEdit::singleline(&mut self.text)
                    .hint_text("robot1 go to charging · all robots stop")
                    .desired_width(FIELD_WIDTH),
            );
            let enter = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            if (enter || ui.button("Say").clicked()) && !self.text.trim().is_empty() {
                entered = Some(std::mem::take(&mut self.text));
                if enter {
                    field.request_focus();
                }
            }
            match &self.last {
                Some(Ok(reply)) => {
                    ui.colored_label(REPLY_COLOR, reply);
                }
                Some(Err(error)) => {
                    ui.colored_label(ERROR_COLOR, error);
                }
                None => {}
            }
        });
        entered
    }
}
