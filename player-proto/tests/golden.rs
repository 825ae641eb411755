//! Golden tests on real bytes: every message a Player 3.1 server (with Stage 4.3) and libplayerc
//! exchanged in the repository's `captures/` decodes to a typed message and re-encodes to the
//! very same bytes; decoded values match what libplayerc printed for the same session.

mod support;

use player_proto::interfaces::{
    fiducial::Fiducial, laser::Laser, player::Player, position2d::Position2d,
};
use player_proto::interfaces::{ranger::Ranger, simulation::Simulation, sonar::Sonar};
use player_proto::message::{Body, Message};
use player_proto::wire::MsgType;
use support::captures::captures_dir;
use support::sessions::load;

#[test]
fn every_captured_message_decodes_typed_and_reencodes_identically() {
    let dir = captures_dir();
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "jsonl"))
        .collect();
    files.sort();
    assert!(
        files.len() >= 15,
        "expected the full capture set in {}",
        dir.display()
    );
    let mut total = 0;
    for file in files {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let (s2c, c2s) = load(&name);
        total += s2c.len() + c2s.len();
    }
    // The repository's set, with its camera and multi-robot sessions trimmed, holds 843.
    assert!(total >= 800, "only {total} messages");
}

fn data(messages: &[Message], subtype: u8) -> impl Iterator<Item = &Message> {
    messages
        .iter()
        .filter(move |m| m.header.msg_type == MsgType::Data && m.header.subtype == subtype)
}

#[test]
fn laser_scans_match_libplayerc() {
    let (s2c, _) = load("laser_push.jsonl");
    let scans: Vec<_> = data(&s2c, 1)
        .filter_map(|m| match &m.body {
            Body::Laser(Laser::Scan(s)) => Some(s),
            _ => None,
        })
        .collect();
    assert_eq!(scans.len(), 60);
    for scan in &scans {
        assert_eq!(scan.ranges.len(), 181);
        assert!(
            (scan.resolution - 0.017357).abs() < 1e-5,
            "fov / samples, not fov / (samples - 1)"
        );
        assert!((scan.min_angle + std::f32::consts::FRAC_PI_2).abs() < 1e-5);
        assert_eq!(scan.max_range, 8.0);
    }
    // rangertolaser publishes a scan without intensities and one with them, every step.
    assert!(scans.iter().any(|s| s.intensity.is_empty()));
    assert!(scans.iter().any(|s| s.intensity.len() == 181));
}

#[test]
fn device_list_and_driver_names_match_libplayerc() {
    let (s2c, _) = load("devlist_driverinfo.jsonl");
    let devices = s2c
        .iter()
        .find_map(|m| match &m.body {
            Body::Player(Player::DevList(d)) => Some(d.devices.clone()),
            _ => None,
        })
        .expect("a device list");
    assert_eq!(devices.len(), 15);
    assert!(
        devices
            .iter()
            .all(|d| d.robot == 6665 && d.host == 0x0100_007f)
    );
    let names: Vec<String> = s2c
        .iter()
        .filter_map(|m| match &m.body {
            Body::Player(Player::DriverInfo(i)) => {
                Some(format!("{}={}", i.addr.interf, i.driver_name))
            }
            _ => None,
        })
        .collect();
    assert_eq!(names.len(), 15);
    for expected in [
        "simulation=stage",
        "laser=rangertolaser",
        "sonar=rangertosonar",
        "camera=cameracompress",
    ] {
        assert!(
            names.iter().any(|n| n == expected),
            "{expected} in {names:?}"
        );
    }
}

#[test]
fn geometry_and_config_replies_match_libplayerc() {
    let (s2c, _) = load("geom_config.jsonl");
    let acks: Vec<&Body> = s2c
        .iter()
        .filter(|m| m.header.msg_type == MsgType::Ack)
        .map(|m| &m.body)
        .collect();
    let laser_config = acks
        .iter()
        .find_map(|b| match b {
            Body::Laser(Laser::Config(c)) => Some(c),
            _ => None,
        })
        .unwrap();
    assert!(
        (laser_config.resolution - 0.017357).abs() < 1e-5
            && laser_config.scanning_frequency == 10.0
    );
    let sonar = acks
        .iter()
        .find_map(|b| match b {
            Body::Sonar(Sonar::Geometry(g)) => Some(g),
            _ => None,
        })
        .unwrap();
    assert_eq!(sonar.poses.len(), 16);
    assert!((sonar.poses[0].px - 0.075).abs() < 1e-3 && (sonar.poses[0].pyaw - 1.571).abs() < 1e-3);
    let base = acks
        .iter()
        .find_map(|b| match b {
            Body::Position2d(Position2d::Geometry(g)) => Some(g),
            _ => None,
        })
        .unwrap();
    assert!(
        (base.pose.px + 0.04).abs() < 1e-6
            && (base.size.sl - 0.44).abs() < 1e-6
            && (base.size.sw - 0.38).abs() < 1e-6
    );
    let configs: Vec<_> = acks
        .iter()
        .filter_map(|b| match b {
            Body::Ranger(Ranger::Config(c)) => Some(c),
            _ => None,
        })
        .collect();
    assert_eq!(configs.len(), 2);
    assert!((configs[0].max_range - 5.0).abs() < 1e-9 && (configs[1].max_range - 8.0).abs() < 1e-9);
    let fiducial = acks
        .iter()
        .any(|b| matches!(b, Body::Fiducial(Fiducial::Geometry(_))));
    assert!(fiducial);
}

#[test]
fn fiducials_report_the_landmark_ids() {
    let (s2c, _) = load("fiducial_push.jsonl");
    let scans: Vec<_> = data(&s2c, 1)
        .filter_map(|m| match &m.body {
            Body::Fiducial(Fiducial::Scan(d)) => Some(d),
            _ => None,
        })
        .collect();
    assert_eq!(scans.len(), 30);
    for scan in scans {
        let mut ids: Vec<i32> = scan.fiducials.iter().map(|f| f.id).collect();
        ids.sort();
        assert_eq!(ids, [0, 0, 5, 6, 7]);
    }
}

#[test]
fn the_robot_moves_as_commanded() {
    let (s2c, c2s) = load("position2d_move.jsonl");
    let commanded = c2s.iter().any(|m| {
        matches!(&m.body, Body::Position2d(Position2d::Velocity(v)) if (v.vel.px - 0.4).abs() < 1e-9 && (v.vel.pa - 0.3).abs() < 1e-9 && v.state == 1)
    });
    assert!(commanded);
    let poses: Vec<_> = data(&s2c, 1)
        .filter_map(|m| match &m.body {
            Body::Position2d(Position2d::State(s)) => Some(s.pos),
            _ => None,
        })
        .collect();
    let (first, last) = (poses.first().unwrap(), poses.last().unwrap());
    assert!((first.px + 3.0).abs() < 1e-6 && first.py.abs() < 1e-6);
    assert!(
        (last.px + 1.92).abs() < 0.05
            && (last.py - 0.52).abs() < 0.05
            && (last.pa - 0.93).abs() < 0.05,
        "{last:?}"
    );
}

#[test]
fn pull_rounds_are_ack_then_data_then_synch() {
    let (s2c, _) = load("pull_position2d_laser.jsonl");
    let kinds: Vec<MsgType> = s2c.iter().map(|m| m.header.msg_type).collect();
    let synchs = kinds.iter().filter(|k| **k == MsgType::Synch).count();
    assert_eq!(synchs, 12);
    // Each SYNCH is preceded by data, and each round starts with the ACK of REQ_DATA.
    for (i, k) in kinds.iter().enumerate() {
        if *k == MsgType::Synch {
            assert_eq!(kinds[i - 1], MsgType::Data);
        }
    }
}

#[test]
fn nacks_and_simulation_poses() {
    let (s2c, c2s) = load("nack_and_simulation.jsonl");
    let nacks = s2c
        .iter()
        .filter(|m| m.header.msg_type == MsgType::Nack)
        .count();
    assert_eq!(nacks, 3, "power, intensity and the unknown model");
    let pose = s2c
        .iter()
        .find_map(|m| match (&m.header.msg_type, &m.body) {
            (MsgType::Ack, Body::Simulation(Simulation::Pose2d(p))) => Some(p),
            _ => None,
        })
        .unwrap();
    assert_eq!(pose.name.as_str(), "r0");
    assert!((pose.pose.px + 3.0).abs() < 1e-9);
    let asked: Vec<String> = c2s
        .iter()
        .filter_map(|m| match &m.body {
            Body::Simulation(Simulation::Pose2d(p)) => Some(p.name.as_str().into_owned()),
            _ => None,
        })
        .collect();
    assert_eq!(asked, ["r0", "no_such_model"]);
}
