//! The ranger plugin fed known data draws a laser-like ranger as a scan and a sonar-like one
//! (Stage's sonar ring) as one cone per element, at the poses its geometry reports.

mod support;

use framework::PluginConfig;
use framework::config::Param;
use framework::device::RecordingDevice;
use framework::plugin::Plugin;
use framework::scene::{NodeId, Scene};
use glam::Vec3;
use player_proto::interfaces::common::{BBox3d, Pose3d};
use player_proto::interfaces::kind::MessageKind;
use player_proto::interfaces::ranger::{Ranger, RangerConfig, RangerGeometry, RangerRanges};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use plugins::sonar::cones::ARC_SEGMENTS;
use support::{Harness, harness};

fn addr() -> DevAddr {
    "ranger:1".parse().unwrap()
}

fn ranger_config(params: Vec<Param>) -> PluginConfig {
    support::on_robot("libpv3d_ranger", "ranger", "ranger:1", params)
}

fn answer(device: &RecordingDevice, geometry: RangerGeometry, config: RangerConfig) {
    let ack = |body: Ranger| Ok(Message::typed(addr(), MsgType::Ack, body));
    device.reply_to(Ranger::REQ_GET_GEOM.kind(), ack(Ranger::Geometry(geometry)));
    device.reply_to(Ranger::REQ_GET_CONFIG.kind(), ack(Ranger::Config(config)));
}

fn push_ranges(device: &RecordingDevice, ranges: Vec<f64>) {
    device.push(Message::typed(
        addr(),
        MsgType::Data,
        Ranger::Ranges(RangerRanges { ranges }),
    ));
}

/// Makes the plugin with `device` in a scene with a robot at (5, 0) facing +x, lets `feed`
/// give the device its data, and runs the plugin once; returns the scene, the robot's node,
/// the plugin's node and the plugin.
fn run(
    device: RecordingDevice,
    params: Vec<Param>,
    feed: impl FnOnce(&RecordingDevice),
) -> (Scene, NodeId, NodeId, Box<dyn Plugin>) {
    let mut h = Harness {
        device,
        ..harness()
    };
    let robot = h.robot_at(5.0);
    let mut plugin = h
        .make(ranger_config(params))
        .unwrap_or_else(|e| panic!("{e}"));
    let asked: Vec<MessageKind> = h
        .device
        .requests
        .lock()
        .unwrap()
        .iter()
        .map(|r| r.0)
        .collect();
    assert_eq!(
        asked,
        [Ranger::REQ_GET_GEOM.kind(), Ranger::REQ_GET_CONFIG.kind()],
        "geometry and config asked for"
    );
    feed(&h.device);
    assert!(h.run_changes_scene(plugin.as_mut()));
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "nothing new, nothing redrawn"
    );
    let node = plugin.node().unwrap();
    (h.scene, robot, node, plugin)
}

#[test]
fn a_laser_like_ranger_is_drawn_as_the_laser_plugin_draws_a_scan() {
    let device = RecordingDevice::default();
    answer(
        &device,
        RangerGeometry {
            pose: Pose3d {
                px: 0.05,
                pz: 0.2,
                ..Pose3d::default()
            },
            size: BBox3d::default(),
            element_poses: vec![Pose3d::default()],
            element_sizes: vec![BBox3d::default()],
        },
        RangerConfig {
            min_angle: -std::f64::consts::FRAC_PI_2,
            max_angle: std::f64::consts::FRAC_PI_2,
            angular_res: std::f64::consts::FRAC_PI_2,
            max_range: 8.0,
            ..RangerConfig::default()
        },
    );
    let params = vec![Param::new("fillLaserCspace", "1")];
    let (scene, robot, node, plugin) = run(device, params, |d| {
        push_ranges(d, vec![1.0, 2.0, 8.0]);
    });
    let object = scene.get(node).unwrap();
    assert_eq!(object.parent, Some(robot));
    assert_eq!(
        object.geometry.points.len(),
        2,
        "the 8 m reading is no return"
    );
    let fan = &object.geometry.fans[0];
    assert_eq!(fan.fill_triangles().count(), 2, "free space filled");
    let world = |p: Vec3| scene.world_transform(node).transform_point3(p);
    // First reading: 1 m to the right of a ranger 5 cm ahead of the robot, 20 cm up.
    let first = world(object.geometry.points[0].pos);
    assert!(
        (first - Vec3::new(5.05, -1.0, 0.2)).length() < 1e-5,
        "{first}"
    );
    let second = world(object.geometry.points[1].pos);
    assert!(
        (second - Vec3::new(7.05, 0.0, 0.2)).length() < 1e-5,
        "{second}"
    );
    assert_eq!(plugin.save().param("fillLaserCspace").unwrap().text, "1");
}

#[test]
fn a_sonar_ring_served_as_ranger_is_one_cone_per_element() {
    let device = RecordingDevice::default();
    // Stage's sonar ring of stage-worlds/robots.inc: 8 elements, 15° each.
    let element_poses: Vec<Pose3d> = (0..8)
        .map(|i| {
            let yaw = f64::from(i) * std::f64::consts::FRAC_PI_4;
            Pose3d {
                px: 0.2 * yaw.cos(),
                py: 0.2 * yaw.sin(),
                pyaw: yaw,
                ..Pose3d::default()
            }
        })
        .collect();
    let fov = 15f64.to_radians();
    answer(
        &device,
        RangerGeometry {
            pose: Pose3d::default(),
            size: BBox3d::default(),
            element_sizes: vec![BBox3d::default(); 8],
            element_poses,
        },
        RangerConfig {
            min_angle: -fov / 2.0,
            max_angle: fov / 2.0,
            angular_res: fov,
            max_range: 5.0,
            ..RangerConfig::default()
        },
    );
    let (scene, _, node, _) = run(device, vec![Param::new("coneAngle", "60")], |d| {
        push_ranges(d, vec![1.0, 1.0, 3.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
    });
    let g = &scene.get(node).unwrap().geometry;
    assert_eq!(g.fans.len(), 8, "eight cones");
    assert!(
        (g.fans.iter()).all(|f| f.fill_triangles().count() == ARC_SEGMENTS),
        "filled"
    );
    assert!(g.points.is_empty(), "not drawn as a scan");
    // The third element looks along +y from (0, 0.2): its cone reaches (0, 3.2) and is the
    // device's 15° wide (its config wins over the 60° coneAngle default).
    let cone = &g.fans[2];
    let tip = cone.rim[ARC_SEGMENTS / 2];
    assert!((tip - Vec3::new(0.0, 3.2, 0.0)).length() < 1e-4, "{tip}");
    let edge = cone.rim[0] - Vec3::new(0.0, 0.2, 0.0);
    let opening = edge.angle_between(Vec3::Y).to_degrees();
    assert!((opening - 7.5).abs() < 1e-2, "half opening {opening}°");
}

#[test]
fn readings_before_the_config_wait_for_it() {
    let mut h = harness();
    let Ok(mut plugin) = h.make(ranger_config(vec![])) else {
        panic!("default config refused");
    };
    push_ranges(&h.device, vec![1.0; 181]);
    plugin.run(&mut h.ctx());
    let node = plugin.node().unwrap();
    assert!(h.scene.get(node).unwrap().geometry.is_empty());

    // The config comes late: the readings already there are drawn with it.
    let config = RangerConfig {
        min_angle: -std::f64::consts::FRAC_PI_2,
        max_angle: std::f64::consts::FRAC_PI_2,
        angular_res: std::f64::consts::PI / 180.0,
        max_range: 8.0,
        ..RangerConfig::default()
    };
    let reply = Message::typed(addr(), MsgType::Ack, Ranger::Config(config));
    let config_kind = Ranger::REQ_GET_CONFIG.kind();
    assert_eq!(h.device.answer_later(config_kind, Ok(reply)), 1);
    assert!(h.run_changes_scene(plugin.as_mut()));
    assert_eq!(h.scene.get(node).unwrap().geometry.points.len(), 181);
}

#[test]
fn stamped_ranges_bring_their_own_geometry_and_config() {
    use player_proto::interfaces::ranger::RangerRangesStamped;

    let device = RecordingDevice::default(); // answers no request: the data must suffice
    let (scene, robot, node, _) = run(device, vec![], |d| {
        d.push(Message::typed(
            addr(),
            MsgType::Data,
            Ranger::RangesStamped(Box::new(RangerRangesStamped {
                data: RangerRanges {
                    ranges: vec![1.0, 2.0, 8.0],
                },
                have_geom: 1,
                geom: RangerGeometry {
                    pose: Pose3d {
                        px: 0.1,
                        ..Pose3d::default()
                    },
                    ..RangerGeometry::default()
                },
                have_config: 1,
                config: RangerConfig {
                    min_angle: -std::f64::consts::FRAC_PI_2,
                    max_angle: std::f64::consts::FRAC_PI_2,
                    angular_res: std::f64::consts::FRAC_PI_2,
                    max_range: 8.0,
                    ..RangerConfig::default()
                },
            })),
        ));
    });
    let object = scene.get(node).unwrap();
    assert_eq!(object.parent, Some(robot));
    let world = |p: Vec3| scene.world_transform(node).transform_point3(p);
    let ahead = world(object.geometry.points[1].pos);
    assert!(
        (ahead - Vec3::new(7.1, 0.0, 0.0)).length() < 1e-5,
        "{ahead}"
    );
}

/// The first `PLAYER_RANGER_DATA_RANGE` and the `_INTNS` after it that Stage 4 sent for the
/// laser of the repository's `captures/ranger_laser_push.jsonl`, or `None` if it has no such pair.
fn captured_ranges_and_intensities() -> Option<(Message, Message)> {
    let mut ranges = None;
    for message in support::captured_messages("ranger_laser_push.jsonl") {
        match (&message.body, ranges.is_some()) {
            (player_proto::message::Body::Ranger(Ranger::Ranges(_)), false) => {
                ranges = Some(message)
            }
            (player_proto::message::Body::Ranger(Ranger::Intensities(_)), true) => {
                return Some((ranges?, message));
            }
            _ => {}
        }
    }
    None
}

#[test]
fn stage_intensities_shade_the_returns_they_belong_to() {
    let (ranges, intensities) =
        captured_ranges_and_intensities().expect("a RANGE then an INTNS message in the capture");
    let device = RecordingDevice::default();
    // The capture's laser: 180° over 181 samples, 8 m (its GET_CONFIG reply in geom_config).
    answer(
        &device,
        RangerGeometry {
            element_poses: vec![Pose3d::default()],
            ..RangerGeometry::default()
        },
        RangerConfig {
            min_angle: -std::f64::consts::FRAC_PI_2,
            max_angle: std::f64::consts::FRAC_PI_2,
            angular_res: std::f64::consts::PI / 180.0,
            max_range: 8.0,
            ..RangerConfig::default()
        },
    );
    let Some(player_proto::message::Body::Ranger(Ranger::Intensities(values))) =
        Some(intensities.body.clone())
    else {
        unreachable!()
    };
    let (scene, _, node, _) = run(device, vec![], |d| {
        d.push(ranges);
        d.push(intensities);
    });
    let points = &scene.get(node).unwrap().geometry.points;
    assert!(!points.is_empty());
    let mut shades: Vec<u8> = points.iter().map(|p| p.color.0[0]).collect();
    shades.sort_unstable();
    shades.dedup();
    let mut levels: Vec<u64> = values
        .intensities
        .iter()
        .filter(|v| **v > 0.0)
        .map(|v| v.to_bits())
        .collect();
    levels.sort_unstable();
    levels.dedup();
    assert_eq!(
        shades.len(),
        levels.len(),
        "one shade per intensity Stage reported for a return: {shades:?}"
    );
}
