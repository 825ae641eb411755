//! The people detector on simulated scans: legs (circles) and walls ray-cast the way a
//! laser sees them, then found, paired, tracked, and put in the scene tagged `person`.

mod support;

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::query::{Query, Target, answer_world};
use glam::Vec2;
use player_proto::DevAddr;
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::message::Message;
use player_proto::wire::MsgType;
use plugins::people::legs::{LegParams, Scan, people};
use plugins::people::tracker::Tracker;
use support::harness;

const LEG_RADIUS: f32 = 0.06;
const BEAMS: usize = 361;
const MAX_RANGE: f32 = 8.0;
/// A wall across the room, this far ahead.
const WALL: f32 = 5.0;

fn first() -> f32 {
    -std::f32::consts::FRAC_PI_2
}

fn step() -> f32 {
    std::f32::consts::PI / (BEAMS - 1) as f32
}

/// Where a ray from the origin along `bearing` first meets a circle, if it does.
fn hit_circle(bearing: f32, centre: Vec2, radius: f32) -> Option<f32> {
    let d = Vec2::from_angle(bearing);
    let along = centre.dot(d);
    let off2 = centre.length_squared() - along * along;
    let r2 = radius * radius;
    (along > 0.0 && off2 <= r2).then(|| along - (r2 - off2).sqrt())
}

/// A scan of circles (legs, posts) in front of a wall.
fn ranges(circles: &[(Vec2, f32)]) -> Vec<f32> {
    (0..BEAMS)
        .map(|i| {
            let bearing = first() + step() * i as f32;
            let wall = if bearing.cos() > 0.05 {
                WALL / bearing.cos()
            } else {
                MAX_RANGE
            };
            circles
                .iter()
                .filter_map(|&(c, r)| hit_circle(bearing, c, r))
                .fold(wall.min(MAX_RANGE), f32::min)
        })
        .collect()
}

/// A person's two legs, `apart` between centres, standing at `at` across the beams.
fn legs_at(at: Vec2, apart: f32) -> [(Vec2, f32); 2] {
    let side = Vec2::new(0.0, apart / 2.0);
    [(at + side, LEG_RADIUS), (at - side, LEG_RADIUS)]
}

fn find(ranges: &[f32], params: &LegParams) -> Vec<Vec2> {
    people(
        &Scan {
            ranges,
            first: first(),
            step: step(),
            max_range: MAX_RANGE,
        },
        params,
    )
}

#[test]
fn two_legs_make_one_person_between_them() {
    let scan = ranges(&legs_at(Vec2::new(2.0, 0.5), 0.25));
    let found = find(&scan, &LegParams::default());
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].distance(Vec2::new(2.0, 0.5)) < 0.1, "{found:?}");
}

#[test]
fn two_people_apart_are_two_and_a_lone_leg_or_a_wide_box_is_nobody() {
    let mut circles = legs_at(Vec2::new(2.0, 1.0), 0.25).to_vec();
    circles.extend(legs_at(Vec2::new(3.0, -1.5), 0.2));
    assert_eq!(find(&ranges(&circles), &LegParams::default()).len(), 2);

    let lone_post = [(Vec2::new(2.0, 0.0), LEG_RADIUS)];
    assert!(find(&ranges(&lone_post), &LegParams::default()).is_empty());

    let robot_wide = [(Vec2::new(2.0, 0.0), 0.2)];
    assert!(
        find(&ranges(&robot_wide), &LegParams::default()).is_empty(),
        "off by default"
    );
    let with_bodies = LegParams {
        body_width: Some((0.3, 0.6)),
        ..LegParams::default()
    };
    assert_eq!(find(&ranges(&robot_wide), &with_bodies).len(), 1);
}

#[test]
fn legs_too_far_apart_are_not_one_person() {
    let scan = ranges(&legs_at(Vec2::new(2.0, 0.0), 0.9));
    assert!(find(&scan, &LegParams::default()).is_empty());
}

#[test]
fn a_walking_person_keeps_their_identity_and_leaves_after_some_missed_scans() {
    let mut tracker = Tracker::new(0.6, 2);
    let first = tracker.update(&[Vec2::new(1.0, 0.0)]);
    assert_eq!(first.appeared.len(), 1);
    let id = first.appeared[0];
    for step in 1..10 {
        let changes = tracker.update(&[Vec2::new(1.0 + 0.1 * step as f32, 0.0)]);
        assert!(
            changes.appeared.is_empty() && changes.left.is_empty(),
            "{changes:?}"
        );
    }
    assert_eq!(tracker.tracks()[0].id, id);
    assert!(
        tracker.update(&[]).left.is_empty(),
        "one missed scan is not leaving"
    );
    assert!(tracker.update(&[]).left.is_empty());
    assert_eq!(tracker.update(&[]).left, [id]);
    let again = tracker.update(&[Vec2::new(1.9, 0.0)]);
    assert_ne!(
        again.appeared,
        [id],
        "someone who came back is a new identity"
    );
}

fn config() -> PluginConfig {
    PluginConfig {
        library: "libpv3d_people".into(),
        id: "people".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: "laser:0".parse().unwrap(),
            driver: "stage".into(),
        }),
        params: vec![Param::new("keepScans", "1")],
        ..PluginConfig::default()
    }
}

fn push_scan(device: &framework::device::RecordingDevice, ranges: Vec<f32>, id: u32) {
    let addr: DevAddr = "laser:0".parse().unwrap();
    let scan = LaserScan {
        min_angle: first(),
        max_angle: -first(),
        resolution: step(),
        max_range: MAX_RANGE,
        ranges,
        id,
        ..LaserScan::default()
    };
    device.push(Message::typed(addr, MsgType::Data, Laser::Scan(scan)));
}

#[test]
fn people_appear_in_the_scene_tagged_person_and_go_when_they_leave() {
    let mut w = harness();
    let mut plugin = w.make(config()).unwrap();
    let ask = Query::new(Target::Named("world".into()), "is there any").with_attr("tag", "person");
    let count = |w: &support::Harness| {
        answer_world(&ask, &w.scene)
            .unwrap()
            .body
            .attr("count")
            .map(str::to_string)
    };
    push_scan(&w.device, ranges(&legs_at(Vec2::new(2.0, 0.0), 0.25)), 1);
    plugin.run(&mut w.ctx());
    assert_eq!(count(&w).as_deref(), Some("1"));
    let person = w
        .scene
        .iter()
        .find(|(_, o)| o.has_tag("person"))
        .unwrap()
        .1
        .clone();
    assert!(
        person.tags.iter().any(|t| t.starts_with("id:p")),
        "{:?}",
        person.tags
    );

    push_scan(&w.device, ranges(&legs_at(Vec2::new(2.2, 0.0), 0.25)), 2);
    plugin.run(&mut w.ctx());
    let (_, moved) = w.scene.iter().find(|(_, o)| o.has_tag("person")).unwrap();
    assert_eq!(moved.name, person.name, "the same person, moved");
    assert!((moved.transform.translation.x - 2.2).abs() < 0.1);

    for id in 3..5 {
        push_scan(&w.device, ranges(&[]), id);
        plugin.run(&mut w.ctx());
    }
    assert_eq!(
        count(&w).as_deref(),
        Some("0"),
        "gone after keepScans missed scans"
    );
    plugin.clean(&mut w.ctx());
}
