//! `libpv3d_ground`, `libpv3d_grid` and `libpv3d_lights`: the stage the robots stand on.
//!
//! The ground is a plain plane, optionally with the walls of a floorplan bitmap standing on it
//! (`<bitmap>../stage-worlds/bitmaps/arena.png</bitmap> <bitmapSize>20 16</bitmapSize>`,
//! optional `<bitmapCentre>0 0</bitmapCentre>`, `<wallHeight>0.5</wallHeight>`, `<wallColor>`;
//! `<size>` is the plane's own extent), and walls drawn with Stage blocks, each a polygon
//! (`<wall>-5 -4  5 -4  5 -3.8  -5 -3.8</wall>`, any number) stood up to `wallHeight`, or
//! to their own `height` and `color` attributes (obstacles); the grid draws
//! metre lines and axes; the lights set the light direction, ambient level and background.

mod floorplan;

pub use floorplan::{FloorplanError, Placement, walls_from_bitmap};

use glam::Vec3;

use framework::config::{ConfigValueError, Param, PluginConfig};
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::polygon::{parse_corners, prism};
use framework::scene::{NodeId, Object3D, Rgba, SceneLighting};

/// Fixed scene content placed once: the ground plane, the grid.
struct Fixture {
    config: PluginConfig,
    title: &'static str,
    node: NodeId,
}

impl Plugin for Fixture {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.title.into()
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}

/// A plane under everything.
pub struct Ground;

impl Ground {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A plane under everything, with the walls of a floorplan bitmap or of Stage blocks standing on it.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let size = config.number("size", 40.0, 0.1..=10_000.0)? as f32;
        let color = config.color("color", Rgba::rgb(52, 56, 62))?;
        let mut object = Object3D::new("ground");
        let h = size / 2.0;
        let corners = [
            Vec3::new(-h, -h, -0.01),
            Vec3::new(h, -h, -0.01),
            Vec3::new(h, h, -0.01),
            Vec3::new(-h, h, -0.01),
        ];
        object
            .geometry
            .triangle(corners[0], corners[1], corners[2], color);
        object
            .geometry
            .triangle(corners[0], corners[2], corners[3], color);
        if let Some(path) = config.path("bitmap") {
            let size = config
                .numbers("bitmapSize", 2)?
                .unwrap_or(vec![f64::from(size), f64::from(size)]);
            let centre = config.numbers("bitmapCentre", 2)?.unwrap_or(vec![0.0, 0.0]);
            let placement = Placement {
                size: (size[0] as f32, size[1] as f32),
                centre: (centre[0] as f32, centre[1] as f32),
                wall_height: config.number("wallHeight", 0.5, 0.0..=100.0)? as f32,
            };
            let wall_color = config.color("wallColor", Rgba::rgb(150, 150, 158))?;
            walls_from_bitmap(&path, placement, wall_color, &mut object.geometry).map_err(|e| {
                ConfigValueError {
                    origin: config
                        .param("bitmap")
                        .map(|p| p.origin.clone())
                        .unwrap_or_default(),
                    library: config.library.clone(),
                    param: "bitmap".into(),
                    message: e.to_string(),
                }
            })?;
        }
        // Walls drawn with Stage blocks: each <wall> a polygon, stood up to wallHeight.
        let walls: Vec<&Param> = config.params.iter().filter(|p| p.name == "wall").collect();
        if !walls.is_empty() {
            let height = config.number("wallHeight", 0.5, 0.0..=100.0)? as f32;
            let wall_color = config.color("wallColor", Rgba::rgb(150, 150, 158))?;
            for wall in walls {
                let bad = |message: String| ConfigValueError {
                    origin: wall.origin.clone(),
                    library: config.library.clone(),
                    param: "wall".into(),
                    message,
                };
                let corners = parse_corners(&wall.text).map_err(|e| bad(e.to_string()))?;
                // A wall may be an obstacle of its own height and colour (a crate, a landmark).
                let height = match wall.attr("height") {
                    Some(h) => h
                        .trim()
                        .parse::<f32>()
                        .ok()
                        .filter(|h| (0.0..=100.0).contains(h))
                        .ok_or_else(|| bad(format!("height {h:?} is not metres from 0 to 100")))?,
                    None => height,
                };
                let color = match wall.attr("color") {
                    Some(c) => framework::config::parse_color(c.trim()).ok_or_else(|| {
                        bad(format!("color {c:?} is not a colour such as #808080"))
                    })?,
                    None => wall_color,
                };
                prism(&corners, height, color, &mut object.geometry);
            }
        }
        object.tags.push("ground".into());
        let node = ctx.scene.add(object);
        Ok(Box::new(Fixture {
            config,
            title: "Ground",
            node,
        }))
    }
}

/// Metre grid lines and the x (red) and y (green) axes.
pub struct Grid;

impl Grid {
    pub const METADATA: Metadata = crate::standard_metadata(
        "Metre lines and the x and y axes on the ground, to judge distances and directions by.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let size = config.number("size", 40.0, 1.0..=10_000.0)? as f32;
        let spacing = config.number("spacing", 1.0, 0.01..=1000.0)? as f32;
        let color = config.color("color", Rgba::rgb(78, 84, 92))?;
        let mut object = Object3D::new("grid");
        let n = (size / 2.0 / spacing).floor() as i32;
        let h = n as f32 * spacing;
        for i in -n..=n {
            let f = i as f32 * spacing;
            if i != 0 {
                object
                    .geometry
                    .line(Vec3::new(f, -h, 0.0), Vec3::new(f, h, 0.0), color);
                object
                    .geometry
                    .line(Vec3::new(-h, f, 0.0), Vec3::new(h, f, 0.0), color);
            }
        }
        object.geometry.line(
            Vec3::new(-h, 0.0, 0.0),
            Vec3::new(h, 0.0, 0.0),
            Rgba::rgb(170, 70, 60),
        );
        object.geometry.line(
            Vec3::new(0.0, -h, 0.0),
            Vec3::new(0.0, h, 0.0),
            Rgba::rgb(70, 160, 80),
        );
        // Decoration: the view frames the content, not the grid.
        object.tags.push("grid".into());
        let node = ctx.scene.add(object);
        Ok(Box::new(Fixture {
            config,
            title: "Grid",
            node,
        }))
    }
}

/// The scene's lighting.
pub struct Lights {
    config: PluginConfig,
}

impl Lights {
    pub const METADATA: Metadata = crate::standard_metadata(
        "The scene's light direction, ambient level and background colour.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let defaults = SceneLighting::default();
        let azimuth = config
            .number("azimuth", 143.0, -360.0..=360.0)?
            .to_radians() as f32;
        let elevation = config.number("elevation", 63.0, 0.0..=90.0)?.to_radians() as f32;
        let lighting = SceneLighting {
            direction: Vec3::new(
                elevation.cos() * azimuth.cos(),
                elevation.cos() * azimuth.sin(),
                elevation.sin(),
            ),
            ambient: config.number("ambient", f64::from(defaults.ambient), 0.0..=1.0)? as f32,
            background: config.color("background", defaults.background)?,
        };
        ctx.scene.set_lighting(lighting);
        Ok(Box::new(Lights { config }))
    }
}

impl Plugin for Lights {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        "Lights".into()
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.set_lighting(SceneLighting::default());
    }
}
