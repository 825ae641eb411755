//! A simulated world as a Stage world file describes it: the floorplan (a bitmap or Stage
//! `block`s, drawn into one occupancy grid), robots (`position` models) with their rangers,
//! fiducial finders and cameras mounted at any depth, and obstacles (boxes, or the blocks drawn
//! in them). What the simulator does not model is noted once as "ignored: <what> at
//! file:line", for the program to summarise.

mod battery;
mod bitmap;
mod blinkenlight;
mod blobfinder;
mod blocks;
mod box_children;
mod cell_floor;
mod colors;
mod controller;
mod floorplan;
mod gripper;
mod ignored;
mod localization;
mod models;
mod mounted_body;
mod person;
mod properties;
mod ranger_noise;
mod raster;
mod robot;
mod shape_slices;
mod stage_bitmap;
mod unread;
mod velocity_bounds;
mod wall_rects;
mod wall_sums;

use std::path::Path;

pub use battery::BatterySpec;
pub use bitmap::{Face, OccupancyGrid};
pub use blobfinder::BlobfinderSpec;
pub use blocks::{Polygon, placed};
pub(crate) use cell_floor::floor_i64;
pub use controller::Controller;
pub use gripper::GripperSpec;
pub use ignored::ignored_summary;
pub use localization::{DEFAULT_ODOM_ERROR_SPAN, Localization, LocalizationSpec};
pub use models::{Model, Types, read_with_includes};
pub use mounted_body::MountedBody;
pub use person::{PersonSpec, STANCE_WIDTH, Walk};
pub use ranger_noise::RangerNoise;
pub use shape_slices::{ShapeSlice, slice_at};
pub use stage_bitmap::StageBitmap;
pub use velocity_bounds::VelocityBounds;
pub use wall_rects::WallRect;

use crate::worldfile::{Item, Pos, Property, WorldFileError};
use properties::{err, name_of, number, opt_number};

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
    /// Height of its beams above the floor, m: as in Stage, the ranger's height on the robot
    /// plus the sensor's own (its pose's z and half its size's). A beam meets only what
    /// stands at that height: it passes over a lower robot, box or wall.
    pub z: f64,
    /// Its `noise` (Stage's; none unless set).
    pub noise: RangerNoise,
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
    /// What rangers report hitting it (Stage's `ranger_return`); negative: they see through.
    pub ranger_return: f64,
    /// Where the body's centre lies from `pose`, in the robot's frame (Stage's `origin`:
    /// Stage's pioneer.inc puts a Pioneer's 4 cm behind the point it turns about).
    pub origin: Pose,
    /// The robot's `block`s, scaled to its size, in its own frame (empty when it has none).
    /// When there are some, rays and collisions meet these polygons (the box of `size`, their
    /// bounding box, is only the first, cheap test).
    pub shape: Vec<Polygon>,
    /// Its blocks by height, when they are not all as tall (rangers meet a band's blocks only).
    pub shape_slices: Vec<ShapeSlice>,
    pub rangers: Vec<RangerSpec>,
    pub fiducials: Vec<FiducialSpec>,
    pub cameras: Vec<CameraSpec>,
    pub blobfinders: Vec<BlobfinderSpec>,
    pub grippers: Vec<GripperSpec>,
    /// Stage's `ctrl`: what drives the robot besides its clients.
    pub controller: Option<Controller>,
    /// Its power pack, when the model gives it `joules` (or `kjoules`) as Stage reads them.
    pub battery: Option<BatterySpec>,
    /// What its commanded velocity is held within (Stage's `velocity_bounds`).
    pub velocity_bounds: VelocityBounds,
    /// What its position2d reports as its pose (Stage's `localization`, `odom_error`).
    pub localization: LocalizationSpec,
    /// The solid models mounted on it, which rangers meet at their heights.
    pub mounted_bodies: Vec<MountedBody>,
}

/// A box that stops robots and beams (landmarks, furniture).
#[derive(Debug, Clone, PartialEq)]
pub struct BoxObstacle {
    pub name: String,
    pub pose: Pose,
    pub size: [f64; 3],
    pub color: [u8; 3],
    pub fiducial_id: Option<i32>,
    /// What rangers report hitting it (Stage's `ranger_return`); negative: they see through.
    pub ranger_return: f64,
    /// Where the body's centre lies from `pose`, in the model's frame (Stage's `origin`).
    pub origin: Pose,
    /// The model's `block`s, scaled to its size, in its own frame (empty when it has none).
    /// When there are some, rays and collisions meet these polygons (the box of `size`, their
    /// bounding box, is only the first, cheap test).
    pub shape: Vec<Polygon>,
    /// Its blocks by height, when they are not all as tall (rangers meet a band's blocks only).
    pub shape_slices: Vec<ShapeSlice>,
    /// Stage's `gripper_return`: a gripper can pick it up.
    pub gripper_return: bool,
    /// Stage's `obstacle_return`: robots bump into it (unless set to 0: a zone marked on the
    /// floor, which robots drive over).
    pub obstacle_return: bool,
}

impl BoxObstacle {
    /// A plain box of `size` at `pose`: no blocks, no marker, centred on its pose, seen by
    /// rangers as a wall is, bumped into, not picked up.
    pub fn plain(name: String, pose: Pose, size: [f64; 3], color: [u8; 3]) -> BoxObstacle {
        BoxObstacle {
            name,
            pose,
            size,
            color,
            fiducial_id: None,
            ranger_return: 1.0,
            origin: Pose::default(),
            shape: Vec::new(),
            shape_slices: Vec::new(),
            gripper_return: false,
            obstacle_return: true,
        }
    }
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
    /// A bitmap floorplan, for viewers; `None` when the floorplan is drawn with blocks only.
    pub floorplan: Option<Floorplan>,
    /// An unrotated bitmap floorplan's own pixels where Stage places them (rangers' raster).
    pub floor_bitmap: Option<std::sync::Arc<StageBitmap>>,
    /// Floorplans drawn with `block`s and the walls of `boundary 1`, in world coordinates
    /// (they are also in `floor`).
    pub floor_blocks: Vec<Polygon>,
    /// Metres per cell of the grid block floorplans are drawn into (the world's `resolution`,
    /// 0.02 as in Stage unless set).
    pub resolution: f64,
    /// The world's `speedup`, if it sets one (0 or less: as fast as possible).
    pub speedup: Option<f64>,
    /// The floorplan's wall height (its size's z) and colour, for the camera.
    pub floor_height: f64,
    pub floor_color: [u8; 3],
    /// What rangers report hitting the floorplan's walls (its `ranger_return`).
    pub floor_ranger_return: f64,
    pub robots: Vec<RobotSpec>,
    pub obstacles: Vec<BoxObstacle>,
    /// Walking people (`person`); their legs are among `obstacles`.
    pub people: Vec<PersonSpec>,
    /// "ignored: <what> at file:line", once each; not logged while loading (the program says
    /// them once, with its .cfg's, in one line: [`ignored_summary`]).
    pub ignored: Vec<String>,
    /// The notes of `ignored`, to say each once without searching the list (a world of
    /// 100 000 models may give as many).
    ignored_seen: std::collections::HashSet<String>,
    /// Floorplan polygons read but not drawn yet (while loading: the grid they go into is
    /// known only once every floorplan and the world's resolution are).
    pending_floor: Vec<(Polygon, Pos)>,
}

/// Stage's default raytrace resolution: 50 cells per metre.
const DEFAULT_RESOLUTION: f64 = 0.02;

impl World {
    /// Loads a world file and its includes.
    pub fn load(path: &Path) -> Result<World, WorldFileError> {
        let items = read_with_includes(path)?;
        let mut types = Types::default();
        let mut world = World {
            interval: 0.1,
            resolution: DEFAULT_RESOLUTION,
            floor_height: 1.0,
            floor_color: [77, 77, 77],
            floor_ranger_return: 1.0,
            ..World::default()
        };
        let base = path.parent().unwrap_or(Path::new("."));
        let mut resolution_at = None;
        for item in items {
            match item {
                Item::Define { name, base, body } => types.add(name, base, body),
                Item::Property(p) => {
                    if p.name == "resolution" {
                        resolution_at = Some(p.pos.clone());
                    }
                    world.top_property(&p)?;
                }
                Item::Include { .. } => unreachable!("includes are expanded while reading"),
                Item::Block(block) if block.kind == "window" => {
                    world.ignore("window (the Stage GUI)", &block.pos);
                }
                Item::Block(block)
                    if block.kind == "floorplan"
                        || types.derives_from(&block.kind, "floorplan") =>
                {
                    world.floorplan(&types.instantiate_as_model(&block)?, base)?;
                }
                Item::Block(block) => {
                    let model = types.instantiate(&block)?;
                    world.top_model(&model, base)?;
                }
            }
        }
        let resolution_used = world.draw_floor_blocks()?;
        if !resolution_used && let Some(pos) = resolution_at {
            world.ignore(
                "world property resolution (only block floorplans are drawn into a grid of \
                 that resolution; a bitmap's pixels are its cells)",
                &pos,
            );
        }
        Ok(world)
    }

    fn top_property(&mut self, p: &Property) -> Result<(), WorldFileError> {
        match p.name.as_str() {
            "interval_sim" => self.interval = number(p)? / 1000.0,
            "resolution" => {
                let r = number(p)?;
                if !(r.is_finite() && r > 0.0) {
                    return Err(err(
                        &p.pos,
                        "resolution must be a positive number of metres",
                    ));
                }
                self.resolution = r;
            }
            // Stage's GUI starts paused and its 'p' key resumes; without a GUI (Player's
            // `usegui 0`) Stage runs, and so does player-sim, which has none.
            "paused" if number(p)? != 0.0 => {
                self.ignore(
                    "world property paused (player-sim has no GUI to resume it: it runs)",
                    &p.pos,
                );
            }
            // Simulated seconds per real second, 0 or less as fast as possible: what player-sim
            // runs at headless unless --speedup says otherwise (Stage honours it only in its
            // window).
            "speedup" => self.speedup = Some(number(p)?),
            // Pacing is the server's; these change nothing here.
            "paused" | "quit_time" | "threads" => {}
            other => self.ignore(&format!("world property {other}"), &p.pos),
        }
        Ok(())
    }

    fn top_model(&mut self, model: &Model, base: &Path) -> Result<(), WorldFileError> {
        self.note_unread(model);
        match model.kind.as_str() {
            "position" => {
                let robot = self.robot(model)?;
                self.robots.push(robot);
            }
            "person" => self.person(model)?,
            "model" if model.get("bitmap").is_some() => {
                self.floorplan(model, base)?;
            }
            "model" => {
                if let Some(p) = model.get("boundary")
                    && opt_number(model, "boundary")? != Some(0.0)
                {
                    self.ignore("boundary on a model that is not a floorplan", &p.pos);
                }
                let name = name_of(model, &format!("box{}", self.obstacles.len()));
                self.box_and_children(model, Pose::default(), 0.0, name, 1)?;
            }
            other => self.ignore(&format!("a {other} outside any robot"), &model.pos),
        }
        Ok(())
    }
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
        let mut model = self.instantiate(&as_model)?;
        model.declared = block.kind.clone();
        Ok(model)
    }
}
