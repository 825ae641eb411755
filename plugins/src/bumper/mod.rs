//! `libpv3d_bumper`: a robot's bumpers under its body, each where the bumper geometry says it
//! is: dim while free, lit red while pressed, so a person sees which side hit something.
//!
//! Parameters: `<parentNode interface="position2d"/>` (the robot); `color` (#e03c32, pressed);
//! `idleColor` (#787878). Until the geometry arrives (asked for once, or pushed as data) the
//! bumpers are listed in the panel but not drawn: their places are unknown.

pub mod segments;

use player_proto::interfaces::bumper::{Bumper, BumperData, BumperDefine, BumperGeometry};

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D, Rgba, Scene};
use segments::bumper_polyline;

pub struct BumperPlugin {
    config: PluginConfig,
    pressed_color: Rgba,
    idle_color: Rgba,
    node: NodeId,
    parent: ParentLink,
    geometry_reply: Awaited<BumperGeometry>,
    geometry_taken: LastTaken,
    state_taken: LastTaken,
    bumpers: Vec<BumperDefine>,
    pressed: Vec<bool>,
}

impl BumperPlugin {
    pub const METADATA: Metadata =
        crate::standard_metadata("A robot's bumpers under its body, the pressed ones lit red.");

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let pressed_color = config.color("color", Rgba::rgb(224, 60, 50))?;
        let idle_color = config.color("idleColor", Rgba::rgb(120, 120, 120))?;
        let mut object = Object3D::new(config.titled("bumper"));
        object.tags.push("bumper".into());
        let node = ctx.scene.add(object);
        Ok(Box::new(BumperPlugin {
            parent: ParentLink::from_config(&config),
            geometry_reply: Awaited::fetch(ctx.device, Bumper::REQ_GET_GEOM),
            config,
            pressed_color,
            idle_color,
            node,
            geometry_taken: LastTaken::default(),
            state_taken: LastTaken::default(),
            bumpers: Vec::new(),
            pressed: Vec::new(),
        }))
    }

    fn redraw(&self, scene: &mut Scene) {
        let Some(object) = scene.get_mut(self.node) else {
            return;
        };
        object.geometry.clear();
        for (i, bumper) in self.bumpers.iter().enumerate() {
            let pressed = self.pressed.get(i).copied().unwrap_or(false);
            let color = if pressed {
                self.pressed_color
            } else {
                self.idle_color
            };
            for pair in bumper_polyline(bumper).windows(2) {
                object.geometry.line(pair[0], pair[1], color);
            }
        }
    }

    /// The geometry, from the reply or pushed as data; whether it changed.
    fn take_geometry(&mut self, ctx: &PluginContext<'_>) -> bool {
        let pushed = self
            .geometry_taken
            .newest_of::<BumperGeometry>(ctx.device)
            .map(|(g, _)| g);
        let replied = match self.geometry_reply.take() {
            Some(Ok(g)) => Some(g),
            Some(Err(e)) => {
                tracing::warn!(plugin = %self.config.id, "no bumper geometry: {e}");
                None
            }
            None => None,
        };
        match pushed.or(replied) {
            Some(g) => {
                self.bumpers = g.bumper_def;
                true
            }
            None => false,
        }
    }
}

impl Plugin for BumperPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.config.titled("Bumper")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        let mut changed = self.take_geometry(ctx);
        if let Some((data, _)) = self.state_taken.newest_of::<BumperData>(ctx.device) {
            let pressed: Vec<bool> = data.bumpers.iter().map(|&b| b != 0).collect();
            changed |= pressed != self.pressed;
            self.pressed = pressed;
        }
        if changed {
            self.redraw(ctx.scene);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        if self.pressed.is_empty() {
            ui.label("no reading yet");
            return;
        }
        let hit: Vec<String> = (0..self.pressed.len())
            .filter(|&i| self.pressed[i])
            .map(|i| i.to_string())
            .collect();
        if hit.is_empty() {
            ui.label(format!("{} bumpers, none pressed", self.pressed.len()));
        } else {
            ui.colored_label(
                egui::Color32::from_rgb(230, 80, 60),
                format!("pressed: {}", hit.join(", ")),
            );
        }
        if self.bumpers.is_empty() {
            ui.small("geometry unknown: not drawn");
        }
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
