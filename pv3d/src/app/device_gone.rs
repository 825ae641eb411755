//! How a plugin whose device went away is shown, on its own so that the viewer's item tree and
//! the status panel, which the viewer holds, say it alike without the panel using the viewer.

use eframe::egui;

/// What the item tree and the status panel say of a plugin whose device went away.
pub(crate) const GONE: &str = "device gone";

/// The colour of "device gone": a warning, not an error — the plugin resumes by itself.
pub(crate) const GONE_COLOR: egui::Color32 = egui::Color32::from_rgb(230, 150, 70);
