//! Every interface's data path and request path through the typed proxies, client to server.

use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::camera::{Camera, CameraData, FORMAT_RGB888};
use player_proto::interfaces::common::{BBox2d, BBox3d, Pose2d, Pose3d};
use player_proto::interfaces::fiducial::{Fiducial, FiducialData, FiducialGeometry, FiducialItem};
use player_proto::interfaces::position2d::{Position2d, Position2dData, Position2dGeometry};
use player_proto::interfaces::ranger::{Ranger, RangerConfig, RangerGeometry, RangerRanges};
use player_proto::interfaces::sonar::{Sonar, SonarData, SonarGeometry};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Reply, Server, ServerConfig};
use player_proto::wire::{DevAddr, Opaque};

/// A device that answers its geometry (and config) requests with fixed bodies.
struct Answering {
    replies: Vec<(u8, Body)>,
}

impl Device for Answering {
    fn driver_name(&self) -> &str {
        "stage"
    }
    fn on_request(&mut self, request: &Message) -> Reply {
        self.replies
            .iter()
            .find(|(s, _)| *s == request.header.subtype)
            .map_or(Reply::Nack, |(_, b)| Reply::Ack(b.clone()))
    }
}

fn device(replies: Vec<(u8, Body)>) -> Answering {
    Answering { replies }
}

fn wait_for<T>(what: &str, mut get: impl FnMut() -> Option<T>) -> T {
    let deadline = Instant::now() + Duration::from_secs(3);
    loop {
        if let Some(v) = get() {
            return v;
        }
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn sonar_ranger_fiducial_camera_and_position2d_end_to_end() {
    let sonar_geom = SonarGeometry {
        poses: vec![
            Pose3d {
                px: 0.1,
                pyaw: 1.0,
                ..Pose3d::default()
            };
            16
        ],
    };
    let ranger_geom = RangerGeometry {
        element_poses: vec![Pose3d::default()],
        element_sizes: vec![BBox3d::default()],
        ..RangerGeometry::default()
    };
    let ranger_config = RangerConfig {
        min_angle: -1.5,
        max_angle: 1.5,
        angular_res: 0.01,
        max_range: 8.0,
        frequency: 10.0,
        ..RangerConfig::default()
    };
    let fiducial_geom = FiducialGeometry {
        fiducial_size: BBox2d { sw: 0.4, sl: 0.4 },
        ..FiducialGeometry::default()
    };
    let base_geom = Position2dGeometry {
        size: BBox3d {
            sw: 0.38,
            sl: 0.44,
            sh: 0.22,
        },
        ..Position2dGeometry::default()
    };

    let mut config = ServerConfig::default();
    let r = config.robot(0);
    config.device(
        r,
        "sonar:0".parse().unwrap(),
        device(vec![(1, Body::Sonar(Sonar::Geometry(sonar_geom.clone())))]),
    );
    config.device(
        r,
        "ranger:0".parse().unwrap(),
        device(vec![
            (1, Body::Ranger(Ranger::Geometry(ranger_geom.clone()))),
            (5, Body::Ranger(Ranger::Config(ranger_config))),
        ]),
    );
    config.device(
        r,
        "fiducial:0".parse().unwrap(),
        device(vec![(1, Body::Fiducial(Fiducial::Geometry(fiducial_geom)))]),
    );
    config.device(r, "camera:0".parse().unwrap(), device(vec![]));
    config.device(
        r,
        "position2d:0".parse().unwrap(),
        device(vec![(1, Body::Position2d(Position2d::Geometry(base_geom)))]),
    );
    let server = Server::start(config).unwrap();
    let port = server.port(0);
    let at = |text: &str| DevAddr {
        robot: u32::from(port),
        ..text.parse::<DevAddr>().unwrap()
    };

    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    assert_eq!(client.devices().len(), 5);

    // Requests.
    assert_eq!(client.sonar(0).geometry().unwrap(), sonar_geom);
    assert_eq!(client.ranger(0).geometry().unwrap(), ranger_geom);
    assert_eq!(client.ranger(0).config().unwrap(), ranger_config);
    assert_eq!(client.fiducial(0).geometry().unwrap().fiducial_size.sw, 0.4);
    assert_eq!(client.position2d(0).geometry().unwrap().size.sl, 0.44);
    assert!(
        client.camera(0).request_image().is_err(),
        "this camera does not serve single frames"
    );

    // Data.
    for proxy_addr in [
        "sonar:0",
        "ranger:0",
        "fiducial:0",
        "camera:0",
        "position2d:0",
    ] {
        client.subscribe(at(proxy_addr)).unwrap();
    }
    let p = server.publisher();
    p.publish(
        at("sonar:0"),
        1,
        Body::Sonar(Sonar::Ranges(SonarData {
            ranges: vec![0.7; 16],
        })),
        1.0,
    );
    p.publish(
        at("ranger:0"),
        1,
        Body::Ranger(Ranger::Ranges(RangerRanges {
            ranges: vec![2.5; 301],
        })),
        1.0,
    );
    let marker = FiducialItem {
        id: 7,
        pose: Pose3d {
            px: 1.0,
            py: 1.0,
            ..Pose3d::default()
        },
        upose: Pose3d::default(),
    };
    p.publish(
        at("fiducial:0"),
        1,
        Body::Fiducial(Fiducial::Scan(FiducialData {
            fiducials: vec![marker],
        })),
        1.0,
    );
    let frame = CameraData {
        width: 4,
        height: 2,
        bpp: 24,
        format: FORMAT_RGB888,
        fdiv: 1,
        compression: 0,
        image: Opaque::from(vec![200; 24]),
    };
    p.publish(at("camera:0"), 1, Body::Camera(Camera::State(frame)), 1.0);
    let odometry = Position2dData {
        pos: Pose2d::new(1.0, 2.0, 0.5),
        vel: Pose2d::new(0.3, 0.0, 0.1),
        stall: 0,
    };
    p.publish(
        at("position2d:0"),
        1,
        Body::Position2d(Position2d::State(odometry)),
        1.0,
    );

    assert_eq!(
        wait_for("sonar", || client.sonar(0).ranges())
            .0
            .ranges
            .len(),
        16
    );
    assert_eq!(
        wait_for("ranger", || client.ranger(0).ranges())
            .0
            .ranges
            .len(),
        301
    );
    let markers = wait_for("fiducials", || client.fiducial(0).markers()).0;
    assert_eq!(markers.fiducials[0].id, 7);
    assert!((markers.fiducials[0].bearing() - std::f64::consts::FRAC_PI_4).abs() < 1e-9);
    let image = wait_for("camera", || client.camera(0).frame())
        .0
        .to_rgba()
        .unwrap();
    assert_eq!(
        (image.width(), image.height(), image.get_pixel(3, 1).0),
        (4, 2, [200, 200, 200, 255])
    );
    assert_eq!(
        wait_for("odometry", || client.position2d(0).state()).0,
        odometry
    );
}
