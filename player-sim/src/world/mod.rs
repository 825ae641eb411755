//! A simulated world as a Stage world file describes it: the floorplan bitmap, robots
//! (`position` models) with their rangers, fiducial finders and cameras, and box obstacles.
//! What the simulator does not model is reported once as "ignored: <what> at file:line".

mod bitmap;
mod colors;
mod models;
mod properties;

use std::path::Path;

pub use bitmap::{Face, OccupancyGrid};
pub use models::{Model, Types, read_with_includes};

use crate::worldfile::{Item, Pos, Property, WorldFileError};
use properties::{
    color_of, err, fiducial_of, name_of, number, numbers, opt_number, pose_from, pose_of, size_of,
    string,
};

/// Stage's drive models.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Drive {
    Diff,
    Omni,
}

/// A pose in the plane: metres and radians.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub a: f64,
}

/// One beam fan of a ranger: a laser is one sensor with many samples; a sonar ring is many
/// sensors with one sample each.
#[derive(Debug, Clone, PartialEq)]
pub struct SensorSpec {
    /// On the ranger.
    pub pose: Pose,
    pub min_range: f64,
    pub max_range: f64,
    /// Radians.
    pub fov: f64,
    pub samples: usize,
}

#[derive(Debug, Clone, PartialEq)]
pub struct RangerSpec {
    /// On the robot.
    pub pose: Pose,
    pub sensors: Vec<SensorSpec>,
}

impl RangerSpec {
    /// One sensor with many samples: served as a laser as well as a ranger.
    pub fn is_laser_like(&self) -> bool {
        self.sensors.len() == 1 && self.sensors[0].samples > 1
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct FiducialSpec {
    pub pose: Pose,
    pub min_range: f64,
    pub max_range: f64,
    /// Beyond this range markers are seen but reported with id 0.
    pub max_range_id: f64,
    pub fov: f64,
}

#[derive(Debug, Clone, PartialEq)]
pub struct CameraSpec {
    pub pose: Pose,
    pub height: f64,
    pub width_px: u32,
    pub height_px: u32,
    pub fov_h: f64,
    pub fov_v: f64,
    pub max_range: f64,
}

#[derive(Debug, Clone, PartialEq)]
pub struct RobotSpec {
    pub name: String,
    pub pose: Pose,
    /// Length (x), width (y), height, m.
    pub size: [f64; 3],
    pub color: [u8; 3],
    pub drive: Drive,
    pub fiducial_id: Option<i32>,
    pub rangers: Vec<RangerSpec>,
    pub fiducials: Vec<FiducialSpec>,
    pub cameras: Vec<CameraSpec>,
}

/// A box that stops robots and beams (landmarks, furniture).
#[derive(Debug, Clone, PartialEq)]
pub struct BoxObstacle {
    pub name: String,
    pub pose: Pose,
    pub size: [f64; 3],
    pub color: [u8; 3],
    pub fiducial_id: Option<i32>,
}

/// Where the floorplan bitmap lies, so a viewer can draw the same walls.
#[derive(Debug, Clone, PartialEq)]
pub struct Floorplan {
    /// The bitmap, resolved against the world file's folder.
    pub bitmap: std::path::PathBuf,
    /// Metres the bitmap covers, x then y.
    pub size: [f64; 2],
    /// The bitmap's centre in the world.
    pub centre: [f64; 2],
    pub height: f64,
    pub color: [u8; 3],
}

/// Everything the simulator needs from a world file.
#[derive(Debug, Clone, Default)]
pub struct World {
    /// Simulation step, seconds.
    pub interval: f64,
    pub floor: Option<OccupancyGrid>,
    pub floorplan: Option<Floorplan>,
    /// The floorplan's wall height (its size's z) and colour, for the camera.
    pub floor_height: f64,
    pub floor_color: [u8; 3],
    pub robots: Vec<RobotSpec>,
    pub obstacles: Vec<BoxObstacle>,
    /// "ignored: <what> at file:line", once each.
    pub ignored: Vec<String>,
}

/// Properties each kind of model reads; anything else is reported as ignored.
const READ: &[&str] = &[
    "name",
    "pose",
    "size",
    "color",
    "color_rgba",
    "drive",
    "bitmap",
    "fiducial_return",
    "obstacle_return",
    "range_min",
    "range_max",
    "range_max_id",
    "fov",
    "range",
    "resolution",
];

impl World {
    /// Loads a world file and its includes.
    pub fn load(path: &Path) -> Result<World, WorldFileError> {
        let items = read_with_includes(path)?;
        let mut types = Types::default();
        let mut world = World {
            interval: 0.1,
            floor_height: 1.0,
            floor_color: [77, 77, 77],
            ..World::default()
        };
        let base = path.parent().unwrap_or(Path::new("."));
        for item in items {
            match item {
                Item::Define { name, base, body } => types.add(name, base, body),
                Item::Property(p) => world.top_property(&p)?,
                Item::Include { .. } => unreachable!("includes are expanded while reading"),
                Item::Block(block) if block.kind == "window" => {
                    world.ignore("window (the Stage GUI)", &block.pos);
                }
                Item::Block(block) if block.kind == "floorplan" => {
                    world.floorplan(&types.instantiate_as_model(&block)?, base)?;
                }
                Item::Block(block) => {
                    let model = types.instantiate(&block)?;
                    world.top_model(&model, base)?;
                }
            }
        }
        Ok(world)
    }

    fn ignore(&mut self, what: &str, pos: &Pos) {
        let note = format!("ignored: {what} at {}:{}", pos.file, pos.line);
        if !self.ignored.contains(&note) {
            tracing::warn!("{note}");
            self.ignored.push(note);
        }
    }

    fn top_property(&mut self, p: &Property) -> Result<(), WorldFileError> {
        match p.name.as_str() {
            "interval_sim" => self.interval = number(p)? / 1000.0,
            // Real-time pacing is the server's choice (--speedup); these change nothing here.
            "resolution" | "speedup" | "quit_time" | "paused" | "threads" => {}
            other => self.ignore(&format!("world property {other}"), &p.pos),
        }
        Ok(())
    }

    fn note_unread(&mut self, model: &Model) {
        for p in &model.properties {
            if !READ.contains(&p.name.as_str()) {
                self.ignore(&format!("{} property {}", model.declared, p.name), &p.pos);
            }
        }
        // Sensors are read by the ranger; other nested blocks (Stage's block() shapes) are not
        // modelled: footprints are boxes of the model's size.
        for part in model
            .parts
            .iter()
            .filter(|p| !(model.kind == "ranger" && p.kind == "sensor"))
        {
            self.ignore(
                &format!(
                    "{}() in {} (footprints are boxes of its size)",
                    part.kind, model.declared
                ),
                &part.pos,
            );
        }
    }

    fn floorplan(&mut self, model: &Model, base: &Path) -> Result<(), WorldFileError> {
        self.note_unread(model);
        let Some(bitmap) = model.get("bitmap") else {
            self.ignore("floorplan without a bitmap", &model.pos);
            return Ok(());
        };
        let file = string(bitmap)?;
        let size = numbers(model.get("size"), 2, &model.pos)?;
        let pose = pose_of(model)?;
        let grid = OccupancyGrid::from_png(&base.join(file), size[0], size[1], pose.x, pose.y)
            .map_err(|e| err(&bitmap.pos, e))?;
        self.floor = Some(grid);
        self.floor_height = size.get(2).copied().unwrap_or(1.0);
        self.floor_color = color_of(model)?;
        self.floorplan = Some(Floorplan {
            bitmap: base.join(file),
            size: [size[0], size[1]],
            centre: [pose.x, pose.y],
            height: self.floor_height,
            color: self.floor_color,
        });
        Ok(())
    }

    fn top_model(&mut self, model: &Model, base: &Path) -> Result<(), WorldFileError> {
        self.note_unread(model);
        match model.kind.as_str() {
            "position" => {
                let robot = self.robot(model)?;
                self.robots.push(robot);
            }
            "model" if model.get("bitmap").is_some() => self.floorplan(model, base)?,
            "model" => {
                let obstacle = BoxObstacle {
                    name: name_of(model, &format!("box{}", self.obstacles.len())),
                    pose: pose_of(model)?,
                    size: size_of(model, [1.0, 1.0, 1.0])?,
                    color: color_of(model)?,
                    fiducial_id: fiducial_of(model)?,
                };
                self.obstacles.push(obstacle);
            }
            other => self.ignore(&format!("a {other} outside any robot"), &model.pos),
        }
        Ok(())
    }

    fn robot(&mut self, model: &Model) -> Result<RobotSpec, WorldFileError> {
        let drive = match model.get("drive").map(string).transpose()? {
            None | Some("diff") => Drive::Diff,
            Some("omni") => Drive::Omni,
            Some(other) => {
                self.ignore(
                    &format!("drive {other:?} (simulated as diff)"),
                    &model.get("drive").expect("present").pos,
                );
                Drive::Diff
            }
        };
        let mut robot = RobotSpec {
            name: name_of(model, &format!("robot{}", self.robots.len())),
            pose: pose_of(model)?,
            size: size_of(model, [0.44, 0.38, 0.22])?,
            color: color_of(model)?,
            drive,
            fiducial_id: fiducial_of(model)?,
            rangers: Vec::new(),
            fiducials: Vec::new(),
            cameras: Vec::new(),
        };
        for child in &model.children {
            self.note_unread(child);
            let pose = pose_of(child)?;
            match child.kind.as_str() {
                "ranger" => {
                    let mut sensors = Vec::new();
                    for part in child.parts.iter().filter(|p| p.kind == "sensor") {
                        let range = part
                            .get("range")
                            .map(|p| numbers(Some(p), 2, &p.pos))
                            .transpose()?
                            .unwrap_or_else(|| vec![0.0, 5.0]);
                        let fov = part
                            .get("fov")
                            .map(number)
                            .transpose()?
                            .unwrap_or(0.0)
                            .to_radians();
                        let samples = part
                            .get("samples")
                            .map(number)
                            .transpose()?
                            .unwrap_or(1.0)
                            .max(1.0) as usize;
                        let sensor_pose = match part.get("pose") {
                            Some(p) => pose_from(p)?,
                            None => Pose::default(),
                        };
                        sensors.push(SensorSpec {
                            pose: sensor_pose,
                            min_range: range[0],
                            max_range: range[1],
                            fov,
                            samples,
                        });
                    }
                    if sensors.is_empty() {
                        self.ignore("a ranger without sensor()", &child.pos);
                        continue;
                    }
                    robot.rangers.push(RangerSpec { pose, sensors });
                }
                "fiducial" => robot.fiducials.push(FiducialSpec {
                    pose,
                    min_range: opt_number(child, "range_min")?.unwrap_or(0.0),
                    max_range: opt_number(child, "range_max")?.unwrap_or(8.0),
                    max_range_id: opt_number(child, "range_max_id")?.unwrap_or(5.0),
                    fov: opt_number(child, "fov")?.unwrap_or(180.0).to_radians(),
                }),
                "camera" => {
                    let (width_px, height_px) = camera_resolution(child)?;
                    let fov = child
                        .get("fov")
                        .map(|p| numbers(Some(p), 2, &p.pos))
                        .transpose()?
                        .unwrap_or_else(|| vec![70.0, 40.0]);
                    if let Some(p) = child.get("fov")
                        && !fov[..2].iter().all(|f| *f > 0.0 && *f < 180.0)
                    {
                        return Err(err(
                            &p.pos,
                            "camera fov [h v] must be degrees between 0 and 180 (exclusive)",
                        ));
                    }
                    let range = child
                        .get("range")
                        .map(|p| numbers(Some(p), 2, &p.pos))
                        .transpose()?
                        .unwrap_or_else(|| vec![0.2, 10.0]);
                    let z = child
                        .get("pose")
                        .and_then(|p| p.value.numbers())
                        .and_then(|n| n.get(2).copied())
                        .unwrap_or(0.0);
                    robot.cameras.push(CameraSpec {
                        pose,
                        height: z + robot.size[2],
                        width_px,
                        height_px,
                        fov_h: fov[0].to_radians(),
                        fov_v: fov[1].to_radians(),
                        max_range: range[1],
                    });
                }
                other => self.ignore(&format!("a {other} on robot {}", robot.name), &child.pos),
            }
        }
        Ok(robot)
    }
}

/// The largest raw camera frame served: Player's messages (and our clients) stop at 8 MiB.
const MAX_FRAME_BYTES: f64 = (8 * 1024 * 1024 - 1024) as f64;

/// A camera's `resolution [w h]` (160 x 120 by default), refused when a raw RGB frame of that
/// size could not be sent.
fn camera_resolution(camera: &Model) -> Result<(u32, u32), WorldFileError> {
    let Some(p) = camera.get("resolution") else {
        return Ok((160, 120));
    };
    let n = numbers(Some(p), 2, &p.pos)?;
    let (w, h) = (n[0].round(), n[1].round());
    if !(w >= 1.0 && h >= 1.0 && w * h * 3.0 <= MAX_FRAME_BYTES) {
        return Err(err(
            &p.pos,
            format!(
                "camera resolution {} x {} is not a frame Player can send \
                 (at least 1 x 1, at most 8 MiB of RGB)",
                n[0], n[1]
            ),
        ));
    }
    Ok((w as u32, h as u32))
}

impl Types {
    /// A floorplan block is a plain model, whether or not `floorplan` was defined.
    fn instantiate_as_model(
        &self,
        block: &crate::worldfile::Block,
    ) -> Result<Model, WorldFileError> {
        if self.is_model_type("floorplan") {
            return self.instantiate(block);
        }
        let mut as_model = block.clone();
        as_model.kind = "model".into();
        self.instantiate(&as_model)
    }
}
