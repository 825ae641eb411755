//! The component model: a plugin is made from its configuration, fills the scene, shows an
//! egui panel, offers services, reacts to input, and writes its state back.

use std::collections::HashMap;
use std::time::Instant;

use glam::Vec3;

pub use crate::action::{Action, ObjectRef};
use crate::config::PluginConfig;
use crate::device::DeviceAccess;
use crate::query::{Query, QueryError, Reply};
use crate::scene::{NodeId, Scene};

/// Where a device's scene node is, so that other plugins can attach to it (`<parentNode>`):
/// the laser of robot r0 hangs below r0's position2d node.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct AnchorKey {
    pub host: String,
    pub port: u16,
    pub interface: String,
    pub index: u16,
}

/// Scene nodes published by plugins under their device's address.
#[derive(Debug, Default)]
pub struct Anchors(HashMap<AnchorKey, NodeId>);

impl Anchors {
    pub fn publish(&mut self, key: AnchorKey, node: NodeId) {
        self.0.insert(key, node);
    }

    pub fn find(&self, key: &AnchorKey) -> Option<NodeId> {
        self.0.get(key).copied()
    }

    pub fn withdraw(&mut self, node: NodeId) {
        self.0.retain(|_, n| *n != node);
    }
}

/// What a plugin works with during a call.
pub struct PluginContext<'a> {
    pub scene: &'a mut Scene,
    /// The plugin's own device, when it was made for one.
    pub device: Option<&'a dyn DeviceAccess>,
    pub anchors: &'a mut Anchors,
    pub now: Instant,
    /// Queries this plugin sends ([`PluginContext::send`]); `None` where nobody routes them
    /// (a test harness, a constructor run alone).
    pub outbox: Option<&'a mut Vec<Query>>,
}

impl<'a> PluginContext<'a> {
    /// A context with no device of its own; a plugin made for a device gets it through
    /// [`PluginContext::with_device`]. The one way a context is made, so that a field added
    /// later is filled in one place.
    pub fn new(scene: &'a mut Scene, anchors: &'a mut Anchors, now: Instant) -> Self {
        PluginContext {
            scene,
            device: None,
            anchors,
            now,
            outbox: None,
        }
    }

    /// The same context whose sent queries go into `outbox` (the viewer routes them after
    /// the call and hands each reply to [`Plugin::on_reply`]).
    pub fn with_outbox(self, outbox: &'a mut Vec<Query>) -> Self {
        PluginContext {
            outbox: Some(outbox),
            ..self
        }
    }

    /// Sends a query to other components; the reply comes later through
    /// [`Plugin::on_reply`]. Returns false where nobody routes queries (the query is dropped).
    pub fn send(&mut self, query: Query) -> bool {
        match self.outbox.as_deref_mut() {
            Some(outbox) => {
                outbox.push(query);
                true
            }
            None => false,
        }
    }

    /// The same context for a plugin with this device (or none).
    pub fn with_device(self, device: Option<&'a dyn DeviceAccess>) -> Self {
        PluginContext { device, ..self }
    }
}

/// Input that reached a plugin through the event chain.
#[derive(Debug, Clone, PartialEq)]
pub enum InputEvent {
    /// A click on the ground at this world point.
    GroundClicked(Vec3),
    /// A click on a scene object.
    ObjectClicked(NodeId),
    /// The person is dragging a target over the ground (press, move): show it, send nothing
    /// yet. The release arrives as a [`InputEvent::GroundClicked`] at the drop point.
    TargetDragged(Vec3),
    /// The dragged target was let go outside the ground: forget it.
    TargetDragCancelled,
    /// The window lost focus, or the person asked every robot to stop.
    StopAll,
    /// This plugin became (true) or stopped being (false) the active event handler.
    Activated(bool),
}

/// Whether a plugin consumed an event (the chain of responsibility stops there).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Handled {
    Yes,
    No,
}

/// An action a plugin offers in the item tree ("Stop", "Reset trail"). Clicking it runs it
/// ([`Plugin::run_service`]), or, when `popup` is set, opens its popup
/// ([`Plugin::service_popup`]) for the person to fill in first.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Service {
    pub name: &'static str,
    pub description: &'static str,
    pub popup: bool,
}

impl Service {
    /// A service that runs when clicked.
    pub const fn run(name: &'static str, description: &'static str) -> Service {
        Service {
            name,
            description,
            popup: false,
        }
    }

    /// A service that opens a popup when clicked.
    pub const fn popup(name: &'static str, description: &'static str) -> Service {
        Service {
            name,
            description,
            popup: true,
        }
    }
}

/// A component of a composition. Its life, as the viewer drives it: made by its
/// [`Constructor`](crate::registry::Constructor), then [`Plugin::initialize`] once, [`Plugin::run`] every iteration, and
/// [`Plugin::clean`] once before it is removed; nothing is called after `clean`.
pub trait Plugin: Send {
    /// The configuration this plugin was made from, with its current state written in.
    fn save(&self) -> PluginConfig;

    /// A short name for the item tree.
    fn title(&self) -> String;

    /// Called once, after the window and its GL context exist and before the first
    /// [`Plugin::run`]: the place for set-up that needs a live window, which a constructor
    /// (also run for `--emit-config`-style checks and in GL-free tests) cannot assume.
    fn initialize(&mut self, _ctx: &mut PluginContext<'_>) {}

    /// One iteration of the viewer's loop: take the newest data into the scene and send what
    /// the person asked for. Called often, so it must not block on the network.
    fn run(&mut self, _ctx: &mut PluginContext<'_>) {}

    /// The plugin's panel in the item tree.
    fn ui(&mut self, _ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {}

    /// Windows of the plugin's own (a camera's image), drawn every frame through egui: a
    /// plugin never touches OpenGL. Called once per frame for every plugin, after the main
    /// window's panels.
    fn windows(&mut self, _egui_ctx: &egui::Context, _ctx: &mut PluginContext<'_>) {}

    /// Actions offered in the item tree.
    fn services(&self) -> Vec<Service> {
        Vec::new()
    }

    /// Runs one of [`Plugin::services`].
    fn run_service(&mut self, _name: &str, _ctx: &mut PluginContext<'_>) {}

    /// Draws the popup of a service made with [`Service::popup`]; returns whether it stays
    /// open (false once the person ran or cancelled it).
    fn service_popup(
        &mut self,
        _name: &str,
        _ui: &mut egui::Ui,
        _ctx: &mut PluginContext<'_>,
    ) -> bool {
        false
    }

    /// What this plugin, as the active event handler, can do with a clicked object (a robot:
    /// "Go to", "Follow"). A non-empty list opens a popup of them over the view; an empty one
    /// lets the click go on down the chain.
    fn actions_on(&self, _target: &ObjectRef) -> Vec<Action> {
        Vec::new()
    }

    /// Runs one of the [`Plugin::actions_on`] actions the person chose for `target`.
    fn run_action(&mut self, _action: &str, _target: &ObjectRef, _ctx: &mut PluginContext<'_>) {}

    /// Answers a query addressed to this plugin (by its id or library name): `None` when it
    /// is not one this plugin knows, so the viewer passes it on to the next addressee; a
    /// reply with error 0 when done; an error (< 0) saying what was wrong. See
    /// [`crate::query`].
    fn answer(&mut self, _query: &Query, _ctx: &mut PluginContext<'_>) -> Option<Reply> {
        None
    }

    /// The outcome of a query this plugin sent with [`PluginContext::send`]: the reply with
    /// error 0, or why there was none.
    fn on_reply(
        &mut self,
        _query: &Query,
        _result: &Result<Reply, QueryError>,
        _ctx: &mut PluginContext<'_>,
    ) {
    }

    /// Controls drawn over the 3D view while this plugin is the active event handler (a
    /// robot's joystick), so they work without opening its item-tree entry.
    fn active_ui(&mut self, _ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {}

    /// Input from the event chain.
    fn on_event(&mut self, _event: &InputEvent, _ctx: &mut PluginContext<'_>) -> Handled {
        Handled::No
    }

    /// Whether this plugin can become the active event handler (e.g. a robot to drive).
    fn can_be_active(&self) -> bool {
        false
    }

    /// The scene node that stands for this plugin (picked to select it), if any.
    fn node(&self) -> Option<NodeId> {
        None
    }

    /// Called once before the plugin is removed (its device went away, the window is
    /// closing): takes its nodes out of the scene and withdraws its anchors, so that nothing
    /// it drew outlives it. The plugin is dropped right after.
    fn clean(&mut self, ctx: &mut PluginContext<'_>);
}
