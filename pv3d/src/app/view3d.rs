//! The 3D view widget: camera input (pan, orbit, zoom, switch projection), the scene drawn by
//! our glow renderer through an egui paint callback, and labels drawn as text on top. A primary
//! drag that the viewer says starts a target (on the selected robot, or with Ctrl held) drags a
//! way-point over the ground instead of moving the camera.

use std::sync::{Arc, Mutex};

use eframe::egui::{self, Color32, Rect, Sense, Ui};
use eframe::egui_glow;
use eframe::glow::{self, HasContext};
use framework::scene::Scene;
use glam::{Vec2, Vec3};

use super::formula_textures::FormulaTextures;
use super::frame_times::{FRAME_TIMES, Stage};
use super::framing::Framing;
use crate::render::{
    Lighting, OrbitCamera, POINT_SIZE_PX, PictureFilters, Projection, SceneBatch, SceneRenderer,
    ScreenDetail, ViewTargets,
};

/// The size of a label's text, points.
const LABEL_POINTS: f32 = 13.0;
/// The em of a label typeset as math, points: larger than the text's, because a formula's
/// subscripts and exponents are set smaller still.
const FORMULA_EM_POINTS: f32 = 16.0;

/// GL-side state shared with the paint callback (which runs later, during painting).
#[derive(Default)]
struct GpuState {
    renderer: Option<SceneRenderer>,
    batch: SceneBatch,
    /// Counts rebuilds of `batch`, so the renderer uploads each one once.
    revision: u64,
    lighting: Lighting,
    failed: Option<String>,
    /// Off-screen targets of the scene's virtual cameras.
    views: ViewTargets,
    /// Filters the pictures plugins show in their windows.
    filters: PictureFilters,
}

/// What the person did in the view this frame, for the event handlers.
#[derive(Debug, Clone, Default)]
pub struct ViewInput {
    /// A primary click: the ray under the pointer (origin, direction) and the ground point.
    pub clicked: Option<(Vec3, Vec3, Option<Vec3>)>,
    /// A secondary click, same data.
    pub secondary_clicked: Option<(Vec3, Vec3, Option<Vec3>)>,
    /// The ground point under the pointer while hovering.
    pub hover_ground: Option<Vec3>,
    /// Whether any camera movement happened.
    pub camera_moved: bool,
    /// A target being dragged over the ground this frame.
    pub target_drag: Option<TargetDrag>,
}

/// A way-point dragged over the ground: the ground point under the pointer (`None` when the
/// pointer is off the ground, e.g. above the horizon).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TargetDrag {
    Moved(Option<Vec3>),
    Released(Option<Vec3>),
}

/// Decides, from the ray under the press, whether a primary drag moves a target.
pub type StartsTargetDrag<'a> = &'a dyn Fn(Vec3, Vec3) -> bool;

/// The 3D world view of one window.
#[derive(Default)]
pub struct View3d {
    pub camera: OrbitCamera,
    gpu: Arc<Mutex<GpuState>>,
    /// The scene generation and screen the batch was built for: a new camera or window size
    /// changes which details are finer than a pixel.
    batched_for: Option<(u64, ScreenDetail)>,
    /// Line segments drawn in the last frame built (for the status line and benchmarks).
    pub segments: usize,
    /// Frames the world until the person moves the view.
    framing: Framing,
    /// The primary drag under way moves a target, not the camera.
    dragging_target: bool,
    /// Labels written as math (`$…$`), typeset once each.
    formulas: FormulaTextures,
}

impl View3d {
    /// Shows the view in all of `ui`'s remaining space.
    pub fn show(&mut self, ui: &mut Ui, scene: &Scene) -> ViewInput {
        self.show_with_targets(ui, scene, None)
    }

    /// [`View3d::show`], where a primary drag for which `starts_target_drag` holds (or that
    /// starts with Ctrl held) drags a target over the ground instead of moving the camera.
    pub fn show_with_targets(
        &mut self,
        ui: &mut Ui,
        scene: &Scene,
        starts_target_drag: Option<StartsTargetDrag<'_>>,
    ) -> ViewInput {
        let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
        let mut input = ViewInput::default();
        let size = Vec2::new(rect.width(), rect.height());
        let aspect = size.x / size.y.max(1.0);
        let to_ndc = |p: egui::Pos2| {
            Vec2::new(
                (p.x - rect.left()) / rect.width() * 2.0 - 1.0,
                1.0 - (p.y - rect.top()) / rect.height() * 2.0,
            )
        };

        let ray_at = |camera: &OrbitCamera, p: egui::Pos2| {
            let (o, d) = camera.ray(to_ndc(p), aspect);
            (o, d, camera.ground_point(to_ndc(p), aspect, 0.0))
        };
        // A target drag: decided where the press began, then follows the pointer.
        if response.drag_started_by(egui::PointerButton::Primary)
            && let Some(starts) = starts_target_drag
            && let Some(press) = ui.input(|i| i.pointer.press_origin())
        {
            let (o, d, _) = ray_at(&self.camera, press);
            self.dragging_target = ui.input(|i| i.modifiers.ctrl) || starts(o, d);
        }
        if self.dragging_target {
            let at = response
                .interact_pointer_pos()
                .or_else(|| ui.input(|i| i.pointer.latest_pos()))
                .and_then(|p| ray_at(&self.camera, p).2);
            if response.drag_stopped() || !response.dragged() {
                self.dragging_target = false;
                input.target_drag = Some(TargetDrag::Released(at));
            } else {
                input.target_drag = Some(TargetDrag::Moved(at));
            }
        }
        // Camera: drag with the primary button pans (top) or orbits (perspective), the
        // secondary button always pans; the wheel zooms.
        if response.dragged() && input.target_drag.is_none() {
            let delta = response.drag_delta();
            let orbit = self.camera.projection == Projection::Perspective
                && response.dragged_by(egui::PointerButton::Primary)
                && !ui.input(|i| i.modifiers.shift);
            if orbit {
                self.camera.orbit(-delta.x * 0.01, delta.y * 0.01);
            } else {
                self.camera.pan_pixels(Vec2::new(delta.x, delta.y), size);
            }
            input.camera_moved = true;
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.camera.zoom((-scroll * 0.002).exp());
                input.camera_moved = true;
            }
        }
        if let Some(pointer) = response.hover_pos() {
            input.hover_ground = self.camera.ground_point(to_ndc(pointer), aspect, 0.0);
        }
        if response.clicked() {
            input.clicked = response
                .interact_pointer_pos()
                .map(|p| ray_at(&self.camera, p));
        }
        if response.secondary_clicked() {
            input.secondary_clicked = response
                .interact_pointer_pos()
                .map(|p| ray_at(&self.camera, p));
        }

        // Moving the view, or beginning to work in it (a click, a drag of a target), makes it
        // the person's: it is not framed under their pointer any more.
        if input.camera_moved || input.target_drag.is_some() || response.clicked() {
            self.framing.user_moved();
        }
        self.framing.update(&mut self.camera, scene, aspect);
        let view_proj = self.camera.view_projection(aspect);
        let viewport_px = size * ui.ctx().pixels_per_point();
        self.rebuild_batch(
            scene,
            ScreenDetail::new(view_proj, viewport_px, POINT_SIZE_PX),
        );
        self.paint(ui, rect, view_proj);
        self.paint_labels(ui, rect);
        input
    }

    fn rebuild_batch(&mut self, scene: &Scene, detail: ScreenDetail) {
        let wanted = (scene.generation(), detail);
        if self.batched_for == Some(wanted) {
            return;
        }
        let mut gpu = self.gpu.lock().expect("gpu state");
        FRAME_TIMES.timed(Stage::Batch, || gpu.batch.rebuild(scene, Some(&detail)));
        gpu.revision += 1;
        let light = scene.lighting();
        let [r, g, b, a] = light.background.0;
        gpu.lighting = Lighting {
            direction: light.direction,
            ambient: light.ambient,
            background: [r, g, b, a].map(|c| f32::from(c) / 255.0),
        };
        self.segments = gpu.batch.segment_count();
        self.batched_for = Some(wanted);
    }

    fn paint(&self, ui: &mut Ui, rect: Rect, view_proj: glam::Mat4) {
        let gpu = self.gpu.clone();
        let callback = egui_glow::CallbackFn::new(move |info, painter| {
            let gl = painter.gl();
            let painting = std::time::Instant::now();
            let mut gpu = gpu.lock().expect("gpu state");
            let state = &mut *gpu;
            if state.renderer.is_none() && state.failed.is_none() {
                match SceneRenderer::new(gl) {
                    Ok(r) => state.renderer = Some(r),
                    Err(e) => {
                        tracing::error!("3D view disabled: {e}");
                        state.failed = Some(e.to_string());
                    }
                }
            }
            let Some(renderer) = state.renderer.as_mut() else {
                return;
            };
            renderer.upload(gl, &state.batch, state.revision);
            state.filters.run(gl, &state.batch.filtered);
            if let Err(e) = state.views.render(gl, renderer, &state.batch.views) {
                tracing::warn!("virtual cameras not drawn: {e}");
            }
            let clip = info.clip_rect_in_pixels();
            // SAFETY: egui_glow made this context current and restores its state afterwards.
            unsafe {
                gl.enable(glow::SCISSOR_TEST);
                gl.scissor(
                    clip.left_px,
                    clip.from_bottom_px,
                    clip.width_px,
                    clip.height_px,
                );
            }
            renderer.draw(gl, view_proj);
            FRAME_TIMES.record(Stage::ViewPaint, painting.elapsed());
        });
        ui.painter().add(egui::PaintCallback {
            rect,
            callback: Arc::new(callback),
        });
    }

    /// Draws the labels, leaving out any that would overlap one already drawn: 256 robot
    /// names on top of each other are unreadable, every other one is not. Zoom in and all
    /// of them come back. A label that is math (`$…$`) shows typeset, in its colour, on a
    /// transparent background.
    fn paint_labels(&mut self, ui: &mut Ui, rect: Rect) {
        let gpu = self.gpu.lock().expect("gpu state");
        let size = Vec2::new(rect.width(), rect.height());
        let painter = ui.painter_at(rect);
        let mut taken: Vec<Rect> = Vec::new();
        for label in &gpu.batch.labels {
            let Some(at) = self.camera.to_screen(label.pos, size) else {
                continue;
            };
            let at = rect.min + egui::vec2(at.x, at.y);
            let formula = self
                .formulas
                .get(ui.ctx(), &label.text, label.color, FORMULA_EM_POINTS);
            let [r, g, b, a] = label.color.0;
            let color = Color32::from_rgba_unmultiplied(r, g, b, a);
            let (galley, shape_size) = match &formula {
                Some(f) => (None, f.size),
                None => {
                    let galley = painter.layout_no_wrap(
                        label.text.clone(),
                        egui::FontId::proportional(LABEL_POINTS),
                        color,
                    );
                    let size = galley.size();
                    (Some(galley), size)
                }
            };
            let place = egui::Align2::LEFT_BOTTOM.anchor_size(at, shape_size);
            if !rect.intersects(place) || taken.iter().any(|t| t.intersects(place)) {
                continue;
            }
            taken.push(place);
            match (formula, galley) {
                (Some(f), _) => {
                    let whole = Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
                    painter.image(f.texture.id(), place, whole, Color32::WHITE);
                }
                (None, Some(galley)) => painter.galley(place.min, galley, color),
                (None, None) => {}
            }
        }
    }
}
