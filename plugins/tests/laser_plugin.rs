//! The laser plugin fed known data fills the scene as expected (no GL involved).

mod support;

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::device::RecordingDevice;
use framework::scene::Scene;
use glam::Vec3;
use player_proto::interfaces::common::{BBox3d, Pose3d};
use player_proto::interfaces::laser::{Laser, LaserGeometry, LaserScan};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use plugins::standard_plugins;
use support::{Harness, harness};

fn laser_config() -> PluginConfig {
    let mut parent = Param::new("parentNode", "");
    parent.attributes = vec![
        ("interface".into(), "position2d".into()),
        ("index".into(), "0".into()),
    ];
    PluginConfig {
        library: "libpv3d_laser".into(),
        id: "laser".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: "laser:0".parse().unwrap(),
            driver: "sicklms200".into(),
        }),
        params: vec![parent, Param::new("fillLaserCspace", "1")],
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

#[test]
fn scans_become_points_below_the_robot_at_the_geometry_pose() {
    let device = RecordingDevice::default();
    let geometry = LaserGeometry {
        pose: Pose3d {
            px: 0.2,
            pz: 0.3,
            ..Pose3d::default()
        },
        size: BBox3d::default(),
    };
    let addr: DevAddr = "laser:0".parse().unwrap();
    device.reply_to(
        Laser::REQ_GET_GEOM.kind(),
        Ok(Message::typed(
            addr,
            MsgType::Ack,
            Laser::Geometry(geometry),
        )),
    );

    let mut h = Harness {
        device,
        ..harness()
    };
    let robot = h.robot_at(5.0);
    let mut plugin = h.make(laser_config()).unwrap();
    assert_eq!(
        h.device.requests.lock().unwrap().len(),
        1,
        "geometry was asked for"
    );

    let scan = LaserScan {
        min_angle: 0.0,
        resolution: std::f32::consts::FRAC_PI_2,
        max_range: 8.0,
        ranges: vec![2.0, 1.0],
        ..LaserScan::default()
    };
    h.device
        .push(Message::typed(addr, MsgType::Data, Laser::Scan(scan)));
    assert!(h.run_changes_scene(plugin.as_mut()));
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "nothing new, nothing redrawn"
    );

    let node = plugin.node().unwrap();
    let scene = &h.scene;
    let object = scene.get(node).unwrap();
    assert_eq!(object.parent, Some(robot));
    assert_eq!(object.geometry.points.len(), 2);
    let fan = &object.geometry.fans[0];
    assert_eq!(fan.fill_triangles().count(), 1, "filled free space");
    // The first return is 2 m straight ahead of a laser 0.2 m ahead of a robot at x = 5.
    let world = scene
        .world_transform(node)
        .transform_point3(object.geometry.points[0].pos);
    assert!(
        (world - Vec3::new(7.2, 0.0, 0.3)).length() < 1e-5,
        "{world}"
    );

    let saved = plugin.save();
    assert_eq!(saved.param("fillLaserCspace").unwrap().text, "1");
    assert_eq!(saved.param("drawLaserCspace").unwrap().text, "0");
}

#[test]
fn bad_parameters_name_the_place() {
    let mut config = laser_config();
    config.params.push(Param {
        origin: "test.xml:7:3".into(),
        ..Param::new("drawPoints", "sometimes")
    });
    let mut h = harness();
    let create = standard_plugins().constructor("libpv3d_laser").unwrap();
    let err = match create(config, &mut h.ctx_without_device()) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted a bad flag"),
    };
    assert!(
        err.starts_with("test.xml:7:3: <drawPoints> of libpv3d_laser"),
        "{err}"
    );
}

#[test]
fn scans_with_a_pose_or_a_bearing_per_reading_are_drawn_newest_first() {
    use player_proto::interfaces::common::Pose2d;
    use player_proto::interfaces::laser::{LaserScanAngle, LaserScanPose};

    let addr: DevAddr = "laser:0".parse().unwrap();
    let mut h = harness();
    let mut plugin = h.make(laser_config()).unwrap();
    let node = plugin.node().unwrap();

    // A scan with the pose it was taken at: the scan is drawn as a plain one would be.
    h.device.push(Message::typed(
        addr,
        MsgType::Data,
        Laser::ScanPose(LaserScanPose {
            scan: LaserScan {
                min_angle: 0.0,
                resolution: 0.5,
                max_range: 8.0,
                ranges: vec![1.0, 1.0],
                ..LaserScan::default()
            },
            pose: Pose2d {
                px: 3.0,
                ..Pose2d::default()
            },
        }),
    ));
    assert!(h.run_changes_scene(plugin.as_mut()));
    let points = points_of(&h.scene, node);
    assert_eq!(points.len(), 2);
    assert!((points[0] - Vec3::X).length() < 1e-5, "{points:?}");

    // Then a scan with its own bearings (one reading lacks one and is dropped).
    h.device.push(Message::typed(
        addr,
        MsgType::Data,
        Laser::ScanAngle(LaserScanAngle {
            max_range: 8.0,
            ranges: vec![2.0, 2.0, 2.0],
            angles: vec![std::f32::consts::FRAC_PI_2, -std::f32::consts::FRAC_PI_2],
            ..LaserScanAngle::default()
        }),
    ));
    assert!(h.run_changes_scene(plugin.as_mut()));
    let points = points_of(&h.scene, node);
    assert_eq!(points.len(), 2, "{points:?}");
    assert!(
        (points[0] - Vec3::new(0.0, 2.0, 0.0)).length() < 1e-5,
        "{points:?}"
    );
    assert!(
        (points[1] - Vec3::new(0.0, -2.0, 0.0)).length() < 1e-5,
        "{points:?}"
    );
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "nothing new: nothing redrawn"
    );
}

/// Where the points of `node` are, in its own frame.
fn points_of(scene: &Scene, node: framework::scene::NodeId) -> Vec<Vec3> {
    let g = &scene.get(node).unwrap().geometry;
    g.points.iter().map(|p| p.pos).collect()
}
