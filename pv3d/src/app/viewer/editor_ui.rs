//! The editor's controls in the item tree: under each component, buttons to move it in the
//! visiting order, disable or remove it, and its parameters as text fields; after the list,
//! the disabled components and "Add component". Clicks become [`Edit`]s, applied once the
//! tree is drawn (while it is drawn, the plugins are borrowed).

use std::collections::HashMap;

use eframe::egui::{self, Ui};
use framework::config::PluginConfig;

use super::Viewer;

/// One change the person asked for.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Edit {
    Move {
        index: usize,
        up: bool,
    },
    Disable(usize),
    Remove(usize),
    SetParam {
        index: usize,
        name: String,
        text: String,
    },
    Enable(usize),
    Add {
        library: String,
        attach_to: Option<usize>,
    },
}

/// What the editor's fields hold between frames.
#[derive(Debug, Default)]
pub(super) struct EditorState {
    /// Parameter texts being typed, by (component, parameter).
    drafts: HashMap<(usize, String), String>,
    library: String,
    attach_to: Option<usize>,
    /// The outcome of the last edit.
    message: Option<String>,
}

impl EditorState {
    /// The buttons and parameter fields under component `index`.
    pub(super) fn component_controls(
        &mut self,
        ui: &mut Ui,
        index: usize,
        config: &PluginConfig,
    ) -> Option<Edit> {
        let mut edit = None;
        ui.horizontal(|ui| {
            if ui
                .small_button("▲")
                .on_hover_text("visit earlier")
                .clicked()
            {
                edit = Some(Edit::Move { index, up: true });
            }
            if ui.small_button("▼").on_hover_text("visit later").clicked() {
                edit = Some(Edit::Move { index, up: false });
            }
            if ui
                .small_button("Disable")
                .on_hover_text("stop running and drawing it")
                .clicked()
            {
                edit = Some(Edit::Disable(index));
            }
            if ui.small_button("Remove").clicked() {
                edit = Some(Edit::Remove(index));
            }
        });
        egui::CollapsingHeader::new("Parameters")
            .id_salt(("params", index))
            .show(ui, |ui| {
                for param in &config.params {
                    let key = (index, param.name.clone());
                    let draft = self
                        .drafts
                        .entry(key.clone())
                        .or_insert_with(|| param.text.clone());
                    ui.horizontal(|ui| {
                        ui.label(&param.name);
                        let field = ui.text_edit_singleline(draft);
                        let enter =
                            field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                        if (enter || ui.small_button("Set").clicked()) && *draft != param.text {
                            edit = Some(Edit::SetParam {
                                index,
                                name: param.name.clone(),
                                text: draft.clone(),
                            });
                        }
                    });
                }
            });
        edit
    }
}

impl Viewer {
    /// The disabled components and "Add component", after the list.
    pub(super) fn editor_footer(&mut self, ui: &mut Ui) -> Option<Edit> {
        let mut edit = None;
        for (i, title) in self.disabled_titles().into_iter().enumerate() {
            let about = self.disabled[i].metadata.description;
            ui.horizontal(|ui| {
                ui.weak(format!("{title} (disabled)")).on_hover_text(about);
                if ui.small_button("Enable").clicked() {
                    edit = Some(Edit::Enable(i));
                }
            });
        }
        let libraries = self.component_libraries();
        let titles = self.titles();
        let state = &mut self.editor;
        egui::CollapsingHeader::new("Add component").show(ui, |ui| {
            egui::ComboBox::from_id_salt("add-library")
                .selected_text(if state.library.is_empty() {
                    "library…"
                } else {
                    state.library.as_str()
                })
                .show_ui(ui, |ui| {
                    for library in &libraries {
                        ui.selectable_value(&mut state.library, library.to_string(), *library);
                    }
                });
            let attached = state
                .attach_to
                .and_then(|i| titles.get(i))
                .map_or("the world", String::as_str);
            egui::ComboBox::from_id_salt("add-attach")
                .selected_text(attached)
                .show_ui(ui, |ui| {
                    ui.selectable_value(&mut state.attach_to, None, "the world");
                    for (i, title) in titles.iter().enumerate() {
                        ui.selectable_value(&mut state.attach_to, Some(i), title);
                    }
                });
            if ui.button("Add").clicked() && !state.library.is_empty() {
                edit = Some(Edit::Add {
                    library: state.library.clone(),
                    attach_to: state.attach_to,
                });
            }
        });
        if let Some(message) = &self.editor.message {
            ui.small(message);
        }
        edit
    }

    /// Carries out an edit from the tree; its outcome is shown under the tree.
    pub(super) fn apply_edit(&mut self, edit: Edit) {
        let outcome = match edit.clone() {
            Edit::Move { index, up } => self.move_component(index, up).map(|_| "moved".into()),
            Edit::Disable(i) => self.disable_component(i).map(|_| "disabled".into()),
            Edit::Remove(i) => self.remove_component(i).map(|_| "removed".into()),
            Edit::SetParam { index, name, text } => self
                .set_component_param(index, &name, &text)
                .map(|_| format!("{name} set to {text:?}")),
            Edit::Enable(i) => self.enable_component(i).map(|_| "enabled".into()),
            Edit::Add { library, attach_to } => self
                .add_component(&library, attach_to)
                .map(|_| format!("added {library}")),
        };
        // Positions changed: drafts keyed by position no longer match their components.
        self.editor.drafts.clear();
        self.editor.message = Some(match outcome {
            Ok(done) => done,
            Err(e) => format!("not done: {e}"),
        });
    }
}
