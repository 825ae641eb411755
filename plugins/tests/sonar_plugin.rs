//! The sonar plugin fed known data draws one cone per transducer at the poses the sonar's
//! geometry reports, as long as each reading, below its robot (no GL involved).

use std::sync::Arc;
use std::time::Instant;

use glam::Vec3;
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::sonar::{Sonar, SonarData, SonarGeometry};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use pv3d_plugins::config::{DeviceRef, Param};
use pv3d_plugins::device::{RecordingDevice, RequestFailure};
use pv3d_plugins::plugin::{AnchorKey, Anchors, Plugin, PluginContext};
use pv3d_plugins::scene::{Object3D, Scene};
use pv3d_plugins::sonar::cones::ARC_SEGMENTS;
use pv3d_plugins::{PluginConfig, standard_plugins};

fn addr() -> DevAddr {
    "sonar:0".parse().unwrap()
}

fn sonar_config(extra: Vec<Param>) -> PluginConfig {
    let mut parent = Param::new("parentNode", "");
    parent.attributes = vec![
        ("interface".into(), "position2d".into()),
        ("index".into(), "0".into()),
    ];
    let mut params = vec![parent];
    params.extend(extra);
    PluginConfig {
        library: "libpv3d_sonar".into(),
        id: "sonar".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr(),
            driver: "p2os".into(),
        }),
        params,
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

/// A scene with a robot at x = 5 published as position2d:0 of localhost:6665.
fn scene_with_robot() -> (Scene, Anchors, pv3d_plugins::scene::NodeId) {
    let mut scene = Scene::new();
    let mut anchors = Anchors::default();
    let mut robot = Object3D::new("robot");
    robot.transform = glam::Affine3A::from_translation(Vec3::new(5.0, 0.0, 0.0));
    let robot = scene.add(robot);
    anchors.publish(
        AnchorKey {
            host: "localhost".into(),
            port: 6665,
            interface: "position2d".into(),
            index: 0,
        },
        robot,
    );
    (scene, anchors, robot)
}

fn make(config: PluginConfig, ctx: &mut PluginContext<'_>) -> Box<dyn Plugin> {
    match standard_plugins().constructor("libpv3d_sonar").unwrap()(config, ctx) {
        Ok(p) => p,
        Err(e) => panic!("{e}"),
    }
}

#[test]
fn one_cone_per_transducer_at_its_pose_as_long_as_its_reading() {
    let device = RecordingDevice::default();
    let poses = vec![
        Pose3d {
            px: 0.2,
            ..Pose3d::default()
        },
        Pose3d {
            py: 0.2,
            pyaw: std::f64::consts::FRAC_PI_2,
            ..Pose3d::default()
        },
    ];
    device.replies.lock().unwrap().push((
        1,
        Ok(Arc::new(Message::typed(
            addr(),
            MsgType::Ack,
            Sonar::Geometry(SonarGeometry { poses }),
        ))),
    ));
    let (mut scene, mut anchors, robot) = scene_with_robot();
    let mut ctx = PluginContext {
        scene: &mut scene,
        device: Some(&device),
        anchors: &mut anchors,
        now: Instant::now(),
    };
    let mut plugin = make(sonar_config(vec![]), &mut ctx);
    assert_eq!(
        device.requests.lock().unwrap()[0].0,
        1,
        "geometry asked for"
    );

    device.push(Message::typed(
        addr(),
        MsgType::Data,
        Sonar::Ranges(SonarData {
            ranges: vec![1.0, 2.0],
        }),
    ));
    assert!(plugin.update(&mut ctx));
    assert!(!plugin.update(&mut ctx), "nothing new, nothing redrawn");

    let node = plugin.node().unwrap();
    let object = scene.get(node).unwrap();
    assert_eq!(object.parent, Some(robot));
    let g = &object.geometry;
    assert_eq!(g.triangles.len(), 2 * ARC_SEGMENTS * 3, "two filled cones");
    assert_eq!(g.lines.len(), 2 * (ARC_SEGMENTS + 2) * 2, "two outlines");
    // The second cone's axis ends 2 m along +y from (0, 0.2), on a robot at x = 5.
    let second_tip = g.triangles[ARC_SEGMENTS * 3 + (ARC_SEGMENTS / 2) * 3 + 1].pos;
    let world = scene.world_transform(node).transform_point3(second_tip);
    assert!(
        (world - Vec3::new(5.0, 2.2, 0.0)).length() < 1e-5,
        "{world}"
    );
    // Every vertex of the first cone is within 1 m of its transducer.
    for v in &g.triangles[..ARC_SEGMENTS * 3] {
        assert!((v.pos - Vec3::new(0.2, 0.0, 0.0)).length() <= 1.0 + 1e-5);
    }
}

#[test]
fn without_geometry_the_transducers_are_drawn_on_a_ring_and_state_is_saved() {
    let device = RecordingDevice::default();
    device
        .replies
        .lock()
        .unwrap()
        .push((1, Err(RequestFailure::Nack)));
    let (mut scene, mut anchors, _) = scene_with_robot();
    let mut ctx = PluginContext {
        scene: &mut scene,
        device: Some(&device),
        anchors: &mut anchors,
        now: Instant::now(),
    };
    let config = sonar_config(vec![Param::new("drawConeOutline", "0")]);
    let mut plugin = make(config, &mut ctx);
    device.push(Message::typed(
        addr(),
        MsgType::Data,
        Sonar::Ranges(SonarData {
            ranges: vec![1.0; 4],
        }),
    ));
    assert!(plugin.update(&mut ctx));
    let object = scene.get(plugin.node().unwrap()).unwrap();
    assert_eq!(object.geometry.triangles.len(), 4 * ARC_SEGMENTS * 3);
    assert!(object.geometry.lines.is_empty(), "outlines switched off");
    // Four cones, facing +x, +y, -x, -y: their far points spread all round.
    let far: Vec<Vec3> = object
        .geometry
        .triangles
        .chunks(ARC_SEGMENTS * 3)
        .map(|c| c[(ARC_SEGMENTS / 2) * 3 + 1].pos)
        .collect();
    assert!(
        (far[0] - Vec3::new(1.2, 0.0, 0.0)).length() < 1e-4,
        "{far:?}"
    );
    assert!(
        (far[2] - Vec3::new(-1.2, 0.0, 0.0)).length() < 1e-4,
        "{far:?}"
    );

    let saved = plugin.save();
    assert_eq!(saved.param("drawConeOutline").unwrap().text, "0");
    assert_eq!(saved.param("drawCones").unwrap().text, "1");
    assert_eq!(saved.param("visible").unwrap().text, "1");
}

#[test]
fn bad_parameters_name_the_place() {
    let config = sonar_config(vec![Param {
        origin: "test.xml:4:5".into(),
        ..Param::new("alpha", "opaque")
    }]);
    let (mut scene, mut anchors, _) = scene_with_robot();
    let mut ctx = PluginContext {
        scene: &mut scene,
        device: None,
        anchors: &mut anchors,
        now: Instant::now(),
    };
    let err = match standard_plugins().constructor("libpv3d_sonar").unwrap()(config, &mut ctx) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted a bad alpha"),
    };
    assert!(
        err.starts_with("test.xml:4:5: <alpha> of libpv3d_sonar"),
        "{err}"
    );
}
