//! pv3d against a live Player server over real TCP: a robot facing a wall 2 m ahead, its laser
//! seeing the wall. The screenshot must show the robot and, to its right (east, the way it
//! faces), the wall's returns as a vertical line.

use std::process::Command;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use player_proto::interfaces::common::{BBox3d, Pose2d, Pose3d};
use player_proto::interfaces::laser::{Laser, LaserGeometry, LaserScan};
use player_proto::interfaces::position2d::{Position2d, Position2dData, Position2dGeometry};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Reply, Server, ServerConfig};
use player_proto::wire::DevAddr;

struct Geometry(Body, &'static str);
impl Device for Geometry {
    fn driver_name(&self) -> &str {
        self.1
    }
    fn on_request(&mut self, request: &Message) -> Reply {
        // Answers the request whose reply this body is (each device's geometry request).
        if self.0.kind().map(|(_, subtype)| subtype) == Some(request.header.subtype) {
            Reply::Ack(self.0.clone())
        } else {
            Reply::Nack
        }
    }
}

/// 181 readings over 180°, a wall at x = 2 m in the sensor frame.
fn wall_scan() -> LaserScan {
    let n = 181;
    let resolution = std::f32::consts::PI / (n - 1) as f32;
    let ranges = (0..n)
        .map(|i| {
            let a = -std::f32::consts::FRAC_PI_2 + i as f32 * resolution;
            let r = 2.0 / a.cos();
            if a.cos() > 0.3 && r < 8.0 { r } else { 8.0 }
        })
        .collect();
    LaserScan {
        min_angle: -std::f32::consts::FRAC_PI_2,
        max_angle: std::f32::consts::FRAC_PI_2,
        resolution,
        max_range: 8.0,
        ranges,
        ..LaserScan::default()
    }
}

#[test]
fn a_laser_facing_a_wall_is_drawn_where_the_wall_is() {
    let mut config = ServerConfig::default();
    let robot = config.robot(0);
    let base_geom = Position2dGeometry {
        pose: Pose3d::default(),
        size: BBox3d {
            sw: 0.4,
            sl: 0.5,
            sh: 0.25,
        },
    };
    let laser_geom = LaserGeometry {
        pose: Pose3d {
            pz: 0.3,
            ..Pose3d::default()
        },
        size: BBox3d {
            sw: 0.1,
            sl: 0.1,
            sh: 0.1,
        },
    };
    config.device(
        robot,
        "position2d:0".parse().unwrap(),
        Geometry(Body::Position2d(Position2d::Geometry(base_geom)), "stage"),
    );
    config.device(
        robot,
        "laser:0".parse().unwrap(),
        Geometry(Body::Laser(Laser::Geometry(laser_geom)), "sicklms200"),
    );
    let server = Server::start(config).unwrap();
    let port = server.port(0);

    let stop = Arc::new(AtomicBool::new(false));
    let feeder = {
        let (stop, publisher) = (stop.clone(), server.publisher());
        std::thread::spawn(move || {
            let at = |s: &str| DevAddr {
                robot: u32::from(port),
                ..s.parse::<DevAddr>().unwrap()
            };
            let mut t = 0.0;
            while !stop.load(Ordering::Relaxed) {
                let odometry = Position2dData {
                    pos: Pose2d::new(0.0, 0.0, 0.0),
                    vel: Pose2d::default(),
                    stall: 0,
                };
                publisher.publish(
                    at("position2d:0"),
                    1,
                    Body::Position2d(Position2d::State(odometry)),
                    t,
                );
                publisher.publish(at("laser:0"), 1, Body::Laser(Laser::Scan(wall_scan())), t);
                t += 0.05;
                std::thread::sleep(Duration::from_millis(50));
            }
        })
    };

    let dir = tempfile::tempdir().unwrap();
    let composition = dir.path().join("live.xml");
    std::fs::write(
        &composition,
        format!(
            r#"<pv3d>
  <handlers>
    <playerClient host="127.0.0.1" port="{port}"/>
    <playerDeviceMask interface="position2d"><plugin library="libpv3d_position2d" id="r0"/></playerDeviceMask>
    <playerDeviceMask mask="laser:sicklms200:*">
      <plugin library="libpv3d_laser" id="laser"><parentNode interface="position2d" index="0"/></plugin>
    </playerDeviceMask>
  </handlers>
  <plugin library="libpv3d_lights"/>
  <plugin library="libpv3d_grid"/>
</pv3d>"#
        ),
    )
    .unwrap();
    let png = dir.path().join("live.png");
    let out = Command::new(env!("CARGO_BIN_EXE_pv3d"))
        .arg(&composition)
        .args([
            "--headless",
            "--after",
            "1.0",
            "--size",
            "900x600",
            "--screenshot",
        ])
        .arg(&png)
        .output()
        .unwrap();
    stop.store(true, Ordering::Relaxed);
    feeder.join().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let keep = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("live_server.png");
    std::fs::copy(&png, &keep).unwrap();

    let image = image::open(&png).unwrap().to_rgba8();
    let pixels_where = |test: &dyn Fn(&image::Rgba<u8>) -> bool| -> Vec<(u32, u32)> {
        image
            .enumerate_pixels()
            .filter(|(_, _, p)| test(p))
            .map(|(x, y, _)| (x, y))
            .collect()
    };
    let laser = pixels_where(&|p| p[0] > 200 && (70..=120).contains(&p[1]) && p[2] < 90);
    let body = pixels_where(&|p| p[2] > 150 && p[0] < 110 && p[1] > 90 && p[1] < 190);
    assert!(
        laser.len() > 50,
        "laser returns drawn ({} pixels); see {}",
        laser.len(),
        keep.display()
    );
    assert!(
        body.len() > 50,
        "robot body drawn ({} pixels); see {}",
        body.len(),
        keep.display()
    );
    let mean = |v: &[(u32, u32)]| {
        let n = v.len() as f64;
        (
            v.iter().map(|p| p.0 as f64).sum::<f64>() / n,
            v.iter().map(|p| p.1 as f64).sum::<f64>() / n,
        )
    };
    let (lx, ly) = mean(&laser);
    let (bx, by) = mean(&body);
    let spread_x = laser
        .iter()
        .map(|p| (p.0 as f64 - lx).abs())
        .fold(0.0, f64::max);
    let spread_y = laser
        .iter()
        .map(|p| (p.1 as f64 - ly).abs())
        .fold(0.0, f64::max);
    assert!(
        lx > bx + 20.0,
        "the wall is east of the robot: laser x {lx:.0}, robot x {bx:.0}"
    );
    assert!(
        (ly - by).abs() < 15.0,
        "and centred on it: laser y {ly:.0}, robot y {by:.0}"
    );
    assert!(
        spread_y > 4.0 * spread_x,
        "a straight wall: x spread {spread_x:.0}, y spread {spread_y:.0}"
    );
}
