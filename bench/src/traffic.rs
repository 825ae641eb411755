//! The server side: N robots on N ports of one `player_proto::server`, each with a
//! `position2d:0` and a `laser:0`, and one generator thread publishing both at a fixed rate.
//!
//! A mock server rather than player-sim: player-sim's ray casting for 256 robots would load
//! the two cores this runs on with simulation work that has nothing to do with the clients,
//! and its publish times follow the simulation loop. Here every message's header timestamp is
//! the send time on the shared [`BenchClock`], taken immediately before it is queued.
//! Robots are staggered evenly across the period (independent robots, independent clocks), so
//! the load is steady rather than one burst per tick.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::kind::MessageKind;
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Reply, Server, ServerConfig};
use player_proto::wire::{DevAddr, Interface, Opaque};

use crate::BenchError;
use crate::clock::{BenchClock, SharedWindow};

/// What each of a robot's two devices publishes: position2d state and a laser scan.
pub const PUBLISHED: [MessageKind; 2] = [Position2d::DATA_STATE.kind(), Laser::DATA_SCAN.kind()];

/// The two devices every robot has.
pub const DEVICES: [Interface; 2] = [PUBLISHED[0].interf, PUBLISHED[1].interf];

/// What each robot publishes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrafficConfig {
    pub robots: usize,
    pub beams: usize,
    /// Messages per second per device.
    pub rate_hz: f64,
}

/// A device that only publishes; every request is NACKed, as an unhandled one is in Player.
struct Publishing(&'static str);

impl Device for Publishing {
    fn driver_name(&self) -> &str {
        self.0
    }

    fn on_request(&mut self, _request: &Message) -> Reply {
        Reply::Nack
    }
}

/// A running server and its generator; both stop when dropped.
pub struct Traffic {
    server: Server,
    stop: Arc<AtomicBool>,
    published: Arc<AtomicU64>,
    generator: Option<JoinHandle<()>>,
}

impl Traffic {
    /// Binds N free ports and starts publishing at once (nobody is subscribed yet, so nothing
    /// is queued until a client subscribes).
    pub fn start(
        config: TrafficConfig,
        clock: BenchClock,
        window: SharedWindow,
    ) -> Result<Traffic, BenchError> {
        if config.robots == 0
            || config.beams == 0
            || !config.rate_hz.is_finite()
            || config.rate_hz <= 0.0
        {
            return Err(BenchError::Config(format!(
                "robots, beams and rate must be positive, got {config:?}"
            )));
        }
        let mut server_config = ServerConfig::default();
        for _ in 0..config.robots {
            let robot = server_config.robot(0);
            server_config.device(
                robot,
                DevAddr::local(Interface::POSITION2D, 0),
                Publishing("stage"),
            );
            server_config.device(
                robot,
                DevAddr::local(Interface::LASER, 0),
                Publishing("stage"),
            );
        }
        let server = Server::start(server_config).map_err(|e| BenchError::Server(e.to_string()))?;
        let stop = Arc::new(AtomicBool::new(false));
        let published = Arc::new(AtomicU64::new(0));
        let generator = {
            let ports = server.ports().to_vec();
            let publisher = server.publisher();
            let (stop, published) = (stop.clone(), published.clone());
            std::thread::Builder::new()
                .name("bench-traffic".into())
                .spawn(move || {
                    let bodies = bodies(config.beams);
                    let period = 1.0 / config.rate_hz;
                    let slot = period / ports.len() as f64;
                    let start = clock.now();
                    let mut event: u64 = 0;
                    while !stop.load(Ordering::Relaxed) {
                        let due = start + event as f64 * slot;
                        let now = clock.now();
                        if due > now {
                            std::thread::sleep(Duration::from_secs_f64((due - now).min(0.05)));
                            continue;
                        }
                        let port = ports[(event % ports.len() as u64) as usize];
                        for (kind, body) in PUBLISHED.iter().zip(&bodies) {
                            let addr = DevAddr {
                                host: 0,
                                robot: u32::from(port),
                                interf: kind.interf,
                                index: 0,
                            };
                            let sent = clock.now();
                            if publisher.publish(addr, kind.subtype, body.clone(), sent) > 0
                                && window.contains(sent)
                            {
                                published.fetch_add(1, Ordering::Relaxed);
                            }
                        }
                        event += 1;
                    }
                })
                .map_err(|e| BenchError::Thread(e.to_string()))?
        };
        Ok(Traffic {
            server,
            stop,
            published,
            generator: Some(generator),
        })
    }

    pub fn ports(&self) -> &[u16] {
        self.server.ports()
    }

    /// Messages published to a subscriber with a send time inside the window since the last
    /// call; resets the count.
    pub fn take_published(&self) -> u64 {
        self.published.swap(0, Ordering::SeqCst)
    }
}

impl Drop for Traffic {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        if let Some(generator) = self.generator.take() {
            let _ = generator.join();
        }
        self.server.shutdown();
    }
}

/// Position2d state and a laser scan of `beams` readings over 270°, in [`DEVICES`] order.
pub fn bodies(beams: usize) -> [Body; 2] {
    let fov = 270f32.to_radians();
    let scan = LaserScan {
        min_angle: -fov / 2.0,
        max_angle: fov / 2.0,
        resolution: fov / (beams.max(2) - 1) as f32,
        max_range: 30.0,
        ranges: (0..beams).map(|i| 1.0 + (i % 97) as f32 * 0.05).collect(),
        intensity: Opaque::from(vec![0u8; beams]),
        id: 0,
    };
    let state = Position2dData {
        pos: Pose2d {
            px: 1.0,
            py: 2.0,
            pa: 0.5,
        },
        vel: Pose2d {
            px: 0.3,
            py: 0.0,
            pa: 0.1,
        },
        stall: 0,
    };
    [
        Body::Position2d(Position2d::State(state)),
        Body::Laser(Laser::Scan(scan)),
    ]
}
