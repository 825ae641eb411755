//! The contents of a world window: the plugins made from the composition, the scene they fill,
//! the item tree, the 3D view, and the chain of responsibility that input flows along
//! (active event handler first, then the clicked object, then the world).
//!
//! Mouse: click a robot to make it the active handler; click the ground (or Ctrl+drag, or drag
//! from the robot, and let go) to send it there; click a tagged object (a fiducial marker) for
//! the robot's popup of actions on it; right-click any object, robots included, for the same.

mod awareness;
mod commanding;
mod device_presence;
mod editor;
mod editor_ui;
mod input_chain;
mod item_tree;
mod lifecycle;
mod math_title;
mod popups;
mod queries;
mod reactions;
mod speech;

pub use editor::EditError;

use std::sync::Arc;
use std::time::Instant;

use eframe::egui::{self, Ui};
use framework::config::DeviceRef;
use framework::device::DeviceAccess;
use framework::plugin::{Anchors, Plugin, PluginContext};
use framework::registry::{Metadata, PluginRegistry};
use framework::scene::Scene;

use super::view3d::{TargetDrag, View3d};
use crate::composition::{Composer, PluginInstance, write_back};

/// A plugin and what it was made from.
struct Slot {
    plugin: Box<dyn Plugin>,
    device: Option<Arc<dyn DeviceAccess>>,
    instance: PluginInstance,
    /// What its component says about itself, for the item tree.
    metadata: Metadata,
    /// Whether [`Plugin::initialize`] ran (it runs before the first [`Plugin::run`]).
    initialized: bool,
}

/// Looks up the device access for a plugin's device.
pub type DeviceLookup<'a> = &'a dyn Fn(&DeviceRef) -> Option<Arc<dyn DeviceAccess>>;

/// One world window's state.
pub struct Viewer {
    scene: Scene,
    anchors: Anchors,
    slots: Vec<Slot>,
    /// Plugins whose device went away, waiting for it to come back.
    gone: Vec<device_presence::GonePlugin>,
    /// Makes the plugins of servers that answer after the start.
    registry: PluginRegistry,
    pub view: View3d,
    /// Index of the active event handler (the selected robot).
    active: Option<usize>,
    /// Plugins that could not be made, with why.
    pub errors: Vec<String>,
    /// The Player servers, for the status panel.
    pub robots: Option<Arc<crate::robots::RobotManager>>,
    /// Turns the handlers into plugins for servers that answer late, and for devices that
    /// appear when a server comes back (needs `robots`).
    pub(crate) composer: Option<Composer>,
    status: super::status_panel::StatusPanel,
    /// Where "Save" writes the composition with the plugins' current state.
    pub(crate) save_target: Option<SaveTarget>,
    save_message: Option<String>,
    /// The popup open over the view (actions on an object, a service's popup).
    popup: Option<popups::Popup>,
    /// Where the pointer was at the last click in the view: popups open there.
    popup_at: egui::Pos2,
    /// The composition's `<reaction>`s and what they have seen.
    reactions: reactions::Reactions,
    /// The grammar sentences are parsed with (the command line, `--script`, speech).
    grammar: crate::commands::Grammar,
    command_line: super::command_line::CommandLine,
    /// The `--script` being run, if any.
    script: Option<crate::commands::Script>,
    /// Every sentence's reply or error, oldest first.
    replies: Vec<Result<String, String>>,
    /// The servers' speech_recognition and speech devices, once seen.
    speech: speech::SpeechLinks,
    /// Components switched off in the editor (or saved so), kept to be enabled again.
    disabled: Vec<editor::DisabledPlugin>,
    editor: editor_ui::EditorState,
    /// Item-tree titles' math, typeset once each.
    titles: super::formula_textures::FormulaTextures,
    /// What the person typed to find components and servers (see [`super::listing`]).
    pub find: String,
}

/// The composition a session came from and the file its state is saved to.
pub struct SaveTarget {
    pub path: std::path::PathBuf,
    pub composition: crate::composition::Composition,
}

impl Viewer {
    /// Makes a plugin for every instance the registry knows. A plugin that fails is reported
    /// in [`Viewer::errors`] and the others carry on.
    pub fn new(
        instances: Vec<PluginInstance>,
        registry: PluginRegistry,
        devices: DeviceLookup<'_>,
    ) -> Viewer {
        let mut viewer = Viewer {
            scene: Scene::new(),
            anchors: Anchors::default(),
            slots: Vec::new(),
            gone: Vec::new(),
            registry,
            view: View3d::default(),
            active: None,
            errors: Vec::new(),
            robots: None,
            composer: None,
            status: Default::default(),
            save_target: None,
            save_message: None,
            popup: None,
            popup_at: egui::pos2(300.0, 200.0),
            reactions: Default::default(),
            grammar: crate::commands::Grammar::standard(),
            command_line: Default::default(),
            script: None,
            replies: Vec::new(),
            speech: Default::default(),
            disabled: Vec::new(),
            editor: Default::default(),
            titles: Default::default(),
            find: String::new(),
        };
        viewer.add_plugins(instances, devices);
        viewer
    }

    /// Plugin `index` and the context it is called in: its own device, the shared scene and
    /// anchors. Every call into a plugin after it was made goes through here.
    fn plugin_in_context(
        &mut self,
        index: usize,
        now: Instant,
    ) -> (&mut dyn Plugin, PluginContext<'_>) {
        let slot = &mut self.slots[index];
        let ctx = PluginContext::new(&mut self.scene, &mut self.anchors, now)
            .with_device(slot.device.as_deref());
        (slot.plugin.as_mut(), ctx)
    }

    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    pub fn plugin_count(&self) -> usize {
        self.slots.len()
    }

    /// The whole window: item tree on the left, 3D view in the middle.
    pub fn ui(&mut self, ui: &mut Ui) {
        self.handle_keys(ui);
        egui::Panel::left("item-tree")
            .resizable(true)
            .default_size(230.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.item_tree(ui));
            });
        if let Some(robots) = self.robots.clone() {
            egui::Panel::bottom("robot-status")
                .resizable(true)
                .default_size(140.0)
                .show(ui, |ui| {
                    let gone = self.gone_devices();
                    let selected = self.selected_server();
                    let find = super::status_panel::Find {
                        text: &self.find,
                        servers: &self.servers_found(),
                        selected: selected.as_ref().map(|(h, p)| (h.as_str(), *p)),
                    };
                    self.status.ui(ui, &robots, &gone, &find)
                });
        }
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| {
                let view_rect = ui.max_rect();
                let mut view = std::mem::take(&mut self.view);
                let starts = |o, d| self.starts_on_active(o, d);
                let drag_rule: Option<super::view3d::StartsTargetDrag<'_>> = self
                    .active
                    .map(|_| &starts as super::view3d::StartsTargetDrag<'_>);
                let input = view.show_with_targets(ui, &self.scene, drag_rule);
                self.view = view;
                if let Some(pointer) = ui.input(|i| i.pointer.interact_pos())
                    && (input.clicked.is_some() || input.secondary_clicked.is_some())
                {
                    self.popup_at = pointer + egui::vec2(12.0, 12.0);
                }
                if let Some((origin, dir, ground)) = input.clicked {
                    let picked = self.scene.pick(origin, dir).map(|(n, _)| n);
                    self.click(picked, ground);
                }
                if let Some((origin, dir, _)) = input.secondary_clicked {
                    let picked = self.scene.pick(origin, dir).map(|(n, _)| n);
                    self.secondary_click(picked);
                }
                match input.target_drag {
                    Some(TargetDrag::Moved(Some(p))) => self.drag_target(p),
                    Some(TargetDrag::Released(p)) => self.release_target(p),
                    _ => {}
                }
                self.active_controls(ui.ctx(), view_rect);
                if let Some(sentence) = self.command_line.over_view(ui.ctx(), view_rect) {
                    // The outcome is shown on the line itself.
                    let _ = self.command(&sentence);
                }
            });
        let at = self.popup_at;
        self.show_popup(ui.ctx(), at);
        // Plugins' own windows (a camera's image), through egui.
        let (egui_ctx, now) = (ui.ctx().clone(), Instant::now());
        for i in 0..self.slots.len() {
            let (plugin, mut ctx) = self.plugin_in_context(i, now);
            plugin.windows(&egui_ctx, &mut ctx);
        }
    }

    /// The Player server (host, port) of the selected robot, listed first in the panels.
    fn selected_server(&self) -> Option<(String, u16)> {
        let slot = self.slots.get(self.active?)?;
        let device = slot.instance.device.as_ref()?;
        Some((device.host.clone(), device.port))
    }

    fn handle_keys(&mut self, ui: &mut Ui) {
        let (space, tab, t, focus_lost) = ui.input(|i| {
            let focus_lost = i
                .events
                .iter()
                .any(|e| matches!(e, egui::Event::WindowFocused(false)));
            (
                i.key_pressed(egui::Key::Space),
                i.key_pressed(egui::Key::Tab),
                i.key_pressed(egui::Key::T),
                focus_lost,
            )
        });
        let typing = ui.ctx().egui_wants_keyboard_input();
        if focus_lost || (space && !typing) {
            self.stop_all();
        }
        if tab && !typing {
            self.cycle_active();
        }
        if t && !typing {
            self.view.camera.toggle_projection();
        }
    }

    /// The active handler's controls (a robot's joystick), over the view's bottom right.
    fn active_controls(&mut self, egui_ctx: &egui::Context, view_rect: egui::Rect) {
        let Some(active) = self.active else { return };
        let (plugin, mut ctx) = self.plugin_in_context(active, Instant::now());
        egui::Area::new(egui::Id::unique("pv3d-active-controls"))
            .pivot(egui::Align2::RIGHT_BOTTOM)
            .fixed_pos(view_rect.right_bottom() - egui::vec2(10.0, 10.0))
            .show(egui_ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| plugin.active_ui(ui, &mut ctx));
            });
    }

    /// Writes the composition, with every plugin's current state, to the save target.
    pub fn save_now(&self) -> std::io::Result<std::path::PathBuf> {
        let Some(target) = &self.save_target else {
            return Err(std::io::Error::other("no file to save to (use --save-to)"));
        };
        let text =
            crate::composition::emit_document(&target.composition, &self.save(), &target.path);
        std::fs::write(&target.path, text)?;
        tracing::info!("composition saved to {}", target.path.display());
        Ok(target.path.clone())
    }

    /// The composition's plugin elements with every plugin's current state written back, the
    /// plugins whose device is gone as they were when it went, and the plugins still waiting
    /// for their device as they were written.
    pub fn save(&self) -> Vec<PluginInstance> {
        let mut saved: Vec<PluginInstance> = self
            .slots
            .iter()
            .map(|slot| {
                let mut instance = slot.instance.clone();
                write_back(&mut instance.element, &slot.plugin.save());
                instance
            })
            .collect();
        // A disabled plugin keeps its place in the visiting order.
        for off in &self.disabled {
            let mut instance = off.instance.clone();
            instance.element.set_attr(editor::ENABLED_ATTR, "false");
            saved.insert(off.at.min(saved.len()), instance);
        }
        saved.extend(self.gone.iter().map(|g| g.instance.clone()));
        if let Some(composer) = &self.composer {
            saved.extend(composer.waiting().iter().cloned());
        }
        saved
    }
}

impl Drop for Viewer {
    fn drop(&mut self) {
        // Leave no robot moving when the window goes away, keep what the person set up, and
        // only then let the plugins clean up.
        self.stop_all();
        if self.save_target.is_some()
            && let Err(e) = self.save_now()
        {
            tracing::error!("could not save the composition on exit: {e}");
        }
        self.remove_all_plugins();
    }
}
