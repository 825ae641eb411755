//! `libpv3d_zones`: named polygonal zones on the ground — a charging dock, a danger area, the
//! teacher's corner — and which robot is in which. A composition enables them with
//! `<addParser element="zone"/>` and writes each as
//! `<zone name="dock" color="#40c0ff">x y  x y  x y …</zone>` (metres, world frame, three
//! corners or more, convex or not). Each zone is a tagged object (`zone`, `zone:dock`); when a
//! robot enters or leaves one, the plugin says so in its panel and in the log — the paper's
//! awareness events. It answers the queries "which zone" and "where is" (see `answers.rs`).

mod answers;

use std::collections::{HashSet, VecDeque};

use glam::{Vec2, Vec3};

use framework::config::{ConfigValueError, Param, PluginConfig};
use framework::plugin::{Plugin, PluginContext};
use framework::query::{Query, Reply};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D, Rgba, Scene};

use framework::scene::polygon::{contains, parse_corners, triangulate};

/// Zones lie this far above the ground, under everything else.
const HEIGHT: f32 = 0.005;
/// Awareness events kept for the panel.
const EVENTS_KEPT: usize = 12;

struct Zone {
    name: String,
    corners: Vec<Vec2>,
}

impl Zone {
    /// Where the zone's name is drawn, and where a robot sent "to the zone" goes: the mean of
    /// its corners (inside for the convex zones rooms and docks usually are).
    fn centre(&self) -> Vec2 {
        self.corners.iter().copied().sum::<Vec2>() / self.corners.len() as f32
    }
}

pub struct ZonesPlugin {
    config: PluginConfig,
    zones: Vec<Zone>,
    nodes: Vec<NodeId>,
    /// (zone index, robot name) pairs: who is where, as of the last update.
    inside: HashSet<(usize, String)>,
    events: VecDeque<String>,
}

impl ZonesPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "Named zones drawn on the ground; reports the robots that enter and leave each.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        Ok(Box::new(ZonesPlugin::new(config, ctx)?))
    }

    /// Reads every `<zone>` and adds it to the scene.
    pub fn new(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<ZonesPlugin, ConfigValueError> {
        let default_color = config.color("color", Rgba::rgb(64, 192, 255))?;
        let mut zones = Vec::new();
        let mut nodes = Vec::new();
        for param in config.params.iter().filter(|p| p.name == "zone") {
            let zone = read_zone(&config, param)?;
            let color = match param.attr("color") {
                Some(text) => framework::config::parse_color(text.trim()).ok_or_else(|| {
                    error(
                        &config,
                        param,
                        format!("color {text:?} is not a colour such as #40c0ff"),
                    )
                })?,
                None => default_color,
            };
            nodes.push(ctx.scene.add(zone_object(&zone, color)));
            zones.push(zone);
        }
        Ok(ZonesPlugin {
            config,
            zones,
            nodes,
            inside: HashSet::new(),
            events: VecDeque::new(),
        })
    }

    /// Every robot's position on the ground, by name.
    fn robots(scene: &Scene) -> Vec<(String, Vec2)> {
        scene
            .iter()
            .filter(|(_, o)| o.has_tag("robot"))
            .map(|(id, o)| {
                (
                    o.name.clone(),
                    scene.world_transform(id).translation.truncate(),
                )
            })
            .collect()
    }
}

fn error(config: &PluginConfig, param: &Param, message: String) -> ConfigValueError {
    ConfigValueError {
        origin: param.origin.clone(),
        library: config.library.clone(),
        param: "zone".into(),
        message,
    }
}

fn read_zone(config: &PluginConfig, param: &Param) -> Result<Zone, ConfigValueError> {
    let name = param
        .attr("name")
        .map(str::trim)
        .filter(|n| !n.is_empty())
        .ok_or_else(|| {
            error(
                config,
                param,
                "needs a name attribute, e.g. <zone name=\"dock\">".into(),
            )
        })?;
    let corners = parse_corners(&param.text).map_err(|e| error(config, param, e.to_string()))?;
    Ok(Zone {
        name: name.to_string(),
        corners,
    })
}

fn zone_object(zone: &Zone, color: Rgba) -> Object3D {
    let mut object = Object3D::new(format!("zone {}", zone.name));
    object.tags = vec!["zone".into(), format!("zone:{}", zone.name)];
    let at = |p: Vec2| Vec3::new(p.x, p.y, HEIGHT);
    let fill = color.with_alpha(50);
    for [a, b, c] in triangulate(&zone.corners) {
        let (a, b, c) = (zone.corners[a], zone.corners[b], zone.corners[c]);
        object.geometry.triangle(at(a), at(b), at(c), fill);
    }
    let outline: Vec<Vec3> = zone.corners.iter().map(|&p| at(p)).collect();
    object.geometry.polygon_outline(&outline, color);
    let centre = zone.centre();
    object.geometry.label(at(centre), zone.name.clone(), color);
    object
}

impl Plugin for ZonesPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        format!("Zones ({})", self.zones.len())
    }

    /// Watches the robots; the zones themselves never change, so the scene does not either.
    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        let mut now_inside = HashSet::new();
        for (robot, position) in Self::robots(ctx.scene) {
            for (i, zone) in self.zones.iter().enumerate() {
                if contains(&zone.corners, position) {
                    now_inside.insert((i, robot.clone()));
                }
            }
        }
        let mut changes: Vec<String> = now_inside
            .difference(&self.inside)
            .map(|(i, robot)| format!("{robot} entered {}", self.zones[*i].name))
            .chain(
                self.inside
                    .difference(&now_inside)
                    .map(|(i, robot)| format!("{robot} left {}", self.zones[*i].name)),
            )
            .collect();
        changes.sort();
        for event in changes {
            tracing::info!("zone: {event}");
            if self.events.len() == EVENTS_KEPT {
                self.events.pop_front();
            }
            self.events.push_back(event);
        }
        self.inside = now_inside;
    }

    fn answer(&mut self, query: &Query, ctx: &mut PluginContext<'_>) -> Option<Reply> {
        self.answer_query(query, ctx)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        for node in self.nodes.drain(..) {
            ctx.scene.remove(node);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        for (i, zone) in self.zones.iter().enumerate() {
            let mut robots: Vec<&str> = self
                .inside
                .iter()
                .filter(|(z, _)| *z == i)
                .map(|(_, r)| r.as_str())
                .collect();
            robots.sort_unstable();
            let who = if robots.is_empty() {
                "empty".to_string()
            } else {
                robots.join(", ")
            };
            ui.label(format!("{}: {who}", zone.name));
        }
        if !self.events.is_empty() {
            ui.separator();
            for event in self.events.iter().rev() {
                ui.small(event);
            }
        }
    }
}

impl ZonesPlugin {
    /// Who is in zone `name` now, sorted (for tests and other components).
    pub fn robots_in(&self, name: &str) -> Vec<String> {
        let mut robots: Vec<String> = self
            .zones
            .iter()
            .enumerate()
            .filter(|(_, z)| z.name == name)
            .flat_map(|(i, _)| {
                self.inside
                    .iter()
                    .filter(move |(z, _)| *z == i)
                    .map(|(_, r)| r.clone())
            })
            .collect();
        robots.sort();
        robots
    }

    /// The awareness events so far, oldest first.
    pub fn events(&self) -> impl Iterator<Item = &str> {
        self.events.iter().map(String::as_str)
    }
}
