//! A robot: a `position` model and everything mounted on it, at any depth (a ranger inside a
//! model inside the position is read with the two poses composed, and raised by the heights
//! of the models it stands on, as Stage stacks children on their parent's top).

use super::blinkenlight::{default_size, is_blinkenlight};
use super::blocks::{has_blocks, model_blocks};
use super::gripper::gripper;
use super::models::Model;
use super::properties::{
    color_of, err, fiducial_of, name_of, number, numbers, opt_number, origin_of, pose_from,
    pose_of, ranger_return_of, size_of, string,
};
use super::{
    BatterySpec, CameraSpec, Drive, FiducialSpec, MountedBody, Pose, RangerSpec, RobotSpec,
    SensorSpec, World,
};
use crate::worldfile::WorldFileError;

/// Models nested deeper than this under a robot are refused (no real robot is built so).
const MAX_DEPTH: usize = 32;

/// Where a model's parent sits on the robot.
#[derive(Debug, Clone, Copy)]
struct Mount {
    /// The parent's pose in the robot's frame.
    pose: Pose,
    /// Height of the parent's top above the floor.
    top: f64,
}

impl World {
    pub(super) fn robot(&mut self, model: &Model) -> Result<RobotSpec, WorldFileError> {
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
        let size = size_of(model, [0.44, 0.38, 0.22])?;
        let mut robot = RobotSpec {
            // Stage names a model given no name by its type and how many of that type came
            // before it: a client asks simulation:0 for "position:1".
            name: name_of(model, &format!("position:{}", self.robots.len())),
            pose: pose_of(model)?,
            size,
            color: color_of(model)?,
            drive,
            fiducial_id: fiducial_of(model)?,
            ranger_return: ranger_return_of(model)?,
            origin: origin_of(model)?,
            shape: model_blocks(model, [size[0], size[1]])?,
            shape_slices: super::shape_slices::shape_slices(model, size)?,
            rangers: Vec::new(),
            fiducials: Vec::new(),
            cameras: Vec::new(),
            blobfinders: Vec::new(),
            grippers: Vec::new(),
            controller: None,
            battery: BatterySpec::of(model)?,
            velocity_bounds: super::VelocityBounds::of(model)?,
            localization: super::LocalizationSpec::of(model)?,
            mounted_bodies: Vec::new(),
        };
        if let Some(p) = model.get("gripper_return") {
            self.ignore(
                "gripper_return on a robot (only boxes can be gripped)",
                &p.pos,
            );
        }
        let on_base = Mount {
            pose: Pose::default(),
            top: size[2],
        };
        for child in &model.children {
            self.mounted(&mut robot, child, on_base, 1)?;
        }
        robot.controller = self.controller(model, &robot.rangers)?;
        Ok(robot)
    }

    /// Reads `child`, standing on `parent`, and what is mounted on it in turn.
    fn mounted(
        &mut self,
        robot: &mut RobotSpec,
        child: &Model,
        parent: Mount,
        depth: usize,
    ) -> Result<(), WorldFileError> {
        if depth > MAX_DEPTH {
            return Err(err(
                &child.pos,
                format!(
                    "models nested more than {MAX_DEPTH} deep on robot {}",
                    robot.name
                ),
            ));
        }
        self.note_unread(child);
        let pose = compose(parent.pose, pose_of(child)?);
        let z = child
            .get("pose")
            .and_then(|p| p.value.numbers())
            .filter(|n| n.len() >= 4)
            .map_or(0.0, |n| n[2]);
        let mut size_z = 0.0;
        // A plain model is solid (its blocks, else its box), as are a blinkenlight (Stage's
        // 2 cm box) and a ranger given blocks.
        let solid = child.kind == "model"
            || is_blinkenlight(child)
            || (child.kind == "ranger" && has_blocks(child));
        if solid {
            let size = size_of(child, default_size(child))?;
            robot.mounted_bodies.push(MountedBody {
                pose: compose(pose, origin_of(child)?),
                size,
                bottom: parent.top + z,
                shape: model_blocks(child, [size[0], size[1]])?,
                ranger_return: ranger_return_of(child)?,
            });
        }
        match child.kind.as_str() {
            "ranger" => match ranger(child, pose, parent.top + z)? {
                Some(r) => robot.rangers.push(r),
                None => self.ignore("a ranger without sensor()", &child.pos),
            },
            "fiducial" => robot.fiducials.push(FiducialSpec {
                pose,
                min_range: opt_number(child, "range_min")?.unwrap_or(0.0),
                max_range: opt_number(child, "range_max")?.unwrap_or(8.0),
                max_range_id: opt_number(child, "range_max_id")?.unwrap_or(5.0),
                fov: opt_number(child, "fov")?.unwrap_or(180.0).to_radians(),
            }),
            "camera" => robot.cameras.push(camera(child, pose, z + parent.top)?),
            "blobfinder" => {
                let finder = self.blobfinder(child, pose)?;
                robot.blobfinders.push(finder);
            }
            "gripper" => robot.grippers.push(gripper(child, pose)?),
            "model" => size_z = size_of(child, [0.0, 0.0, 0.0])?[2],
            // Its light blinks in Stage's window only; its body is mounted above.
            "blinkenlight" => {
                self.ignore("a blinkenlight's light (its body is solid)", &child.pos);
                size_z = size_of(child, default_size(child))?[2];
            }
            other => {
                self.ignore(&format!("a {other} on a robot"), &child.pos);
                return Ok(());
            }
        }
        let here = Mount {
            pose,
            top: parent.top + z + size_z,
        };
        for grandchild in &child.children {
            self.mounted(robot, grandchild, here, depth + 1)?;
        }
        Ok(())
    }
}

/// `local` (in a frame placed at `frame`) in the frame `frame` is given in.
fn compose(frame: Pose, local: Pose) -> Pose {
    let (s, c) = frame.a.sin_cos();
    Pose {
        x: frame.x + c * local.x - s * local.y,
        y: frame.y + s * local.x + c * local.y,
        a: frame.a + local.a,
    }
}

/// A ranger's `sensor()`s, or `None` when it has none.
/// Stage's sensor size when a `sensor()` gives none: a small transducer, 2 cm each way.
const SENSOR_SIZE: f64 = 0.02;

/// A ranger at `pose` on the robot, `height` above the floor.
fn ranger(model: &Model, pose: Pose, height: f64) -> Result<Option<RangerSpec>, WorldFileError> {
    let mut sensors = Vec::new();
    for part in model.parts.iter().filter(|p| p.kind == "sensor") {
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
        let z_of = |name: &str, at: usize| -> Result<Option<f64>, WorldFileError> {
            let Some(p) = part.get(name) else {
                return Ok(None);
            };
            let n = numbers(Some(p), 3, &p.pos)?;
            Ok((n.len() > at && (name != "pose" || n.len() >= 4)).then(|| n[at]))
        };
        let sensor_z = z_of("pose", 2)?.unwrap_or(0.0);
        let sensor_height = z_of("size", 2)?.unwrap_or(SENSOR_SIZE);
        sensors.push(SensorSpec {
            z: height + sensor_z + sensor_height / 2.0,
            pose: sensor_pose,
            min_range: range[0],
            max_range: range[1],
            fov,
            samples,
            noise: super::RangerNoise::of(part)?,
        });
    }
    Ok((!sensors.is_empty()).then_some(RangerSpec { pose, sensors }))
}

fn camera(model: &Model, pose: Pose, height: f64) -> Result<CameraSpec, WorldFileError> {
    let (width_px, height_px) = camera_resolution(model)?;
    let fov = model
        .get("fov")
        .map(|p| numbers(Some(p), 2, &p.pos))
        .transpose()?
        .unwrap_or_else(|| vec![70.0, 40.0]);
    if let Some(p) = model.get("fov")
        && !fov[..2].iter().all(|f| *f > 0.0 && *f < 180.0)
    {
        return Err(err(
            &p.pos,
            "camera fov [h v] must be degrees between 0 and 180 (exclusive)",
        ));
    }
    let range = model
        .get("range")
        .map(|p| numbers(Some(p), 2, &p.pos))
        .transpose()?
        .unwrap_or_else(|| vec![0.2, 10.0]);
    Ok(CameraSpec {
        pose,
        height,
        width_px,
        height_px,
        fov_h: fov[0].to_radians(),
        fov_v: fov[1].to_radians(),
        max_range: range[1],
    })
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
