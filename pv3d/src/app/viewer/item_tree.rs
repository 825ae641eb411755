//! The item tree: one entry per component, with its own panel, its services, and the paper's
//! metadata — what it is for, who wrote it and where to read more — so that a composition
//! explains its parts to whoever opens it. Math in a title (`$…$`) shows typeset.

use std::time::Instant;

use eframe::egui::{self, Ui};
use framework::registry::Metadata;

use super::Viewer;
use super::math_title;
use crate::app::device_gone::{GONE, GONE_COLOR};
use crate::app::listing::{
    Entry, FIND_FROM, LISTED_AT_MOST, Listing, list, matches, summary, thousands,
};

impl Viewer {
    /// The list of components on the left: each plugin's panel, services and "about" line,
    /// then Save and a reminder of the mouse and keys.
    pub(super) fn item_tree(&mut self, ui: &mut Ui) {
        ui.heading("Components");
        for error in &self.errors {
            ui.colored_label(egui::Color32::from_rgb(230, 90, 80), error);
        }
        let now = Instant::now();
        let observing = self.observing();
        if observing {
            ui.strong("Observing: read-only, no tele-operation");
        }
        let listing = self.find_field(ui);
        let mut activate = None;
        let mut used = None;
        let mut edit = None;
        // The plugins are borrowed while their entries are drawn; the editor's fields and the
        // typeset titles too.
        let mut editor = std::mem::take(&mut self.editor);
        let mut titles = std::mem::take(&mut self.titles);
        for &i in &listing.shown {
            let active = self.active == Some(i);
            let about = self.slots[i].metadata;
            let (plugin, mut ctx) = self.plugin_in_context(i, now);
            let mut title = plugin.title();
            if active {
                title.push_str("  (active)");
            }
            let body = |ui: &mut Ui| {
                about_line(ui, ("plugin", i), &about);
                plugin.ui(ui, &mut ctx);
                // An observer's services would command the robot: none are offered.
                let services = if observing {
                    Vec::new()
                } else {
                    plugin.services()
                };
                for service in services {
                    if ui
                        .button(service.name)
                        .on_hover_text(service.description)
                        .clicked()
                    {
                        used = Some((i, service.name));
                    }
                }
                let selectable = plugin.can_be_active() && !observing;
                if selectable && !active && ui.button("Select").clicked() {
                    activate = Some(i);
                }
                let config = plugin.save();
                if let Some(e) = editor.component_controls(ui, i, &config) {
                    edit = Some(e);
                }
            };
            if math_title::has_math(&title) {
                // A custom header under the id CollapsingHeader would use, so an entry keeps
                // its state whichever way its title is drawn.
                let id = ui.make_persistent_id(("plugin", i));
                let (_, header, _) =
                    egui::collapsing_header::CollapsingState::load_with_default_open(
                        ui.ctx(),
                        id,
                        false,
                    )
                    .show_header(ui, |ui| math_title::show(ui, id, &mut titles, &title))
                    .body(body);
                if header.inner.clicked() {
                    let mut state =
                        egui::collapsing_header::CollapsingState::load_with_default_open(
                            ui.ctx(),
                            id,
                            false,
                        );
                    state.toggle(ui);
                    state.store(ui.ctx());
                }
                header
                    .inner
                    .on_hover_text(format!("{title}\n\n{}", about.description));
            } else {
                egui::CollapsingHeader::new(title)
                    .id_salt(("plugin", i))
                    .show(ui, body)
                    .header_response
                    .on_hover_text(about.description);
            }
        }
        self.titles = titles;
        self.editor = editor;
        if listing.left_out() > 0 {
            ui.small(format!(
                "… and {} more: type in Find to reach them",
                thousands(listing.left_out())
            ));
        } else if listing.found == 0 && !self.find.trim().is_empty() {
            ui.small("no component matches");
        }
        self.gone_entries(ui);
        if let Some(e) = self.editor_footer(ui) {
            edit = Some(e);
        }
        if let Some(e) = edit {
            self.apply_edit(e);
            return;
        }
        if let Some(i) = activate {
            self.set_active(Some(i));
        }
        if let Some((i, name)) = used {
            self.popup_at = ui
                .input(|i| i.pointer.interact_pos())
                .unwrap_or(self.popup_at);
            self.use_service(i, name);
        }
        if let Some(target) = &self.save_target {
            ui.separator();
            if ui
                .button("Save")
                .on_hover_text(format!(
                    "write the composition with the current state to {}",
                    target.path.display()
                ))
                .clicked()
            {
                self.save_message = Some(match self.save_now() {
                    Ok(path) => format!("saved to {}", path.display()),
                    Err(e) => format!("not saved: {e}"),
                });
            }
            if let Some(message) = &self.save_message {
                ui.small(message);
            }
        }
        ui.separator();
        ui.small(if observing {
            "drag: pan/orbit · wheel: zoom · T: top/perspective"
        } else {
            "drag: pan/orbit · wheel: zoom · T: top/perspective · Tab: next robot · Space: stop all \
             · click ground: send robot · Ctrl+drag: drag its target · click/right-click object: actions"
        });
    }

    /// The find field and the summary by kind, once there are enough components to need
    /// them, and which entries to list: the selected robot and its server's first.
    fn find_field(&mut self, ui: &mut Ui) -> Listing {
        if self.slots.len() >= FIND_FROM {
            ui.add(
                egui::TextEdit::singleline(&mut self.find)
                    .hint_text("Find: robot, device, host:port"),
            );
            ui.small(summary(
                self.slots.iter().map(|s| {
                    let library = s.instance.library();
                    library.strip_prefix("libpv3d_").unwrap_or(library)
                }),
                "components",
            ));
        }
        // Titles are only searched: with nothing typed, none is made (a thousand a frame).
        let typed = !self.find.trim().is_empty();
        let titles: Vec<String> = (self.slots.iter())
            .map(|s| {
                if typed {
                    s.plugin.title()
                } else {
                    String::new()
                }
            })
            .collect();
        let entries: Vec<Entry<'_>> = self
            .slots
            .iter()
            .zip(&titles)
            .map(|(slot, title)| Entry {
                title,
                server: slot
                    .instance
                    .device
                    .as_ref()
                    .map(|d| (d.host.as_str(), d.port)),
            })
            .collect();
        list(&entries, self.active, &self.find, LISTED_AT_MOST)
    }

    /// The servers of the components the find text matches: their rows stay in the status
    /// panel, so finding "robot3" shows robot3's server too.
    pub(super) fn servers_found(&self) -> Vec<(String, u16)> {
        if self.find.trim().is_empty() {
            return Vec::new();
        }
        let mut servers: Vec<(String, u16)> = self
            .slots
            .iter()
            .filter(|slot| matches(&self.find, &slot.plugin.title()))
            .filter_map(|slot| slot.instance.device.as_ref())
            .map(|d| (d.host.clone(), d.port))
            .collect();
        servers.sort();
        servers.dedup();
        servers
    }

    /// The plugins whose device went away: named as they were, marked, and told when they
    /// come back.
    fn gone_entries(&self, ui: &mut Ui) {
        for (i, gone) in self.gone.iter().enumerate() {
            let device = gone.device().map_or(String::new(), |d| {
                format!(
                    "{}:{} on {}:{}",
                    d.addr.interf, d.addr.index, d.host, d.port
                )
            });
            let title = egui::RichText::new(format!("{}  ({GONE})", gone.title)).color(GONE_COLOR);
            egui::CollapsingHeader::new(title)
                .id_salt(("gone", i))
                .show(ui, |ui| {
                    about_line(ui, ("gone", i), &gone.metadata);
                    ui.label(format!(
                        "{device} is no longer listed by its server; this plugin was cleaned \
                         and resumes, as it was, when the device comes back"
                    ));
                })
                .header_response
                .on_hover_text(gone.metadata.description);
        }
    }
}

/// A collapsed "About" line under a plugin's entry: the description, the author with their
/// e-mail, and the web page as a link.
fn about_line(ui: &mut Ui, entry: impl std::hash::Hash + std::fmt::Debug, about: &Metadata) {
    egui::CollapsingHeader::new("About")
        .id_salt(("about", entry))
        .show(ui, |ui| {
            ui.label(about.description);
            ui.label(format!("by {} <{}>", about.author, about.email));
            ui.hyperlink(about.web_page);
        });
}
