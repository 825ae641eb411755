//! One-line human summaries of messages, for `playerdump`, `playerprint` and logs.

use crate::interfaces::gripper::{self, Gripper};
use crate::interfaces::{
    blobfinder::Blobfinder, bumper::Bumper, camera::Camera, fiducial::Fiducial, ir::Ir,
    laser::Laser, map::Map, player::Player, pointcloud3d::Pointcloud3d, position2d::Position2d,
    power::Power, ptz::Ptz, ranger::Ranger, simulation::Simulation, sonar::Sonar,
    speech_recognition::SpeechRecognition,
};
use crate::message::{Body, Message};

mod navigation;

fn nearest(values: impl Iterator<Item = f64>) -> String {
    match values.filter(|v| v.is_finite()).min_by(f64::total_cmp) {
        Some(v) => format!("min {v:.2} m"),
        None => "no readings".into(),
    }
}

fn pose(x: f64, y: f64, a: f64) -> String {
    format!("({x:.3}, {y:.3}, {:.1}°)", a.to_degrees())
}

/// What a message says, in a few words: `181 ranges, min 0.42 m`.
pub fn summarize(message: &Message) -> String {
    match &message.body {
        Body::Empty => "no body".into(),
        Body::Unknown(raw) => format!("{} bytes (unknown)", raw.len()),
        Body::Universal(u) => format!("{u:?}"),
        Body::Player(p) => match p {
            Player::DevList(d) => format!(
                "{} devices: {}",
                d.devices.len(),
                d.devices
                    .iter()
                    .map(|a| format!("{}:{}", a.interf, a.index))
                    .collect::<Vec<_>>()
                    .join(" ")
            ),
            Player::DriverInfo(i) => {
                format!("{}:{} = {}", i.addr.interf, i.addr.index, i.driver_name)
            }
            Player::Device(d) => format!(
                "{}:{} access {} driver {}",
                d.addr.interf, d.addr.index, d.access, d.driver_name
            ),
            Player::DataMode(m) => format!("mode {}", if m.mode == 2 { "PULL" } else { "PUSH" }),
            Player::AddReplaceRule(r) => format!(
                "rule interf {} index {} type {} subtype {} -> {}",
                r.interf, r.index, r.msg_type, r.subtype, r.replace
            ),
            Player::SynchOverflow(n) => format!("{} messages dropped", n.value),
            other => format!("{other:?}"),
        },
        Body::Laser(l) => match l {
            Laser::Scan(s) => format!(
                "{} ranges, {}, {} intensities",
                s.ranges.len(),
                nearest(s.ranges.iter().map(|&r| f64::from(r))),
                s.intensity.len()
            ),
            Laser::ScanPose(s) => format!(
                "{} ranges at {}",
                s.scan.ranges.len(),
                pose(s.pose.px, s.pose.py, s.pose.pa)
            ),
            Laser::Geometry(g) => format!(
                "pose {} size {:.3}×{:.3}",
                pose(g.pose.px, g.pose.py, g.pose.pyaw),
                g.size.sl,
                g.size.sw
            ),
            Laser::Config(c) | Laser::SetConfig(c) => format!(
                "{:.1}° to {:.1}° step {:.3}°, {} m, {} Hz",
                c.min_angle.to_degrees(),
                c.max_angle.to_degrees(),
                c.resolution.to_degrees(),
                c.max_range,
                c.scanning_frequency
            ),
            other => format!("{other:?}"),
        },
        Body::Sonar(s) => match s {
            Sonar::Ranges(r) => format!(
                "{} ranges, {}",
                r.ranges.len(),
                nearest(r.ranges.iter().map(|&r| f64::from(r)))
            ),
            Sonar::Geometry(g) | Sonar::GeometryData(g) => format!("{} transducers", g.poses.len()),
            other => format!("{other:?}"),
        },
        Body::Ranger(r) => match r {
            Ranger::Ranges(d) => format!(
                "{} ranges, {}",
                d.ranges.len(),
                nearest(d.ranges.iter().copied())
            ),
            Ranger::Intensities(d) => format!("{} intensities", d.intensities.len()),
            Ranger::Geometry(g) | Ranger::GeometryData(g) => {
                format!("{} elements", g.element_poses.len())
            }
            Ranger::Config(c) | Ranger::SetConfig(c) => format!(
                "{:.1}° to {:.1}°, {}–{} m, {} Hz",
                c.min_angle.to_degrees(),
                c.max_angle.to_degrees(),
                c.min_range,
                c.max_range,
                c.frequency
            ),
            other => format!("{other:?}"),
        },
        Body::Position2d(p) => match p {
            Position2d::State(s) => format!(
                "pose {} vel ({:.2} m/s, {:.2} rad/s){}",
                pose(s.pos.px, s.pos.py, s.pos.pa),
                s.vel.px,
                s.vel.pa,
                if s.stall != 0 { " STALLED" } else { "" }
            ),
            Position2d::Velocity(v) => format!(
                "vel ({:.2}, {:.2}, {:.2}) motors {}",
                v.vel.px, v.vel.py, v.vel.pa, v.state
            ),
            Position2d::Position(c) => format!("go to {}", pose(c.pos.px, c.pos.py, c.pos.pa)),
            Position2d::Geometry(g) => format!("size {:.3}×{:.3}", g.size.sl, g.size.sw),
            other => format!("{other:?}"),
        },
        Body::Fiducial(f) => match f {
            Fiducial::Scan(d) => format!(
                "{} markers: {}",
                d.fiducials.len(),
                d.fiducials
                    .iter()
                    .map(|i| format!(
                        "#{} at {:.2} m {:.0}°",
                        i.id,
                        i.range(),
                        i.bearing().to_degrees()
                    ))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            other => format!("{other:?}"),
        },
        Body::Camera(c) => match c {
            Camera::State(d) | Camera::Image(d) => format!(
                "{}×{} {} bpp format {} {}, {} bytes",
                d.width,
                d.height,
                d.bpp,
                d.format,
                if d.compression == 1 { "JPEG" } else { "raw" },
                d.image.len()
            ),
            other => format!("{other:?}"),
        },
        Body::Simulation(s) => match s {
            Simulation::Pose2d(p) | Simulation::SetPose2d(p) => {
                format!("{} at {}", p.name, pose(p.pose.px, p.pose.py, p.pose.pa))
            }
            other => format!("{other:?}"),
        },
        Body::Map(Map::Info(i) | Map::InfoData(i)) => format!(
            "{}×{} cells of {:.3} m, origin {}",
            i.width,
            i.height,
            i.scale,
            navigation::pose2d(&i.origin)
        ),
        Body::Map(Map::Vector(v)) => format!(
            "{} segments in ({:.2}, {:.2})–({:.2}, {:.2})",
            v.segments.len(),
            v.minx,
            v.miny,
            v.maxx,
            v.maxy
        ),
        Body::Bumper(Bumper::State(b)) => {
            let pressed: Vec<String> = (b.bumpers.iter().enumerate())
                .filter(|(_, on)| **on != 0)
                .map(|(i, _)| i.to_string())
                .collect();
            format!(
                "{} bumpers, pressed: [{}]",
                b.bumpers.len(),
                pressed.join(" ")
            )
        }
        Body::Gripper(Gripper::State(g)) => format!(
            "{}, beams {:#b}, {} stored",
            gripper_state(g.state),
            g.beams,
            g.stored
        ),
        Body::Map(Map::Tile(t)) => format!(
            "tile {}×{} at ({}, {}), {} compressed bytes",
            t.width,
            t.height,
            t.col,
            t.row,
            t.data.len()
        ),
        Body::Blobfinder(Blobfinder::Blobs(b)) => {
            format!("{} blobs in {}×{}", b.blobs.len(), b.width, b.height)
        }
        Body::Power(Power::State(p)) => format!("{:.1} V, {:.0} %", p.volts, p.percent),
        Body::Localize(l) => navigation::localize(l),
        Body::Planner(p) => navigation::planner(p),
        Body::Ptz(Ptz::State(s)) => format!(
            "pan {:.1}° tilt {:.1}° fov {:.1}°",
            s.pan.to_degrees(),
            s.tilt.to_degrees(),
            s.zoom.to_degrees()
        ),
        Body::Ptz(Ptz::Command(c)) => format!(
            "to pan {:.1}° tilt {:.1}° fov {:.1}°",
            c.pan.to_degrees(),
            c.tilt.to_degrees(),
            c.zoom.to_degrees()
        ),
        Body::Ir(Ir::Ranges(r)) => format!(
            "{} ranges, {}",
            r.ranges.len(),
            nearest(r.ranges.iter().map(|&r| f64::from(r)))
        ),
        Body::Ir(Ir::Pose(p)) => format!("{} sensors", p.poses.len()),
        Body::Pointcloud3d(Pointcloud3d::State(c)) => format!("{} points", c.points.len()),
        Body::SpeechRecognition(SpeechRecognition::Text(t)) => {
            format!("heard {:?}", t.text.as_str())
        }
        other => format!("{other:?}"),
    }
}

fn gripper_state(state: u8) -> String {
    match state {
        gripper::STATE_OPEN => "open".into(),
        gripper::STATE_CLOSED => "closed".into(),
        gripper::STATE_MOVING => "moving".into(),
        gripper::STATE_ERROR => "error".into(),
        other => format!("state {other}"),
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::interfaces::bumper::BumperData;
    use crate::interfaces::gripper::GripperData;
    use crate::interfaces::{ir::IrData, ptz::PtzData, speech_recognition::SpeechRecognitionData};
    use crate::wire::{DevAddr, MsgType, Opaque, PlayerString};

    pub(super) fn line(addr: &str, body: impl Into<Body>) -> String {
        let addr: DevAddr = addr.parse().unwrap();
        summarize(&Message::typed(addr, MsgType::Data, body))
    }

    #[test]
    fn devices_read_in_their_units() {
        let ptz = PtzData {
            pan: std::f32::consts::FRAC_PI_2,
            zoom: std::f32::consts::FRAC_PI_4,
            ..Default::default()
        };
        assert_eq!(
            line("ptz:0", Ptz::State(ptz)),
            "pan 90.0° tilt 0.0° fov 45.0°"
        );
        let ir = IrData {
            ranges: vec![0.8, 0.25, f32::NAN],
            ..Default::default()
        };
        assert_eq!(line("ir:0", Ir::Ranges(ir)), "3 ranges, min 0.25 m");
        let heard = SpeechRecognitionData {
            text: PlayerString::new("go left"),
        };
        assert_eq!(
            line("speech_recognition:0", SpeechRecognition::Text(heard)),
            "heard \"go left\""
        );
        let bumpers = BumperData {
            bumpers: Opaque::from(vec![0, 1, 0, 0, 1]),
        };
        assert_eq!(
            line("bumper:0", Bumper::State(bumpers)),
            "5 bumpers, pressed: [1 4]"
        );
        let gripper = GripperData {
            state: gripper::STATE_CLOSED,
            beams: 0b101,
            stored: 1,
        };
        assert_eq!(
            line("gripper:0", Gripper::State(gripper)),
            "closed, beams 0b101, 1 stored"
        );
    }
}
