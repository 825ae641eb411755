//! `libpv3d_map`: a Player `map` device's occupancy grid, drawn on the ground at the map's
//! origin and resolution — free cells nearly white, unknown grey, occupied nearly black — as
//! one picture, so that a 4000 × 4000 grid costs one textured quad per frame.
//!
//! The plugin asks for the map's info, then for its tiles ([`grid::TILE_SIDE`] cells on a
//! side at most, a few in flight at a time), and shows the grid once every tile has answered.
//! A tile that does not inflate or lies outside the map stays unknown and is reported; a map
//! whose size is not believable is refused before anything is allocated.
//!
//! Parameters (all optional): `height` (0 m: where the picture lies, above the map's
//! origin); any number of `<filter>` kernels run on the grid in order
//! (`framework::scene::filter_config`), where a `radius` is in metres: `<filter
//! radius="0.3">dilate</filter>` grows the obstacles by a robot's radius — its
//! configuration space — and `<filter>sobel</filter>` keeps only the walls' outlines.
//! `dilate` and `erode` speak of the obstacles: occupied cells are dark, so growing them is
//! a grey-level erosion, which is what the plugin asks the renderer for.

mod answers;
pub mod fetch;
pub mod grid;

use glam::{Affine3A, Vec2, Vec3};

use framework::config::{ConfigValueError, PluginConfig};
use framework::plugin::{Plugin, PluginContext, Service};
use framework::registry::Metadata;
use framework::scene::filter_config::read_filter_chain;
use framework::scene::pose::transform_of_2d;
use framework::scene::{FilterChain, ImageQuad, Kernel, NodeId, Object3D, Sampling, Scene};

use fetch::MapFetch;
use grid::OccupancyGrid;

const RELOAD: Service = Service::run("Reload", "Ask the server for the whole map again");

pub struct MapPlugin {
    config: PluginConfig,
    height: f32,
    node: NodeId,
    fetch: MapFetch,
    /// The chain as drawn (radii in cells), or why it could not be made for this map.
    chain: Result<FilterChain, ConfigValueError>,
    /// The map is on the scene.
    shown: bool,
}

impl MapPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A Player map (mapfile, a SLAM driver) drawn on the ground as an occupancy grid, optionally through GLSL kernels (dilation: the robot's configuration space).",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let height = config.number("height", 0.0, -100.0..=100.0)? as f32;
        // Names, numbers and files are checked now; radii once the resolution is known.
        read_filter_chain(&config, "filter", |_| 0.0)?;
        let mut node = Object3D::new(config.titled("Map"));
        node.tags.push("map".into());
        let node = ctx.scene.add(node);
        Ok(Box::new(MapPlugin {
            fetch: MapFetch::start(ctx.device),
            config,
            height,
            node,
            chain: Ok(FilterChain::default()),
            shown: false,
        }))
    }

    /// Puts the grid on the scene as it is now.
    fn show(&mut self, scene: &mut Scene) {
        let Some(grid) = self.fetch.grid() else {
            return;
        };
        let info = *grid.info();
        let (w, h) = grid.size_m();
        let pixels = match grid.pixels() {
            Ok(p) => p,
            Err(e) => {
                tracing::error!("map not drawn: {e}");
                return;
            }
        };
        let scale = f64::from(info.scale);
        self.chain =
            read_filter_chain(&self.config, "filter", |metres| metres / scale).map(obstacle_view);
        if let Err(e) = &self.chain {
            tracing::error!("map drawn unfiltered: {e}");
        }
        let mut quad = ImageQuad::new(pixels, Vec3::ZERO, Vec2::new(w, h), Sampling::Grid);
        quad.filters = self.chain.clone().unwrap_or_default();
        let Some(node) = scene.get_mut(self.node) else {
            return;
        };
        node.transform =
            Affine3A::from_translation(Vec3::Z * self.height) * transform_of_2d(&info.origin);
        node.geometry.clear();
        node.geometry.images.push(quad);
        self.shown = true;
    }
}

/// The chain with `dilate` and `erode` turned to act on the dark obstacles.
fn obstacle_view(chain: FilterChain) -> FilterChain {
    let kernels = chain
        .0
        .into_iter()
        .map(|k| match k {
            Kernel::Dilate { radius } => Kernel::Erode { radius },
            Kernel::Erode { radius } => Kernel::Dilate { radius },
            other => other,
        })
        .collect();
    FilterChain(kernels)
}

impl Plugin for MapPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.config.titled("Map")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        let polled = self.fetch.poll(ctx.device);
        if polled.info_arrived
            && let Some(info) = self.fetch.grid().map(OccupancyGrid::info)
        {
            tracing::info!(
                plugin = %self.config.id,
                "map {}×{} cells at {} m, {} tiles to fetch",
                info.width,
                info.height,
                info.scale,
                self.fetch.tiles_total
            );
        }
        let answered = polled.info_arrived || polled.tiles_answered > 0;
        if answered && self.fetch.is_complete() {
            self.show(ctx.scene);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        let red = egui::Color32::from_rgb(230, 80, 60);
        if let Some(e) = &self.fetch.fatal {
            ui.colored_label(red, e);
        }
        let Some(grid) = self.fetch.grid() else {
            if self.fetch.fatal.is_none() {
                ui.label("waiting for the map's info");
            }
            return;
        };
        let info = grid.info();
        let (w, h) = grid.size_m();
        ui.label(format!(
            "{} × {} cells, {w:.1} × {h:.1} m",
            info.width, info.height
        ));
        ui.label(format!("resolution {} m per cell", info.scale));
        ui.label(format!(
            "origin ({:.2}, {:.2}) m, {:.1}°",
            info.origin.px,
            info.origin.py,
            info.origin.pa.to_degrees()
        ));
        ui.label(format!(
            "tiles received {} of {}{}",
            self.fetch.tiles_received,
            self.fetch.tiles_total,
            if self.fetch.tiles_failed > 0 {
                format!(", {} failed", self.fetch.tiles_failed)
            } else {
                String::new()
            }
        ));
        for e in &self.fetch.tile_errors {
            ui.colored_label(red, e);
        }
        match &self.chain {
            Ok(chain) if !chain.is_empty() => {
                ui.label(format!("filters: {}", chain.describe()));
            }
            Ok(_) => {}
            Err(e) => {
                ui.colored_label(red, e.to_string());
            }
        }
    }

    fn services(&self) -> Vec<Service> {
        vec![RELOAD]
    }

    fn run_service(&mut self, name: &str, ctx: &mut PluginContext<'_>) {
        if name == RELOAD.name {
            self.fetch = MapFetch::start(ctx.device);
        }
    }

    fn answer(
        &mut self,
        query: &framework::query::Query,
        _ctx: &mut PluginContext<'_>,
    ) -> Option<framework::query::Reply> {
        self.answer_query(query)
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
