//! Popups over the world view: the active robot's actions on a clicked object ("Go to",
//! "Follow"), and the popups of item-tree services that need input first ("Go to point…").
//!
//! The state lives in the [`Viewer`] so that tests open, read and answer popups without egui;
//! [`Viewer::show_popup`] only draws it.

use std::time::Instant;

use eframe::egui;
use framework::action::{Action, ObjectRef};
use framework::scene::NodeId;

use super::Viewer;

/// The popup open now (one at a time).
pub(super) enum Popup {
    /// The actions plugin `plugin` offers on `target`.
    Actions {
        plugin: usize,
        target: ObjectRef,
        actions: Vec<Action>,
    },
    /// The popup of service `name` of plugin `plugin`.
    Service { plugin: usize, name: &'static str },
}

impl Viewer {
    /// Opens the active handler's popup of actions on `node`, if it offers any. Returns
    /// whether a popup opened (the click was handled).
    pub fn offer_actions(&mut self, node: NodeId) -> bool {
        let Some(active) = self.active else {
            return false;
        };
        if self.owner_of(node) == Some(active) {
            return false; // its own body or sensors
        }
        let Some(target) = ObjectRef::of(&self.scene, node) else {
            return false;
        };
        let actions = self.slots[active].plugin.actions_on(&target);
        if actions.is_empty() {
            return false;
        }
        self.popup = Some(Popup::Actions {
            plugin: active,
            target,
            actions,
        });
        true
    }

    /// The names of the actions in the open popup, if an action popup is open.
    pub fn popup_actions(&self) -> Option<Vec<&'static str>> {
        match &self.popup {
            Some(Popup::Actions { actions, .. }) => Some(actions.iter().map(|a| a.name).collect()),
            _ => None,
        }
    }

    /// The open popup's title ("Robot r0: actions on marker 7 (fiducial, id:7, person)").
    pub fn popup_title(&self) -> Option<String> {
        let title = |plugin: usize| self.slots[plugin].plugin.title();
        match &self.popup {
            Some(Popup::Actions { plugin, target, .. }) => Some(format!(
                "{}: actions on {}",
                title(*plugin),
                target.describe()
            )),
            Some(Popup::Service { plugin, name }) => Some(format!("{}: {name}", title(*plugin))),
            None => None,
        }
    }

    /// Runs the action `name` of the open action popup and closes it. Returns whether there
    /// was such an action.
    pub fn choose_action(&mut self, name: &str) -> bool {
        let Some(Popup::Actions {
            plugin,
            target,
            actions,
        }) = self.popup.take()
        else {
            return false;
        };
        if !actions.iter().any(|a| a.name == name) {
            self.popup = Some(Popup::Actions {
                plugin,
                target,
                actions,
            });
            return false;
        }
        let (plugin, mut ctx) = self.plugin_in_context(plugin, Instant::now());
        plugin.run_action(name, &target, &mut ctx);
        true
    }

    pub fn close_popup(&mut self) {
        self.popup = None;
    }

    /// Clicking service `name` of plugin `index` in the item tree: runs it, or opens its
    /// popup. Returns whether the plugin offers that service.
    pub fn use_service(&mut self, index: usize, name: &str) -> bool {
        let Some(slot) = self.slots.get(index) else {
            return false;
        };
        let Some(service) = slot.plugin.services().into_iter().find(|s| s.name == name) else {
            return false;
        };
        if service.popup {
            self.popup = Some(Popup::Service {
                plugin: index,
                name: service.name,
            });
        } else {
            let (plugin, mut ctx) = self.plugin_in_context(index, Instant::now());
            plugin.run_service(service.name, &mut ctx);
        }
        true
    }

    /// Draws the open popup near `at` (where the person clicked).
    pub(super) fn show_popup(&mut self, egui_ctx: &egui::Context, at: egui::Pos2) {
        let Some(title) = self.popup_title() else {
            return;
        };
        let mut keep = true;
        let mut chosen = None;
        let popup = self.popup.as_ref().expect("a title means a popup");
        let (plugin, service) = match popup {
            Popup::Actions { plugin, .. } => (*plugin, None),
            Popup::Service { plugin, name } => (*plugin, Some(*name)),
        };
        let actions: Vec<Action> = match popup {
            Popup::Actions { actions, .. } => actions.clone(),
            Popup::Service { .. } => Vec::new(),
        };
        // The window's title names what the popup is about; the full line goes inside.
        let short = match popup {
            Popup::Actions { target, .. } => target.name.clone(),
            Popup::Service { name, .. } => name.to_string(),
        };
        let (plugin, mut ctx) = self.plugin_in_context(plugin, Instant::now());
        egui::Window::new(short)
            .id(egui::Id::unique("pv3d-popup"))
            .default_pos(at)
            .collapsible(false)
            .resizable(false)
            .show(egui_ctx, |ui| {
                ui.small(&title);
                if let Some(name) = service {
                    keep = plugin.service_popup(name, ui, &mut ctx);
                    return;
                }
                for action in &actions {
                    if ui
                        .button(action.name)
                        .on_hover_text(&action.description)
                        .clicked()
                    {
                        chosen = Some(action.name);
                    }
                }
                if ui.button("Cancel").clicked() {
                    keep = false;
                }
            });
        if let Some(name) = chosen {
            self.choose_action(name);
        } else if !keep {
            self.popup = None;
        }
    }
}
