//! `libpv3d_people`: situational awareness from a laser — people found in each scan by their
//! legs ([`legs`]), followed from scan to scan ([`tracker`]), and put in the world as
//! objects tagged `person` (and `id:pN`, their identity), so that every component — a
//! reaction, a robot asked to "follow" a person, the world asked "is there any person" —
//! knows them by tag without knowing this plugin.
//!
//! Parameters (m unless said): `clusterGap` (0.1), `minLegWidth` (0.05), `maxLegWidth`
//! (0.25), `maxLegGap` (0.5: legs farther apart are two people's), `bodyClusters` (false: a
//! single cluster `minBodyWidth`..`maxBodyWidth`, 0.3..0.6, is a person too — off because a
//! robot is that wide), `matchDistance` (0.6: a detection this near a person is them again),
//! `keepScans` (5: scans a person may go unseen before they have left), `color`. Hang it
//! below its robot with `<parentNode interface="position2d"/>` so that people land in the
//! world frame.

pub mod legs;
pub mod tracker;

use std::collections::HashMap;

use glam::{Vec2, Vec3};
use player_proto::interfaces::laser::{Laser, LaserGeometry, LaserScan};

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::pose::transform_of;
use framework::scene::{Aabb, NodeId, Object3D, Rgba};
use legs::{LegParams, Scan};
use tracker::Tracker;

/// A person as drawn: a column this size, m.
const PERSON_SIZE: Vec3 = Vec3::new(0.4, 0.4, 1.7);

pub struct PeoplePlugin {
    config: PluginConfig,
    params: LegParams,
    color: Rgba,
    /// Stands for the laser: its transform is the laser's pose on the robot.
    sensor: NodeId,
    parent: ParentLink,
    geometry: Awaited<LaserGeometry>,
    taken: LastTaken,
    tracker: Tracker,
    /// Each tracked person's object, by track id.
    people: HashMap<u32, NodeId>,
}

impl PeoplePlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "Finds people in laser scans by their legs and puts them in the world, tagged person, for other components to query and react to.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let defaults = LegParams::default();
        let number = |name, default: f32, max: f64| -> Result<f32, ConfigValueError> {
            Ok(config.number(name, f64::from(default), 0.0..=max)? as f32)
        };
        let max_metres = 10.0;
        let body_width = if config.bool("bodyClusters", false)? {
            Some((
                number("minBodyWidth", 0.3, max_metres)?,
                number("maxBodyWidth", 0.6, max_metres)?,
            ))
        } else {
            None
        };
        let params = LegParams {
            cluster_gap: number("clusterGap", defaults.cluster_gap, max_metres)?,
            min_leg_width: number("minLegWidth", defaults.min_leg_width, max_metres)?,
            max_leg_width: number("maxLegWidth", defaults.max_leg_width, max_metres)?,
            max_leg_gap: number("maxLegGap", defaults.max_leg_gap, max_metres)?,
            body_width,
        };
        let tracker = Tracker::new(
            number("matchDistance", 0.6, max_metres)?,
            config.number("keepScans", 5.0, 0.0..=1000.0)? as u32,
        );
        let color = config.color("color", Rgba::rgb(230, 120, 40))?;
        let sensor = ctx
            .scene
            .add(Object3D::new(format!("people finder {}", config.id)));
        Ok(Box::new(PeoplePlugin {
            parent: ParentLink::from_config(&config),
            geometry: Awaited::fetch(ctx.device, Laser::REQ_GET_GEOM),
            config,
            params,
            color,
            sensor,
            taken: LastTaken::default(),
            tracker,
            people: HashMap::new(),
        }))
    }

    /// The people tracked now: identity and world position.
    pub fn tracked(&self) -> impl Iterator<Item = (u32, Vec2)> + '_ {
        self.tracker.tracks().iter().map(|t| (t.id, t.at))
    }

    fn person_object(&self, id: u32) -> Object3D {
        let mut person = Object3D::new(format!("person {id}"));
        person.tags = vec!["person".into(), format!("id:p{id}")];
        let centre = Vec3::Z * PERSON_SIZE.z / 2.0;
        person.pick_bounds = Some(Aabb::centred(centre, PERSON_SIZE));
        person.geometry.cuboid(centre, PERSON_SIZE, self.color);
        person.geometry.label(
            Vec3::Z * (PERSON_SIZE.z + 0.1),
            format!("person {id}"),
            self.color,
        );
        person
    }

    fn update_people(&mut self, scan: &LaserScan, ctx: &mut PluginContext<'_>) {
        let seen = legs::people(
            &Scan {
                ranges: &scan.ranges,
                first: scan.min_angle,
                step: scan.resolution,
                max_range: scan.max_range,
            },
            &self.params,
        );
        let to_world = ctx.scene.world_transform(self.sensor);
        let in_world: Vec<Vec2> = seen
            .iter()
            .map(|p| to_world.transform_point3(p.extend(0.0)).truncate())
            .collect();
        let changes = self.tracker.update(&in_world);
        for id in changes.left {
            if let Some(node) = self.people.remove(&id) {
                tracing::info!(plugin = %self.config.id, "person {id} left");
                ctx.scene.remove(node);
            }
        }
        for id in changes.appeared {
            tracing::info!(plugin = %self.config.id, "person {id} appeared");
            let node = ctx.scene.add(self.person_object(id));
            self.people.insert(id, node);
        }
        for track in self.tracker.tracks() {
            if let Some(object) = self
                .people
                .get(&track.id)
                .and_then(|n| ctx.scene.get_mut(*n))
            {
                object.transform = glam::Affine3A::from_translation(track.at.extend(0.0));
            }
        }
    }
}

impl Plugin for PeoplePlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        format!("People ({})", self.people.len())
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.sensor, ctx);
        if let Some(Ok(g)) = self.geometry.take()
            && let Some(sensor) = ctx.scene.get_mut(self.sensor)
        {
            sensor.transform = transform_of(&g.pose);
        }
        if let Some((scan, _)) = self.taken.newest_of::<LaserScan>(ctx.device) {
            self.update_people(&scan, ctx);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        let mut tracked: Vec<(u32, Vec2)> = self.tracked().collect();
        tracked.sort_by_key(|(id, _)| *id);
        if tracked.is_empty() {
            ui.label("nobody in sight");
        }
        for (id, at) in tracked {
            ui.label(format!("person {id} at ({:.2}, {:.2})", at.x, at.y));
        }
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        for (_, node) in self.people.drain() {
            ctx.scene.remove(node);
        }
        ctx.scene.remove(self.sensor);
    }
}
