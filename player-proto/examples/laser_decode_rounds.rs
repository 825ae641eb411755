//! Laser decode against `to_vec` of the same wire bytes, interleaved in short rounds.
//!
//! The codec bench (`benches/codec.rs`) measures the two one after the other, seconds apart;
//! on a shared, loaded machine the load changes in between, and a ratio of two such medians
//! moves by ±30 %. Here each round times 4 000 decodes and then 4 000 copies back to back,
//! a few hundred rounds in a row, and the minimum and median over the rounds are printed: the
//! minimum is what each costs when nothing else got in the way. Same message, same decode call
//! (`Message::decode` of a fresh handle on the body, then `unwrap`) and same baseline as the
//! bench. See BENCHMARKS.md, "Laser decode against a copy of its bytes (#23)".
//!
//! `cargo run --release -p player-proto --example laser_decode_rounds -- [rounds]`

use std::hint::black_box;
use std::time::Instant;

use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::message::Message;
use player_proto::wire::{DevAddr, Interface, MsgType, Opaque};

/// The bench's scan of `beams` beams, as a DATA message.
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
    let addr = DevAddr {
        host: 0x0100_007f,
        robot: 6665,
        interf: Interface::LASER,
        index: 0,
    };
    Message::typed(addr, MsgType::Data, Laser::Scan(scan))
}

/// Nanoseconds per call of `f`, over `n` calls.
fn per_call(n: u32, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..n {
        f();
    }
    start.elapsed().as_nanos() as f64 / f64::from(n)
}

/// Minimum and median.
fn spread(mut v: Vec<f64>) -> (f64, f64) {
    v.sort_by(f64::total_cmp);
    (v[0], v[v.len() / 2])
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse().expect("rounds: a number"))
        .unwrap_or(300);
    let n = 4_000;
    for beams in [181, 361, 1081] {
        let message = laser(beams);
        let wire = message.to_bytes();
        let header = message.header;
        let body = wire.slice(40..);
        assert_eq!(Message::decode(header, body.clone()).unwrap(), message);
        let (mut decode, mut copy, mut handle) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..rounds {
            decode.push(per_call(n, || {
                black_box(Message::decode(black_box(header), black_box(body.clone())).unwrap());
            }));
            copy.push(per_call(n, || {
                black_box(black_box(&wire).to_vec());
            }));
            // The part of a decode that is the body handle alone: its clone and drop.
            handle.push(per_call(n, || {
                black_box(black_box(&body).clone());
            }));
        }
        let ((d_min, d_med), (c_min, c_med)) = (spread(decode), spread(copy));
        let (h_min, _) = spread(handle);
        println!(
            "laser {beams:4}: decode min {d_min:6.1} ns, median {d_med:6.1}; to_vec min \
             {c_min:6.1} ns, median {c_med:6.1}; decode / to_vec: min {:.2}x, median {:.2}x; \
             the body handle alone (clone + drop) min {h_min:5.1} ns, {:.2}x to_vec",
            d_min / c_min,
            d_med / c_med,
            h_min / c_min
        );
    }
}
