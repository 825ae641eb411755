//! The conversion on real Player 3 + Stage 4 traffic (`captures/`): every capture gives the
//! Foxglove messages its devices should, and a laser scan keeps its ranges.

use std::collections::BTreeMap;
use std::path::Path;

use player_proto::capture::{Direction, parse_capture};
use player_proto::recording::Event;
use player_proto::recording::from_capture::records_from_capture;

use super::*;

/// What a capture's server messages convert to, counted by schema and topic.
fn converted(capture: &str) -> (BTreeMap<(String, String), usize>, Vec<Output>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../captures")
        .join(capture);
    let chunks = parse_capture(&std::fs::read_to_string(path).unwrap()).unwrap();
    let records = records_from_capture(&chunks, "localhost", 6665, 0, 0).unwrap();
    let mut converter = Converter::new();
    let mut counts = BTreeMap::new();
    let mut all = Vec::new();
    for record in records {
        if let Event::Message {
            direction: Direction::ServerToClient,
            header,
            body,
        } = record.event
        {
            for output in converter.server_message("localhost:6665", &header, &body) {
                let schema = output.message.schema().name;
                *counts.entry((schema, output.topic.clone())).or_default() += 1;
                assert!(!output.message.encode().is_empty() || schema_may_be_empty(&output));
                all.push(output);
            }
        }
    }
    (counts, all)
}

fn schema_may_be_empty(output: &Output) -> bool {
    matches!(output.message, FoxgloveMessage::PoseInFrame(_))
}

fn has(counts: &BTreeMap<(String, String), usize>, schema: &str, topic: &str) -> bool {
    counts.contains_key(&(schema.to_string(), topic.to_string()))
}

/// The topic and scan of outputs that must be one laser scan.
fn one_scan(outputs: &[Output]) -> (&str, &foxglove::messages::LaserScan) {
    match outputs {
        [
            Output {
                topic,
                message: FoxgloveMessage::LaserScan(scan),
            },
        ] => (topic, scan),
        _ => panic!("not one scan: {outputs:?}"),
    }
}

#[test]
fn a_real_laser_becomes_laser_scans_with_its_ranges() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures/laser_push.jsonl");
    let chunks = parse_capture(&std::fs::read_to_string(path).unwrap()).unwrap();
    let records = records_from_capture(&chunks, "localhost", 6665, 0, 0).unwrap();
    let mut converter = Converter::new();
    let mut checked = 0;
    for record in records {
        let Event::Message {
            direction: Direction::ServerToClient,
            header,
            body,
        } = record.event
        else {
            continue;
        };
        let Ok(Message {
            body: Body::Laser(Laser::Scan(scan)),
            ..
        }) = Message::decode(header, body.clone())
        else {
            continue;
        };
        let outputs = converter.server_message("localhost:6665", &header, &body);
        let (topic, converted) = one_scan(&outputs);
        assert_eq!(topic, "/localhost:6665/laser/0/scan");
        assert_eq!(converted.frame_id, "localhost:6665/laser/0");
        let ranges: Vec<f64> = scan.ranges.iter().map(|&r| f64::from(r)).collect();
        assert_eq!(converted.ranges, ranges);
        assert_eq!(converted.start_angle, f64::from(scan.min_angle));
        assert_eq!(converted.end_angle, f64::from(scan.max_angle));
        let intensities: Vec<f64> = scan.intensity.iter().map(|&i| f64::from(i)).collect();
        assert_eq!(converted.intensities, intensities);
        checked += 1;
    }
    assert!(checked >= 10, "{checked} scans");
}

#[test]
fn a_scan_with_its_pose_converts_as_its_scan_and_a_damaged_one_to_nothing() {
    use player_proto::interfaces::common::Pose2d;
    use player_proto::interfaces::laser::{LaserScan, LaserScanPose};
    use player_proto::wire::{DevAddr, HEADER_LEN, Opaque};
    let scan = LaserScan {
        min_angle: -1.5,
        max_angle: 1.5,
        resolution: 1.0,
        max_range: 8.0,
        ranges: vec![1.0, 2.5, 4.0, 8.0],
        intensity: Opaque::from(vec![0, 1, 2, 3]),
        id: 3,
    };
    let laser = DevAddr::local(Interface::LASER, 1);
    let with_pose = LaserScanPose {
        scan,
        pose: Pose2d::new(1.0, 2.0, 0.5),
    };
    let message = Message::typed(laser, MsgType::Data, Laser::ScanPose(with_pose));
    let wire = message.to_bytes();
    let body = wire.slice(HEADER_LEN..);
    let mut converter = Converter::new();
    let outputs = converter.server_message("r", &message.header, &body);
    let (topic, converted) = one_scan(&outputs);
    assert_eq!(topic, "/r/laser/1/scan");
    assert_eq!(converted.frame_id, "r/laser/1");
    assert_eq!(converted.ranges, [1.0, 2.5, 4.0, 8.0]);
    assert_eq!(converted.intensities, [0.0, 1.0, 2.0, 3.0]);
    // Cut inside the ranges: nothing converted, nothing panics.
    let mut header = message.header;
    header.size = 30;
    assert!(
        converter
            .server_message("r", &header, &body.slice(..30))
            .is_empty()
    );
}

#[test]
fn every_kind_of_real_device_converts_to_its_schema() {
    let robot = "/localhost:6665";
    let (counts, _) = converted("position2d_push.jsonl");
    assert!(
        has(
            &counts,
            "foxglove.PoseInFrame",
            &format!("{robot}/position2d/0/pose")
        ),
        "{counts:?}"
    );
    assert!(
        has(&counts, "foxglove.FrameTransform", &format!("{robot}/tf")),
        "{counts:?}"
    );
    let (counts, _) = converted("camera_jpeg_push.jsonl");
    assert!(
        has(
            &counts,
            "foxglove.CompressedImage",
            &format!("{robot}/camera/1/image")
        ),
        "{counts:?}"
    );
    let (counts, _) = converted("camera_raw_push.jsonl");
    assert!(
        has(
            &counts,
            "foxglove.RawImage",
            &format!("{robot}/camera/0/image")
        ),
        "{counts:?}"
    );
    let (counts, _) = converted("fiducial_push.jsonl");
    assert!(
        has(
            &counts,
            "foxglove.SceneUpdate",
            &format!("{robot}/fiducial/0/fiducials")
        ),
        "{counts:?}"
    );
    let (counts, _) = converted("nav/localize_hypotheses_setpose.jsonl");
    assert!(
        has(
            &counts,
            "foxglove.PoseInFrame",
            &format!("{robot}/localize/0/pose")
        ),
        "{counts:?}"
    );
    let (counts, _) = converted("nav/planner_goal_waypoints.jsonl");
    assert!(
        has(
            &counts,
            "foxglove.SceneUpdate",
            &format!("{robot}/planner/0/path")
        ),
        "{counts:?}"
    );
    let (counts, all) = converted("nav/map_info_data.jsonl");
    assert!(
        has(&counts, "foxglove.Grid", &format!("{robot}/map/0/grid")),
        "{counts:?}"
    );
    let grid = all.iter().find_map(|o| match &o.message {
        FoxgloveMessage::Grid(g) => Some(g),
        _ => None,
    });
    let grid = grid.expect("a grid");
    assert_eq!(
        grid.data.len() as u32,
        grid.row_stride * (grid.data.len() as u32 / grid.row_stride)
    );
    assert!(grid.data.iter().any(|&c| c as i8 > 0), "no occupied cell");
}

#[test]
fn geometries_place_devices_on_their_robot() {
    let (_, all) = converted("geom_config.jsonl");
    let transforms: Vec<_> = all
        .iter()
        .filter_map(|o| match &o.message {
            FoxgloveMessage::FrameTransform(t) if t.parent_frame_id != WORLD => Some(t),
            _ => None,
        })
        .collect();
    assert!(!transforms.is_empty(), "no robot → device transform");
    for t in transforms {
        assert!(
            t.child_frame_id
                .starts_with(&format!("{}/", t.parent_frame_id)),
            "{t:?}"
        );
    }
}
