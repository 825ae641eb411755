//! Views on real bytes: every laser scan, ranger and sonar reading, odometry report, fiducial
//! scan, camera frame, map tile and device list in the captures (a real Player 3.1 server's
//! bytes), read in place, holds exactly what decoding it gives.

mod support;

use std::fmt::Debug;

use player_proto::body_kind::BodyKind;
use player_proto::interfaces::camera::Camera;
use player_proto::interfaces::fiducial::Fiducial;
use player_proto::interfaces::laser::Laser;
use player_proto::interfaces::map::Map;
use player_proto::interfaces::player::Player;
use player_proto::interfaces::position2d::Position2d;
use player_proto::interfaces::ranger::Ranger;
use player_proto::interfaces::sonar::Sonar;
use player_proto::message::Message;
use player_proto::wire::{HEADER_LEN, XdrView};
use support::sessions::load;

/// Every message of `kind` in the capture files, viewed and compared with its decoded body;
/// how many there were.
fn views_agree<T: XdrView + PartialEq + Debug>(kind: BodyKind<T>, files: &[&str]) -> usize {
    let mut seen = 0;
    for file in files {
        let (s2c, c2s) = load(file);
        for message in s2c.iter().chain(&c2s) {
            let wire = message.to_bytes();
            let body = &wire[HEADER_LEN..];
            let Some(view) = kind.view(&message.header, body) else {
                continue;
            };
            let view = view.unwrap_or_else(|e| panic!("{file}: {e}"));
            assert_eq!(Some(&T::to_owned_value(view)), kind.of(message), "{file}");
            seen += 1;
        }
    }
    seen
}

#[test]
fn views_of_real_messages_hold_what_decoding_gives() {
    let laser = [
        "laser_push.jsonl",
        "pull_position2d_laser.jsonl",
        "ranger_laser_push.jsonl",
    ];
    assert!(views_agree(Laser::DATA_SCAN, &laser) >= 60);
    let ranger = [
        "ranger_laser_push.jsonl",
        "ranger_sonar_push.jsonl",
        "geom_config.jsonl",
    ];
    assert!(views_agree(Ranger::DATA_RANGE, &ranger) > 0);
    assert!(views_agree(Ranger::DATA_INTNS, &ranger) > 0);
    assert!(views_agree(Ranger::REQ_GET_GEOM, &ranger) > 0);
    assert!(views_agree(Sonar::DATA_RANGES, &["sonar_push.jsonl"]) > 0);
    let odometry = ["position2d_push.jsonl", "position2d_move.jsonl"];
    assert!(views_agree(Position2d::DATA_STATE, &odometry) > 0);
    assert!(views_agree(Fiducial::DATA_SCAN, &["fiducial_push.jsonl"]) > 0);
    let camera = ["camera_raw_push.jsonl", "camera_jpeg_push.jsonl"];
    assert!(views_agree(Camera::DATA_STATE, &camera) > 0);
    assert!(views_agree(Map::REQ_GET_DATA, &["nav/map_info_data.jsonl"]) > 0);
    assert!(views_agree(Player::REQ_DEVLIST, &["devlist_driverinfo.jsonl"]) > 0);
}

#[test]
fn a_scan_read_in_place_gives_its_ranges_and_intensities() {
    let (s2c, _) = load("laser_push.jsonl");
    let message: &Message = s2c
        .iter()
        .find(|m| {
            Laser::DATA_SCAN
                .of(m)
                .is_some_and(|s| !s.intensity.is_empty())
        })
        .expect("a scan with intensities");
    let scan = Laser::DATA_SCAN.of(message).unwrap();
    let wire = message.to_bytes();
    let view = Laser::DATA_SCAN
        .view(&message.header, &wire[HEADER_LEN..])
        .unwrap()
        .unwrap();
    assert_eq!(view.ranges.len(), 181);
    assert_eq!(view.ranges.get(90), Some(scan.ranges[90]));
    assert_eq!(view.ranges.get(181), None);
    assert!(view.ranges.iter().eq(scan.ranges.iter().copied()));
    assert_eq!(view.intensity, &scan.intensity[..]);
    // Into a buffer the reader keeps: no allocation once it has room.
    let mut ranges = Vec::with_capacity(181);
    view.ranges.extend_into(&mut ranges);
    assert_eq!(ranges, scan.ranges);
    // Another kind's header is not viewed as this one.
    assert!(
        Laser::DATA_SCANPOSE
            .view(&message.header, &wire[HEADER_LEN..])
            .is_none()
    );
}

#[test]
fn a_view_of_a_damaged_scan_is_refused_as_decoding_refuses_it() {
    let (s2c, _) = load("laser_push.jsonl");
    let message = s2c
        .iter()
        .find(|m| Laser::DATA_SCAN.of(m).is_some())
        .unwrap();
    let wire = message.to_bytes();
    let short = &wire[HEADER_LEN..wire.len() - 3];
    let viewed = Laser::DATA_SCAN
        .view(&message.header, short)
        .unwrap()
        .unwrap_err();
    let decoded =
        Message::decode(message.header, wire.slice(HEADER_LEN..wire.len() - 3)).unwrap_err();
    assert_eq!(viewed, decoded);
    assert!(viewed.to_string().contains("LaserScan."), "{viewed}");
}
