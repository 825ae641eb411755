//! The models a plain model carries (Stage's fasr.world: a charging station's posts and its
//! yellow charging plate, fiducial 2), read as boxes of their own: Stage stacks a child on its
//! parent's top, at the child's pose in the parent's frame, and it stops robots and rays and
//! shows its fiducial as any model does. Before, they were dropped without a word.
//!
//! A child is taken as standing from the floor to its own top: what lies under it is, in the
//! worlds Stage ships, its parent (a post on a station's base). A sensor or robot on a plain
//! model is not simulated and is said so. A child keeps Stage's name, `parent.model:N`, but
//! moves only with the world: placing its parent through `simulation:0` leaves it where it was.

use super::models::Model;
use super::properties::{
    color_of, err, fiducial_of, name_of, opt_number, origin_of, pose_of, ranger_return_of, size_of,
};
use super::{BoxObstacle, Pose, World, blocks, shape_slices};
use crate::worldfile::WorldFileError;

/// Models nested deeper than this on a plain model are refused.
const MAX_DEPTH: usize = 32;

impl World {
    /// A plain model at `frame` (its parent's pose in the world, the world's own for a top-level
    /// model), standing on `floor` m, named `name`, and what it carries; `depth` it is nested.
    pub(super) fn box_and_children(
        &mut self,
        model: &Model,
        frame: Pose,
        floor: f64,
        name: String,
        depth: usize,
    ) -> Result<(), WorldFileError> {
        if depth > MAX_DEPTH {
            return Err(err(
                &model.pos,
                format!("models nested more than {MAX_DEPTH} deep on a model"),
            ));
        }
        let size = size_of(model, [1.0, 1.0, 1.0])?;
        let pose = compose(frame, pose_of(model)?);
        let bottom = floor + pose_z(model);
        let top = bottom + size[2];
        let standing = [size[0], size[1], top];
        self.obstacles.push(BoxObstacle {
            name: name.clone(),
            pose,
            size: standing,
            color: color_of(model)?,
            fiducial_id: fiducial_of(model)?,
            ranger_return: ranger_return_of(model)?,
            origin: origin_of(model)?,
            shape: blocks::model_blocks(model, [size[0], size[1]])?,
            shape_slices: shape_slices::shape_slices(model, standing)?,
            gripper_return: opt_number(model, "gripper_return")?.is_some_and(|v| v != 0.0),
            obstacle_return: opt_number(model, "obstacle_return")?.is_none_or(|v| v != 0.0),
        });
        let mut models = 0;
        for child in &model.children {
            self.note_unread(child);
            if child.kind != "model" || child.get("bitmap").is_some() {
                self.ignore(
                    &format!(
                        "a {} on a model (only robots carry devices)",
                        child.declared
                    ),
                    &child.pos,
                );
                continue;
            }
            let child_name = name_of(child, &format!("{name}.model:{models}"));
            models += 1;
            self.box_and_children(child, pose, top, child_name, depth + 1)?;
        }
        Ok(())
    }
}

/// The height a model's pose raises it by (`pose [x y z a]`'s z; none in `[x y a]`).
fn pose_z(model: &Model) -> f64 {
    model
        .get("pose")
        .and_then(|p| p.value.numbers())
        .filter(|n| n.len() >= 4)
        .map_or(0.0, |n| n[2])
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
