//! The sonar plugin fed known data draws one cone per transducer at the poses the sonar's
//! geometry reports, as long as each reading, below its robot (no GL involved).

mod support;

use framework::PluginConfig;
use framework::config::Param;
use framework::device::{RecordingDevice, RequestError};
use framework::plugin::Plugin;
use glam::Vec3;
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::sonar::{Sonar, SonarData, SonarGeometry};
use player_proto::message::{Body, Message};
use player_proto::{DevAddr, MsgType};
use plugins::sonar::cones::ARC_SEGMENTS;
use plugins::standard_plugins;
use support::{Harness, harness};

fn addr() -> DevAddr {
    "sonar:0".parse().unwrap()
}

fn sonar_config(extra: Vec<Param>) -> PluginConfig {
    support::on_robot("libpv3d_sonar", "sonar", "sonar:0", extra)
}

fn make(h: &mut Harness, config: PluginConfig) -> Box<dyn Plugin> {
    h.make(config).unwrap_or_else(|e| panic!("{e}"))
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
    device.reply_to(
        Sonar::REQ_GET_GEOM.kind(),
        Ok(Message::typed(
            addr(),
            MsgType::Ack,
            Sonar::Geometry(SonarGeometry { poses }),
        )),
    );
    let mut h = Harness {
        device,
        ..harness()
    };
    let robot = h.robot_at(5.0);
    let mut plugin = make(&mut h, sonar_config(vec![]));
    let device = &h.device;
    assert_eq!(
        device.requests.lock().unwrap()[0].0,
        Sonar::REQ_GET_GEOM.kind(),
        "geometry asked for"
    );

    device.push(Message::typed(
        addr(),
        MsgType::Data,
        Sonar::Ranges(SonarData {
            ranges: vec![1.0, 2.0],
        }),
    ));
    assert!(h.run_changes_scene(plugin.as_mut()));
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "nothing new, nothing redrawn"
    );
    let scene = &h.scene;

    let node = plugin.node().unwrap();
    let object = scene.get(node).unwrap();
    assert_eq!(object.parent, Some(robot));
    let g = &object.geometry;
    let triangles: Vec<[Vec3; 3]> = g.fans.iter().flat_map(|f| f.fill_triangles()).collect();
    let segments = g.fans.iter().flat_map(|f| f.outline_segments()).count();
    assert_eq!(triangles.len(), 2 * ARC_SEGMENTS, "two filled cones");
    assert_eq!(segments, 2 * (ARC_SEGMENTS + 2), "two outlines");
    // The second cone's axis ends 2 m along +y from (0, 0.2), on a robot at x = 5.
    let second_tip = triangles[ARC_SEGMENTS + ARC_SEGMENTS / 2][1];
    let world = scene.world_transform(node).transform_point3(second_tip);
    assert!(
        (world - Vec3::new(5.0, 2.2, 0.0)).length() < 1e-5,
        "{world}"
    );
    // Every vertex of the first cone is within 1 m of its transducer.
    for p in triangles[..ARC_SEGMENTS].iter().flatten() {
        assert!((*p - Vec3::new(0.2, 0.0, 0.0)).length() <= 1.0 + 1e-5);
    }
}

#[test]
fn without_geometry_the_transducers_are_drawn_on_a_ring_and_state_is_saved() {
    let device = RecordingDevice::default();
    let geometry = Sonar::REQ_GET_GEOM.subtype();
    let refused = Message::new(addr(), MsgType::Nack, geometry, Body::Empty);
    device.reply_to(
        Sonar::REQ_GET_GEOM.kind(),
        Err(RequestError::Nack(Box::new(refused))),
    );
    let mut h = Harness {
        device,
        ..harness()
    };
    h.robot_at(5.0);
    let config = sonar_config(vec![Param::new("drawConeOutline", "0")]);
    let mut plugin = make(&mut h, config);
    h.device.push(Message::typed(
        addr(),
        MsgType::Data,
        Sonar::Ranges(SonarData {
            ranges: vec![1.0; 4],
        }),
    ));
    assert!(h.run_changes_scene(plugin.as_mut()));
    let object = h.scene.get(plugin.node().unwrap()).unwrap();
    let fans = &object.geometry.fans;
    assert_eq!(fans.len(), 4);
    assert!(
        fans.iter()
            .all(|f| f.fill_triangles().count() == ARC_SEGMENTS)
    );
    assert!(
        fans.iter().all(|f| f.outline.is_none()),
        "outlines switched off"
    );
    // Four cones, facing +x, +y, -x, -y: their far points spread all round.
    let far: Vec<Vec3> = fans.iter().map(|f| f.rim[ARC_SEGMENTS / 2]).collect();
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
    let mut h = harness();
    let create = standard_plugins().constructor("libpv3d_sonar").unwrap();
    let err = match create(config, &mut h.ctx_without_device()) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted a bad alpha"),
    };
    assert!(
        err.starts_with("test.xml:4:5: <alpha> of libpv3d_sonar"),
        "{err}"
    );
}
