//! OBJ skins: the shipped rover loads; robots wearing the same file share one mesh, read once,
//! with a user count; a missing or broken file leaves the box body and says why; a laser
//! wears its skin at the size its geometry reports.

mod support;

use std::path::{Path, PathBuf};

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::plugin::Plugin;
use framework::skin::{MeshManager, Skin, SkinError};
use glam::Vec3;
use player_proto::interfaces::common::{BBox3d, Pose3d};
use player_proto::interfaces::laser::{Laser, LaserGeometry};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn rover_obj() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/skins/rover.obj")
}

/// A folder of this test's own, so that the shared manager's counts are the test's alone.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pv3d-skin-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn config(library: &str, interface: &str, dir: &Path, skin: &str) -> PluginConfig {
    PluginConfig {
        library: library.into(),
        id: "r".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: format!("{interface}:0").parse().unwrap(),
            driver: "stage".into(),
        }),
        params: vec![Param {
            origin: "robots.xml:7:9".into(),
            ..Param::new("skinFile", skin)
        }],
        origin: "robots.xml:5:3".into(),
        base_dir: dir.to_path_buf(),
    }
}

/// Vertices of the lit mesh `plugin` draws (its skin, or the box it falls back to).
fn mesh_vertices(w: &Harness, plugin: &dyn Plugin) -> usize {
    w.scene
        .get(plugin.node().unwrap())
        .unwrap()
        .geometry
        .mesh
        .len()
}

#[test]
fn the_shipped_rover_is_a_small_model_standing_on_the_ground() {
    let mesh = MeshManager::shared().acquire(&rover_obj()).unwrap();
    // 3 boxes of 12 triangles, 4 hexagonal wheels of 20.
    assert_eq!(mesh.triangles.len(), 3 * 12 + 4 * 20);
    assert_eq!(mesh.min.z, 0.0, "wheels on the ground");
    assert!(mesh.max.x > -mesh.min.x, "the nose is at +x");
}

#[test]
fn robots_wearing_one_file_share_one_mesh_read_once() {
    let dir = scratch("shared");
    std::fs::copy(rover_obj(), dir.join("rover.obj")).unwrap();
    let file = dir.join("rover.obj");
    let manager = MeshManager::shared();
    let mut w = harness();
    let make = |w: &mut Harness| {
        w.make(config(
            "libpv3d_position2d",
            "position2d",
            &dir,
            "rover.obj",
        ))
        .unwrap()
    };
    let mut robots: Vec<Box<dyn Plugin>> = (0..3).map(|_| make(&mut w)).collect();
    assert_eq!(manager.reads(&file), 1, "one file, read once");
    assert_eq!(manager.users(&file), 3);
    for robot in &robots {
        assert_eq!(
            mesh_vertices(&w, robot.as_ref()),
            116 * 3,
            "the skin, not the box"
        );
    }
    let mut gone = robots.pop().unwrap();
    gone.clean(&mut w.ctx());
    drop(gone);
    assert_eq!(manager.users(&file), 2);
    robots.clear();
    assert_eq!(manager.users(&file), 0, "freed with its last user");
    // Worn again: read again, since nothing kept it.
    let _again = make(&mut w);
    assert_eq!(manager.reads(&file), 2);
    assert_eq!(manager.users(&file), 1);
}

#[test]
fn a_missing_or_broken_skin_leaves_the_box_and_says_where() {
    let dir = scratch("broken");
    std::fs::write(
        dir.join("past_the_end.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
    )
    .unwrap();
    std::fs::write(dir.join("no_faces.obj"), "# nothing\nv 0 0 0\n").unwrap();
    std::fs::write(
        dir.join("nan.obj"),
        "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let mut w = harness();
    for file in ["missing.obj", "past_the_end.obj", "no_faces.obj", "nan.obj"] {
        let c = config("libpv3d_position2d", "position2d", &dir, file);
        let skin = Skin::from_config(&c);
        assert!(skin.mesh.is_none(), "{file}");
        let error = skin.error.unwrap();
        assert!(
            error.starts_with("robots.xml:7:9: <skinFile> of libpv3d_position2d: skin ")
                && error.contains(file)
                && error.ends_with("; drawing the box body"),
            "{error}"
        );
        let robot = w.make(c).unwrap();
        assert_eq!(
            mesh_vertices(&w, robot.as_ref()),
            36,
            "{file}: the box body"
        );
    }
    let direct = MeshManager::shared().acquire(&dir.join("past_the_end.obj"));
    assert!(
        matches!(direct, Err(SkinError::Malformed { .. })),
        "{direct:?}"
    );
}

#[test]
fn a_laser_wears_its_skin_at_the_size_its_geometry_reports() {
    let dir = scratch("laser");
    std::fs::copy(rover_obj(), dir.join("scanner.obj")).unwrap();
    let mut w = harness();
    let geometry = LaserGeometry {
        pose: Pose3d {
            px: 0.1,
            pz: 0.2,
            ..Pose3d::default()
        },
        size: BBox3d {
            sw: 0.1,
            sl: 0.12,
            sh: 0.08,
        },
    };
    let addr: DevAddr = "laser:0".parse().unwrap();
    w.device.reply_to(
        Laser::REQ_GET_GEOM.kind(),
        Ok(Message::typed(
            addr,
            MsgType::Ack,
            Laser::Geometry(geometry),
        )),
    );
    let mut laser = w
        .make(config("libpv3d_laser", "laser", &dir, "scanner.obj"))
        .unwrap();
    laser.run(&mut w.ctx());
    let (skin, body) = w
        .scene
        .iter()
        .find(|(_, o)| o.name == "r skin")
        .expect("a skin node");
    assert_eq!(body.parent, laser.node());
    let to_world = w.scene.world_transform(skin);
    let points: Vec<Vec3> = body
        .geometry
        .mesh
        .iter()
        .map(|v| to_world.transform_point3(v.pos))
        .collect();
    let lo = points.iter().fold(Vec3::MAX, |m, p| m.min(*p));
    let hi = points.iter().fold(Vec3::MIN, |m, p| m.max(*p));
    assert!(
        (hi - lo - Vec3::new(0.12, 0.1, 0.08)).length() < 1e-5,
        "{lo} {hi}"
    );
    assert!(
        ((lo + hi) / 2.0 - Vec3::new(0.1, 0.0, 0.2)).length() < 1e-5,
        "at the pose"
    );
}
