//! `libpv3d_virtual_camera`: a camera inside the simulated world. The viewer renders the scene
//! from its pose with its intrinsics into an off-screen picture (`framework::scene::VirtualView`);
//! this plugin shows that picture in its own window and the camera's frustum in the world —
//! the paper's "simulation of a camera projection".
//!
//! Parameters (all optional): `pose` (`x y z yaw`, m and degrees, relative to its parent or
//! the world; `0 0 0.4 0`), `pitch` (degrees down, 0), `fov` (vertical, degrees, 60), `width`
//! and `height` (pixels, 320 × 240), `parentNode` (the robot it rides on, for a camera made in
//! a robot's device handler, as a laser's; none = fixed in the world),
//! `frustumLength` (m, 1; 0 hides it), `color` (the frustum's, `#ffd040`), `showWindow` (1),
//! `servePort` (none: serve each picture as Player device `camera:0` on this port of
//! 127.0.0.1, see [`serve`]), `project` (`none`; `ground`: the picture laid on the ground along
//! the frustum, within `projectDistance` m (5) at `projectResolution` pixels (256);
//! `billboard`: the picture `billboardWidth` m wide (1), its lower edge `billboardHeight` m
//! (0.8) above the camera, turned towards the viewer — see [`projection`]).

pub mod frustum;
pub mod projection;
pub mod serve;

use std::sync::Arc;

use framework::config::{ConfigValueError, PluginConfig};
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D, Pixels, Rgba, ViewOutput, VirtualView};
use glam::{Affine3A, EulerRot, Quat, Vec3};
use image::RgbaImage;

use crate::camera::window::{CameraWindow, Picture};
use framework::parent_link::ParentLink;
use projection::Placement;
use serve::CameraServer;

/// Where the camera sits by default: on a robot's top, looking ahead.
const DEFAULT_POSE: [f64; 4] = [0.0, 0.0, 0.4, 0.0];
const DEFAULT_FOV_DEG: f64 = 60.0;
const DEFAULT_WIDTH: f64 = 320.0;
const DEFAULT_HEIGHT: f64 = 240.0;
/// The largest picture offered: a rendered camera larger than a 4K screen is a typo.
const MAX_SIDE: f64 = 4096.0;
const DEFAULT_FRUSTUM_M: f64 = 1.0;
const DEFAULT_COLOUR: Rgba = Rgba::rgb(255, 208, 64);
const DEFAULT_PROJECT_DISTANCE_M: f64 = 5.0;
const DEFAULT_PROJECT_RESOLUTION: f64 = 256.0;
const MAX_PROJECT_RESOLUTION: f64 = 2048.0;
const DEFAULT_BILLBOARD_WIDTH_M: f64 = 1.0;
const DEFAULT_BILLBOARD_HEIGHT_M: f64 = 0.8;

/// Where the picture goes back into the world, and how.
struct Projection {
    placement: Placement,
    /// The node holding the picture: fixed in the world (ground) or on the camera (billboard).
    node: Option<NodeId>,
    distance: f32,
    resolution: u32,
    billboard_width: f32,
    /// How far above the camera the billboard's lower edge floats, m (straight up in the world
    /// however the camera is pitched).
    billboard_height: f32,
}

pub struct VirtualCameraPlugin {
    config: PluginConfig,
    node: NodeId,
    output: ViewOutput,
    parent: ParentLink,
    /// The newest picture, top row first, as the window wants it.
    image: Option<Arc<RgbaImage>>,
    shown_generation: Option<u64>,
    frames: u64,
    window: CameraWindow,
    show_window: bool,
    size: (u32, u32),
    server: Option<CameraServer>,
    projection: Projection,
}

impl VirtualCameraPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A camera in the simulated world: the scene rendered from its pose, in its own window, with its frustum.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let pose = config
            .numbers("pose", DEFAULT_POSE.len())?
            .unwrap_or(DEFAULT_POSE.to_vec());
        let pitch = config.number("pitch", 0.0, -90.0..=90.0)?;
        let fov = config.number("fov", DEFAULT_FOV_DEG, 1.0..=170.0)?;
        let width = config.number("width", DEFAULT_WIDTH, 1.0..=MAX_SIDE)? as u32;
        let height = config.number("height", DEFAULT_HEIGHT, 1.0..=MAX_SIDE)? as u32;
        let frustum = config.number("frustumLength", DEFAULT_FRUSTUM_M, 0.0..=1000.0)? as f32;
        let colour = config.color("color", DEFAULT_COLOUR)?;
        let show_window = config.bool("showWindow", true)?;
        let parent = ParentLink::from_config(&config);
        let server = start_server(&config)?;
        let placement_text = config.text("project").unwrap_or("none");
        let placement = Placement::parse(placement_text).ok_or_else(|| {
            config_error(
                &config,
                "project",
                format!("expected none, ground or billboard, found {placement_text:?}"),
            )
        })?;
        let distance =
            config.number("projectDistance", DEFAULT_PROJECT_DISTANCE_M, 0.1..=1000.0)? as f32;
        let resolution = config.number(
            "projectResolution",
            DEFAULT_PROJECT_RESOLUTION,
            1.0..=MAX_PROJECT_RESOLUTION,
        )? as u32;
        let billboard_width =
            config.number("billboardWidth", DEFAULT_BILLBOARD_WIDTH_M, 0.01..=100.0)? as f32;
        let billboard_height = config.number(
            "billboardHeight",
            DEFAULT_BILLBOARD_HEIGHT_M,
            -100.0..=100.0,
        )? as f32;

        // Pitch turns about the camera's y; positive looks down.
        let rotation = Quat::from_euler(
            EulerRot::ZYX,
            (pose[3] as f32).to_radians(),
            (pitch as f32).to_radians(),
            0.0,
        );
        let translation = Vec3::new(pose[0] as f32, pose[1] as f32, pose[2] as f32);
        let view = VirtualView::new(Affine3A::IDENTITY, (fov as f32).to_radians(), width, height)
            .map_err(|e| config_error(&config, "fov", e.to_string()))?;
        let output = view.output.clone();
        let mut object = Object3D::new(title(&config));
        object.tags.push("camera".into());
        object.transform = Affine3A::from_rotation_translation(rotation, translation);
        if frustum > 0.0 {
            frustum::draw_frustum(&mut object.geometry, &view, frustum, colour);
        }
        object.geometry.views.push(view);
        let node = ctx.scene.add(object);
        let projection_node = match placement {
            Placement::None => None,
            Placement::Ground => Some(
                ctx.scene
                    .add(Object3D::new(format!("{} on the ground", title(&config)))),
            ),
            Placement::Billboard => {
                let mut board = Object3D::new(format!("{} billboard", title(&config)));
                board.parent = Some(node);
                board.transform = Affine3A::from_translation(Vec3::Z * billboard_height);
                Some(ctx.scene.add(board))
            }
        };
        Ok(Box::new(VirtualCameraPlugin {
            config,
            node,
            output,
            parent,
            image: None,
            shown_generation: None,
            frames: 0,
            window: CameraWindow::default(),
            show_window,
            size: (width, height),
            server,
            projection: Projection {
                placement,
                node: projection_node,
                distance,
                resolution,
                billboard_width,
                billboard_height,
            },
        }))
    }

    /// The newest rendered picture, rows bottom-up as the viewer made it.
    pub fn latest(&self) -> Option<Pixels> {
        self.output.latest()
    }

    /// Pictures received so far.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// The node carrying the camera (and its frustum).
    pub fn node_id(&self) -> NodeId {
        self.node
    }
}

/// The Player server `servePort` asks for, if any; a port that is taken or not a port is a
/// configuration error naming the parameter.
fn start_server(config: &PluginConfig) -> Result<Option<CameraServer>, ConfigValueError> {
    let Some(param) = config.param("servePort") else {
        return Ok(None);
    };
    let port = config.number("servePort", 0.0, 1.0..=f64::from(u16::MAX))?;
    if port.fract() != 0.0 {
        return Err(config_error(
            config,
            "servePort",
            format!("{port} is not a whole port number"),
        ));
    }
    match CameraServer::start(port as u16) {
        Ok(server) => {
            tracing::info!(port = server.port(), "virtual camera served as camera:0");
            Ok(Some(server))
        }
        Err(e) => Err(ConfigValueError {
            origin: param.origin.clone(),
            ..config_error(config, "servePort", e.to_string())
        }),
    }
}

fn config_error(config: &PluginConfig, param: &str, message: String) -> ConfigValueError {
    ConfigValueError {
        origin: config.origin.clone(),
        library: config.library.clone(),
        param: param.into(),
        message,
    }
}

impl VirtualCameraPlugin {
    /// Puts the new picture back into the world where `project` asked.
    fn project(&self, pixels: &Pixels, ctx: &mut PluginContext<'_>) {
        let Some(node) = self.projection.node else {
            return;
        };
        let quad = match self.projection.placement {
            Placement::None => return,
            Placement::Ground => {
                let Some(view) = ctx
                    .scene
                    .get(self.node)
                    .and_then(|o| o.geometry.views.first().cloned())
                else {
                    return;
                };
                let camera_to_world = ctx.scene.world_transform(self.node) * view.pose;
                projection::onto_ground(
                    &view,
                    camera_to_world,
                    pixels,
                    self.projection.distance,
                    self.projection.resolution,
                )
            }
            Placement::Billboard => {
                // Straight up in the world, wherever the camera points.
                let up = ctx
                    .scene
                    .world_transform(self.node)
                    .inverse()
                    .transform_vector3(Vec3::Z * self.projection.billboard_height);
                if let Some(board) = ctx.scene.get_mut(node) {
                    board.transform = Affine3A::from_translation(up);
                }
                Some(projection::billboard(
                    pixels,
                    self.projection.billboard_width,
                ))
            }
        };
        if let Some(object) = ctx.scene.get_mut(node) {
            object.geometry.images.clear();
            object.geometry.images.extend(quad);
        }
    }
}

fn title(config: &PluginConfig) -> String {
    match config.id.as_str() {
        "" => "Virtual camera".into(),
        id => format!("Virtual camera {id}"),
    }
}

/// Pictures count rows from the bottom, windows from the top.
fn top_row_first(pixels: &Pixels) -> Option<RgbaImage> {
    let row = pixels.width() as usize * pixels.format().bytes_per_pixel();
    let rgba: Vec<u8> = match pixels.format() {
        framework::scene::PixelFormat::Rgba8 => pixels
            .bytes()
            .chunks_exact(row)
            .rev()
            .flatten()
            .copied()
            .collect(),
        framework::scene::PixelFormat::Gray8 => pixels
            .bytes()
            .chunks_exact(row)
            .rev()
            .flatten()
            .flat_map(|&g| [g, g, g, u8::MAX])
            .collect(),
    };
    RgbaImage::from_raw(pixels.width(), pixels.height(), rgba)
}

impl Plugin for VirtualCameraPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set_bool("showWindow", self.show_window);
        config
    }

    fn title(&self) -> String {
        title(&self.config)
    }

    /// Attaches to the robot once it is known and takes the picture rendered last frame.
    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        let Some(pixels) = self.output.latest() else {
            return;
        };
        if self.shown_generation == Some(pixels.generation()) {
            return;
        }
        self.shown_generation = Some(pixels.generation());
        if let Some(server) = &self.server {
            server.publish(&pixels);
        }
        self.image = top_row_first(&pixels).map(Arc::new);
        self.frames += 1;
        self.project(&pixels, ctx);
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        ui.label(format!(
            "{} × {} pixels, {} frames rendered",
            self.size.0, self.size.1, self.frames
        ));
        if let Some(server) = &self.server {
            ui.label(format!("served as camera:0 on port {}", server.port()));
        }
        ui.checkbox(&mut self.show_window, "show image window");
    }

    fn windows(&mut self, egui_ctx: &egui::Context, _ctx: &mut PluginContext<'_>) {
        let id = format!("virtual-camera#{}#{}", self.config.id, self.config.origin);
        let picture = Picture {
            image: self.image.as_deref(),
            version: self.frames,
            summary: format!("{} × {} rendered", self.size.0, self.size.1),
        };
        let title = self.title();
        self.window
            .show_picture(egui_ctx, &id, &title, picture, &mut self.show_window);
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
        if let Some(node) = self.projection.node {
            ctx.scene.remove(node);
        }
    }
}
