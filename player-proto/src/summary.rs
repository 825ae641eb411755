//! One-line human summaries of messages, for `playerdump`, `playerprint` and logs.

use crate::interfaces::common::Pose2d;
use crate::interfaces::localize::{Localize, cov};
use crate::interfaces::planner::Planner;
use crate::interfaces::{
    blobfinder::Blobfinder, camera::Camera, fiducial::Fiducial, laser::Laser, map::Map,
    player::Player, position2d::Position2d, power::Power, ranger::Ranger, simulation::Simulation,
    sonar::Sonar,
};
use crate::interfaces::{
    ir::Ir, pointcloud3d::Pointcloud3d, ptz::Ptz, speech_recognition::SpeechRecognition,
};
use crate::message::{Body, Message};

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
        Body::Localize(l) => localize(l),
        Body::Planner(p) => planner(p),
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

fn pose2d(p: &Pose2d) -> String {
    pose(p.px, p.py, p.pa)
}

/// Standard deviations of x, y and yaw: a reader judges a belief by its spread, not by
/// variances in m² and rad².
fn spread(c: &[f64; 6]) -> String {
    let sd = |v: f64| v.max(0.0).sqrt();
    format!(
        "± ({:.3} m, {:.3} m, {:.1}°)",
        sd(c[cov::XX]),
        sd(c[cov::YY]),
        sd(c[cov::AA]).to_degrees()
    )
}

fn localize(l: &Localize) -> String {
    match l {
        Localize::Hypotheses(d) => match d.best() {
            Some(best) => format!(
                "{} hypotheses, best {} {} weight {:.2}",
                d.hypoths.len(),
                pose2d(&best.mean),
                spread(&best.cov),
                best.alpha
            ),
            None => "no hypotheses".into(),
        },
        Localize::SetPose(p) => format!("set pose {} {}", pose2d(&p.mean), spread(&p.cov)),
        Localize::Particles(p) => format!(
            "{} particles, mean {} variance {:.3e}",
            p.particles.len(),
            pose2d(&p.mean),
            p.variance
        ),
    }
}

fn planner(p: &Planner) -> String {
    match p {
        Planner::State(s) if s.is_done() => {
            format!("done at {}, goal {}", pose2d(&s.pos), pose2d(&s.goal))
        }
        Planner::State(s) if s.is_valid() => format!(
            "at {}, waypoint {} of {} {}, goal {}",
            pose2d(&s.pos),
            s.waypoint_idx,
            s.waypoints_count,
            pose2d(&s.waypoint),
            pose2d(&s.goal)
        ),
        Planner::State(s) => format!("no plan, at {}", pose2d(&s.pos)),
        Planner::Goal(c) => format!("go to {}", pose2d(&c.goal)),
        Planner::Start(c) => format!("start from {}", pose2d(&c.goal)),
        Planner::Waypoints(w) => format!(
            "{} waypoints, {:.2} m",
            w.waypoints.len(),
            w.waypoints_distance
        ),
        Planner::Enable(e) => if e.is_on() { "enable" } else { "disable" }.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::localize::{LocalizeData, LocalizeHypothesis};
    use crate::interfaces::planner::{PlannerData, PlannerWaypoints};
    use crate::interfaces::{ir::IrData, ptz::PtzData, speech_recognition::SpeechRecognitionData};
    use crate::message::Body;
    use crate::wire::PlayerString;
    use crate::wire::{DevAddr, MsgType};

    fn line(addr: &str, body: impl Into<Body>) -> String {
        let addr: DevAddr = addr.parse().unwrap();
        summarize(&Message::typed(addr, MsgType::Data, body))
    }

    #[test]
    fn a_belief_reads_as_its_best_hypothesis_and_spread() {
        let weak = LocalizeHypothesis {
            alpha: 0.25,
            ..Default::default()
        };
        let strong = LocalizeHypothesis {
            mean: Pose2d::new(1.0, -2.0, std::f64::consts::FRAC_PI_2),
            cov: [0.01, 0.04, 0.0, 0.0, 0.0, 0.0],
            alpha: 0.75,
        };
        let data = LocalizeData {
            hypoths: vec![weak, strong],
            ..Default::default()
        };
        assert_eq!(
            line("localize:0", Localize::Hypotheses(data)),
            "2 hypotheses, best (1.000, -2.000, 90.0°) ± (0.100 m, 0.200 m, 0.0°) weight 0.75"
        );
    }

    #[test]
    fn a_plan_reads_as_progress_towards_the_goal() {
        let state = PlannerData {
            valid: 1,
            waypoint_idx: 1,
            waypoints_count: 3,
            goal: Pose2d::new(-2.0, 0.5, 0.0),
            ..Default::default()
        };
        assert_eq!(
            line("planner:0", Planner::State(state)),
            "at (0.000, 0.000, 0.0°), waypoint 1 of 3 (0.000, 0.000, 0.0°), goal (-2.000, 0.500, 0.0°)"
        );
        let done = PlannerData { done: 1, ..state };
        assert!(line("planner:0", Planner::State(done)).starts_with("done at"));
        let plan = PlannerWaypoints {
            waypoints_distance: 8.9765,
            waypoints: vec![Pose2d::default(); 3],
        };
        assert_eq!(
            line("planner:0", Planner::Waypoints(plan)),
            "3 waypoints, 8.98 m"
        );
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
    }
}
