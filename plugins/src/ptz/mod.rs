//! `libpv3d_ptz`: a pan-tilt-zoom camera mount's controls, in a small window of their own
//! beside the camera's image: sliders for pan, tilt and zoom that send the PTZ command as they
//! move, and the state the device reports. "Centre" looks straight ahead again.
//!
//! Parameters: `showWindow` (1); `maxPan` (180°), `maxTilt` (90°), `maxZoom` (90°, the widest
//! field of view): the sliders' ranges, so that a mount with smaller limits is not asked for
//! more.

pub mod target;

use player_proto::interfaces::ptz::{Ptz, PtzData};

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::LastTaken;
use framework::plugin::{Plugin, PluginContext, Service};
use framework::registry::Metadata;
use target::{Aim, Limits};

const CENTRE: &str = "Centre";

pub struct PtzPlugin {
    config: PluginConfig,
    show_window: bool,
    limits: Limits,
    taken: LastTaken,
    state: Option<PtzData>,
    /// What the sliders ask for; `None` until the device reports where it looks.
    aim: Option<Aim>,
}

impl PtzPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A pan-tilt-zoom mount: sliders that aim it and the state it reports, in a small window.",
    );

    pub fn create(
        config: PluginConfig,
        _ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let limits = Limits {
            pan: config.number("maxPan", 180.0, 0.0..=180.0)? as f32,
            tilt: config.number("maxTilt", 90.0, 0.0..=90.0)? as f32,
            zoom: config.number("maxZoom", 90.0, 1.0..=180.0)? as f32,
        };
        Ok(Box::new(PtzPlugin {
            show_window: config.bool("showWindow", true)?,
            config,
            limits,
            taken: LastTaken::default(),
            state: None,
            aim: None,
        }))
    }

    fn send(&self, aim: Aim, ctx: &PluginContext<'_>) {
        if let Some(device) = ctx.device {
            device.command(Ptz::CMD_STATE.to_body(aim.command(&self.limits)));
        }
    }

    fn state_text(&self) -> String {
        match &self.state {
            Some(s) => format!(
                "pan {:.0}°, tilt {:.0}°, zoom {:.0}°",
                s.pan.to_degrees(),
                s.tilt.to_degrees(),
                s.zoom.to_degrees()
            ),
            None => "no state yet".into(),
        }
    }

    /// The sliders; a move sends the command at once.
    fn controls(&mut self, ui: &mut egui::Ui, ctx: &PluginContext<'_>) {
        ui.label(self.state_text());
        let Some(mut aim) = self.aim else { return };
        if ctx.device.is_some_and(|d| d.read_only()) {
            return;
        }
        let before = aim;
        let l = self.limits;
        ui.add(egui::Slider::new(&mut aim.pan, -l.pan..=l.pan).text("pan °"));
        ui.add(egui::Slider::new(&mut aim.tilt, -l.tilt..=l.tilt).text("tilt °"));
        ui.add(egui::Slider::new(&mut aim.zoom, 0.0..=l.zoom).text("zoom °"));
        if ui.button(CENTRE).clicked() {
            aim.pan = 0.0;
            aim.tilt = 0.0;
        }
        if aim != before {
            self.send(aim, ctx);
            self.aim = Some(aim);
        }
    }
}

impl Plugin for PtzPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set_bool("showWindow", self.show_window);
        config
    }

    fn title(&self) -> String {
        self.config.titled("PTZ")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        if let Some((state, _)) = self.taken.newest_of::<PtzData>(ctx.device) {
            self.aim.get_or_insert(Aim::of(&state));
            self.state = Some(state);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        ui.label(self.state_text());
        ui.checkbox(&mut self.show_window, "show PTZ window");
    }

    fn windows(&mut self, egui_ctx: &egui::Context, ctx: &mut PluginContext<'_>) {
        if !self.show_window {
            return;
        }
        let mut open = true;
        egui::Window::new(self.title())
            .id(egui::Id::unique((
                "pv3d-ptz",
                &self.config.id,
                &self.config.origin,
            )))
            .open(&mut open)
            .resizable(false)
            // At the view's bottom right, clear of the item tree and the camera windows.
            .pivot(egui::Align2::RIGHT_BOTTOM)
            .default_pos(egui_ctx.content_rect().right_bottom() + egui::vec2(-12.0, -12.0))
            .show(egui_ctx, |ui| self.controls(ui, ctx));
        self.show_window = open;
    }

    fn services(&self) -> Vec<Service> {
        vec![Service::run(CENTRE, "pan and tilt back to straight ahead")]
    }

    fn run_service(&mut self, name: &str, ctx: &mut PluginContext<'_>) {
        if name == CENTRE {
            let zoom = self.aim.map_or(self.limits.zoom, |a| a.zoom);
            let aim = Aim {
                pan: 0.0,
                tilt: 0.0,
                zoom,
            };
            self.send(aim, ctx);
            self.aim = Some(aim);
        }
    }

    fn clean(&mut self, _ctx: &mut PluginContext<'_>) {}
}
