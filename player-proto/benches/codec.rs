//! Decode and encode throughput of the messages a viewer receives most, with a plain copy of
//! the same bytes as the baseline (the memory-bandwidth ceiling on this machine). Each line
//! reports messages/s and bytes/s. The 181-beam laser and 181-range ranger cases are the ones
//! libplayerc's figures exist for (see BENCHMARKS.md).
//!
//! For laser scans two more lines: the scan read in place (`view`), and read in place with
//! every range converted into a kept buffer (`view + ranges`).
//!
//! `cargo bench -p player-proto --bench codec -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use bytes::{Bytes, BytesMut};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use player_proto::interfaces::camera::{Camera, CameraData, FORMAT_RGB888};
use player_proto::interfaces::common::{Pose2d, Pose3d};
use player_proto::interfaces::fiducial::{Fiducial, FiducialData, FiducialItem};
use player_proto::interfaces::laser::{Laser, LaserScan, LaserScanView};
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::interfaces::ranger::{Ranger, RangerRanges};
use player_proto::interfaces::sonar::{Sonar, SonarData};
use player_proto::message::{Body, Message};
use player_proto::wire::{DevAddr, Header, Interface, MsgType, Opaque};

fn laser(beams: usize) -> Message {
    let scan = LaserScan {
        min_angle: -2.35,
        max_angle: 2.35,
        resolution: 4.7 / beams as f32,
        max_range: 30.0,
        ranges: (0..beams).map(|i| 1.0 + (i % 97) as f32 * 0.1).collect(),
        intensity: Opaque::from((0..beams).map(|i| (i % 251) as u8).collect::<Vec<_>>()),
        id: 7,
    };
    data(Interface::LASER, Laser::Scan(scan))
}

fn data(interf: Interface, body: impl Into<Body>) -> Message {
    Message::typed(
        DevAddr {
            host: 0x0100_007f,
            robot: 6665,
            interf,
            index: 0,
        },
        MsgType::Data,
        body,
    )
}

fn cases() -> Vec<(&'static str, Message)> {
    let sonar = SonarData {
        ranges: (0..16).map(|i| 0.5 + i as f32 * 0.2).collect(),
    };
    let odometry = Position2dData {
        pos: Pose2d::new(1.5, -2.0, 0.3),
        vel: Pose2d::new(0.4, 0.0, 0.1),
        stall: 0,
    };
    let marker = |i: i32| FiducialItem {
        id: i,
        pose: Pose3d {
            px: i as f64,
            py: 1.0,
            pyaw: 0.5,
            ..Pose3d::default()
        },
        upose: Pose3d::default(),
    };
    let fiducials = FiducialData {
        fiducials: (0..10).map(marker).collect(),
    };
    let frame = CameraData {
        width: 640,
        height: 480,
        bpp: 24,
        format: FORMAT_RGB888,
        fdiv: 1,
        compression: 0,
        image: Opaque::from(vec![0x5a; 640 * 480 * 3]),
    };
    let ranger = RangerRanges {
        ranges: (0..181).map(|i| 0.5 + (i % 80) as f64 * 0.1).collect(),
    };
    vec![
        ("laser 181", laser(181)),
        ("laser 361", laser(361)),
        ("laser 1081", laser(1081)),
        (
            "ranger 181",
            data(Interface::RANGER, Ranger::Ranges(ranger)),
        ),
        ("sonar 16", data(Interface::SONAR, Sonar::Ranges(sonar))),
        (
            "position2d",
            data(Interface::POSITION2D, Position2d::State(odometry)),
        ),
        (
            "fiducial 10",
            data(Interface::FIDUCIAL, Fiducial::Scan(fiducials)),
        ),
        (
            "camera 640x480 rgb",
            data(Interface::CAMERA, Camera::State(frame)),
        ),
    ]
}

/// One message per iteration, of `bytes` bytes: criterion prints messages/s and bytes/s.
fn per_message(bytes: usize) -> Throughput {
    Throughput::ElementsAndBytes {
        elements: 1,
        bytes: bytes as u64,
    }
}

fn decode(c: &mut Criterion) {
    let mut group = c.benchmark_group("decode");
    for (name, message) in cases() {
        let wire = message.to_bytes();
        let header = message.header;
        let body = wire.slice(40..);
        group.throughput(per_message(wire.len()));
        group.bench_with_input(BenchmarkId::new("message", name), &body, |b, body| {
            b.iter(|| Message::decode(black_box(header), black_box(body.clone())).unwrap())
        });
        // The ceiling: copying the same bytes once.
        group.bench_with_input(
            BenchmarkId::new("memcpy baseline", name),
            &wire,
            |b, wire: &Bytes| b.iter(|| black_box(wire.to_vec())),
        );
        // The floor under `message`: the body handle's clone and drop alone, which the frame
        // decoder pays for every message it splits off the receive buffer (two atomic
        // reference-count operations), before any byte is decoded.
        group.bench_with_input(BenchmarkId::new("body handle", name), &body, |b, body| {
            b.iter(|| black_box(black_box(body).clone()))
        });
        if name.starts_with("laser") {
            view_scan(&mut group, name, &header, &body);
        }
    }
    group.finish();
}

/// A laser scan read in place (`Laser::DATA_SCAN.view`), for code that looks and lets go: the
/// whole body checked, no handle, no allocation; then the same with every range converted
/// into a buffer the reader keeps (what a converter or a drawer does with a scan).
fn view_scan(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    header: &Header,
    body: &Bytes,
) {
    fn view<'a>(header: &Header, body: &'a [u8]) -> LaserScanView<'a> {
        match Laser::DATA_SCAN.view(header, body) {
            Some(Ok(scan)) => scan,
            _ => unreachable!("a laser scan"),
        }
    }
    group.bench_with_input(BenchmarkId::new("view", name), body, |b, body| {
        b.iter(|| black_box(view(header, black_box(body))))
    });
    let mut ranges: Vec<f32> = Vec::new();
    group.bench_with_input(BenchmarkId::new("view + ranges", name), body, |b, body| {
        b.iter(|| {
            let scan = view(header, black_box(body));
            ranges.clear();
            scan.ranges.extend_into(&mut ranges);
            black_box(&mut ranges);
            black_box(scan.intensity)
        })
    });
}

fn encode(c: &mut Criterion) {
    let mut group = c.benchmark_group("encode");
    for (name, message) in cases() {
        group.throughput(per_message(message.encoded_len()));
        let mut out = BytesMut::with_capacity(message.encoded_len());
        group.bench_with_input(BenchmarkId::new("message", name), &message, |b, m| {
            b.iter(|| {
                out.clear();
                black_box(m).encode(&mut out);
                black_box(out.len())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, decode, encode);
criterion_main!(benches);
