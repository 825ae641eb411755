//! What has no schema of its own as `foxglove.SceneUpdate` entities: a robot's body (a box of
//! its geometry's size, locked to its frame), the fiducials a finder sees (a small box each,
//! where it sees them) and a planner's path (a line through its waypoints, in the world).

use foxglove::messages::line_primitive::Type as LineType;
use foxglove::messages::{
    Color, CubePrimitive, LinePrimitive, Point3, SceneEntity, SceneUpdate, Timestamp, Vector3,
};
use player_proto::interfaces::common::{BBox3d, Pose2d, Pose3d};
use player_proto::interfaces::fiducial::FiducialItem;

use crate::frames::{WORLD, pose3d};

const BODY: Color = Color {
    r: 0.2,
    g: 0.5,
    b: 0.9,
    a: 0.8,
};
const FIDUCIAL: Color = Color {
    r: 1.0,
    g: 0.8,
    b: 0.1,
    a: 1.0,
};
const PATH: Color = Color {
    r: 0.1,
    g: 0.9,
    b: 0.3,
    a: 1.0,
};

fn entity(time: Timestamp, frame: &str, id: String) -> SceneEntity {
    SceneEntity {
        timestamp: Some(time),
        frame_id: frame.into(),
        id,
        frame_locked: true,
        ..SceneEntity::default()
    }
}

/// A robot's body: a box of its size at its geometry's offset, moving with its frame.
pub fn body(time: Timestamp, frame: &str, pose: &Pose3d, size: &BBox3d) -> SceneUpdate {
    let mut body = entity(time, frame, format!("{frame}/body"));
    body.cubes.push(CubePrimitive {
        pose: Some(pose3d(pose)),
        size: Some(Vector3 {
            x: size.sl,
            y: size.sw,
            z: size.sh.max(0.01),
        }),
        color: Some(BODY),
    });
    SceneUpdate {
        deletions: Vec::new(),
        entities: vec![body],
    }
}

/// The fiducials a finder sees now, as boxes in its frame (replacing what it saw before).
pub fn fiducials(time: Timestamp, frame: &str, items: &[FiducialItem]) -> SceneUpdate {
    let mut seen = entity(time, frame, format!("{frame}/fiducials"));
    seen.cubes = items
        .iter()
        .map(|item| CubePrimitive {
            pose: Some(pose3d(&item.pose)),
            size: Some(Vector3 {
                x: 0.1,
                y: 0.1,
                z: 0.1,
            }),
            color: Some(FIDUCIAL),
        })
        .collect();
    SceneUpdate {
        deletions: Vec::new(),
        entities: vec![seen],
    }
}

/// A planner's path through its waypoints, in the world.
pub fn path(time: Timestamp, id: &str, waypoints: &[Pose2d]) -> SceneUpdate {
    let mut path = entity(time, WORLD, id.into());
    path.lines.push(LinePrimitive {
        r#type: LineType::LineStrip as i32,
        thickness: 0.05,
        points: waypoints
            .iter()
            .map(|w| Point3 {
                x: w.px,
                y: w.py,
                z: 0.02,
            })
            .collect(),
        color: Some(PATH),
        ..LinePrimitive::default()
    });
    SceneUpdate {
        deletions: Vec::new(),
        entities: vec![path],
    }
}
