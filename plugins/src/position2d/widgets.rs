//! The robot's egui controls: its panel in the item tree, the joystick, the drive-mode switch
//! and the "Go to point…" popup.

use glam::Vec2;

use super::Position2dPlugin;
use super::goal::{DriveMode, Goal};
use framework::device::ConnectionState;
use framework::plugin::PluginContext;

/// The egui id of robot `robot`'s joystick in `place` (`"tree"` or `"view"`), stable so that
/// tests (and tools) can find the pad: `egui::Context::read_response(joystick_id(..))`.
pub fn joystick_id(robot: &str, place: &str) -> egui::Id {
    egui::Id::unique(("pv3d-joystick", robot, place))
}

impl Position2dPlugin {
    /// The item tree's panel: pose, velocity, condition, why it waits, and the controls.
    pub(super) fn panel(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        let (x, y, a) = self.pose;
        ui.label(format!("pose ({x:.2}, {y:.2}) m, {:.0}°", a.to_degrees()));
        ui.label(format!(
            "velocity {:.2} m/s, {:.2} rad/s",
            self.velocity.0, self.velocity.1
        ));
        self.skin.ui(ui);
        if self.stalled {
            ui.colored_label(egui::Color32::from_rgb(230, 90, 80), "STALLED");
        }
        if let Some(why) = &self.refused {
            ui.small(format!("last goal given up: {why}"));
        }
        if let Some(zone) = self.zone_guard.blocked_by() {
            ui.small(format!("waiting: the way ahead enters {zone:?}"));
        }
        if let Some(device) = ctx.device {
            let state = device.link_state();
            if state != ConnectionState::Connected {
                ui.colored_label(egui::Color32::from_rgb(230, 190, 80), format!("{state:?}"));
            }
        }
        if ctx.device.is_some_and(|d| d.read_only()) {
            ui.small("observing: no tele-operation");
            return;
        }
        ui.add(egui::Slider::new(&mut self.limits.max_speed, 0.0..=2.0).text("max m/s"));
        ui.add(egui::Slider::new(&mut self.limits.max_turn, 0.0..=3.0).text("max rad/s"));
        ui.add(egui::Slider::new(&mut self.follow_distance, 0.0..=3.0).text("follow m"));
        self.mode_ui(ui);
        self.joystick_ui(ui, "tree");
        if self.active {
            ui.small(
                "click or Ctrl+drag the ground to send the robot there; click a marker for actions",
            );
        }
    }

    /// A square pad: drag the knob to drive (velocity commands), let go to stop. `place` tells
    /// the item tree's pad from the one over the view (see [`joystick_id`]).
    pub(super) fn joystick_ui(&mut self, ui: &mut egui::Ui, place: &str) {
        let size = egui::vec2(110.0, 110.0);
        let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
        let response = ui.interact(
            rect,
            joystick_id(&self.config.id, place),
            egui::Sense::drag(),
        );
        let painter = ui.painter_at(rect);
        painter.rect_stroke(
            rect,
            6.0,
            egui::Stroke::new(1.0, egui::Color32::GRAY),
            egui::StrokeKind::Inside,
        );
        let centre = rect.center();
        let mut knob = centre;
        if response.dragged()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let d = (pointer - centre) / (size.x / 2.0);
            let deflection = Vec2::new(d.x, -d.y).clamp_length_max(1.0);
            knob = centre + egui::vec2(deflection.x, -deflection.y) * size.x / 2.0;
            self.joystick = Some(deflection);
            self.goal = None;
            self.dragging = None;
        } else if self.joystick.is_some() {
            // Let go: stop at once.
            self.joystick = Some(Vec2::ZERO);
        }
        painter.circle_filled(knob, 9.0, egui::Color32::from_rgb(90, 150, 230));
    }

    /// Velocity (the viewer steers) or position (the server drives to way-points).
    pub(super) fn mode_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.label("drive by");
            for mode in [DriveMode::Velocity, DriveMode::Position] {
                ui.selectable_value(&mut self.mode, mode, mode.name());
            }
        });
    }

    /// The "Go to point…" popup: type a point, go. Returns whether it stays open.
    pub(super) fn go_to_point_popup(
        &mut self,
        ui: &mut egui::Ui,
        ctx: &mut PluginContext<'_>,
    ) -> bool {
        ui.horizontal(|ui| {
            ui.label("x");
            ui.add(egui::DragValue::new(&mut self.typed_point.x).speed(0.05));
            ui.label("y");
            ui.add(egui::DragValue::new(&mut self.typed_point.y).speed(0.05));
            ui.label("m");
        });
        let mut open = true;
        ui.horizontal(|ui| {
            if ui.button("Go").clicked() {
                self.set_goal(Goal::Point(self.typed_point), ctx);
                open = false;
            }
            if ui.button("Cancel").clicked() {
                open = false;
            }
        });
        open
    }
}
