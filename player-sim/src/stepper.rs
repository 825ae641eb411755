//! The thread that steps a served simulation: each step at `interval` (scaled by the speedup),
//! or in lockstep when its clients have answered, then each subscribed device's data published
//! — and, when the simulation records itself, every device's data recorded.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use player_proto::capture::Direction;
use player_proto::server::{DeviceKey, Lockstep, Publisher};
use player_proto::wire::{DevAddr, MsgType};

use crate::devices::SimDevice;
use crate::serve_options::ServeOptions;
use crate::served::Source;
use crate::sim::Simulation;
use crate::sim_record::PortRecord;

/// A served device as the step loop publishes it.
pub(crate) struct Published {
    pub key: DeviceKey,
    pub source: Source,
    /// Its port's recording and its address there.
    pub record: Option<(PortRecord, DevAddr)>,
}

pub(crate) fn step_loop(
    sim: &Mutex<Simulation>,
    devices: &[Published],
    publisher: &Publisher,
    options: &ServeOptions,
    lockstep: Option<&Lockstep>,
    stop: &AtomicBool,
) {
    let interval = sim.lock().expect("simulation").world.interval;
    let period = if options.speedup > 0.0 {
        Some(Duration::from_secs_f64(interval / options.speedup))
    } else {
        None
    };
    let mut started = Instant::now();
    let mut steps = 0u64;
    while !stop.load(Ordering::Relaxed) && options.max_steps.is_none_or(|max| steps < max) {
        if let Some(lockstep) = lockstep {
            let waited = Instant::now();
            if lockstep.next_step(stop).is_none() {
                break;
            }
            // Time spent waiting for the clients does not count against the pace.
            started += waited.elapsed();
        }
        let outgoing = step_once(sim, devices, publisher, options, lockstep.is_some());
        publisher.publish_to_all(outgoing);
        if let Some(lockstep) = lockstep {
            lockstep.stepped();
        }
        steps += 1;
        if let Some(period) = period {
            let due = started + period.mul_f64(steps as f64);
            if let Some(wait) = due.checked_duration_since(Instant::now()) {
                std::thread::sleep(wait);
            }
        }
    }
}

type Outgoing = Vec<(DeviceKey, u8, player_proto::message::Body, f64)>;

/// One step: the world advanced, its data made for whoever subscribed (and recorded).
fn step_once(
    sim: &Mutex<Simulation>,
    devices: &[Published],
    publisher: &Publisher,
    options: &ServeOptions,
    lockstep: bool,
) -> Outgoing {
    let mut sim = sim.lock().expect("simulation");
    sim.step();
    if let Some(observer) = &options.observer {
        (observer.0)(&sim);
    }
    let id = u32::try_from(sim.steps).unwrap_or(u32::MAX);
    // The step's scans in one sensing scope: the robots' index is checked once.
    sim.sensing(|sim| {
        let mut outgoing = Vec::new();
        for device in devices {
            let watched = publisher.subscribers_of(device.key) > 0;
            if !watched && device.record.is_none() {
                continue;
            }
            // A lockstep run is stamped with simulated time only: it must not depend on when.
            let time = if device.source.stamped_by_wall_clock() && !lockstep {
                wall_clock()
            } else {
                sim.time
            };
            for (subtype, body) in SimDevice::data(sim, &device.source, id) {
                if let Some((record, addr)) = &device.record {
                    record.message(
                        sim.time,
                        Direction::ServerToClient,
                        *addr,
                        MsgType::Data,
                        subtype,
                        &body,
                    );
                }
                if watched {
                    outgoing.push((device.key, subtype, body, time));
                }
            }
        }
        outgoing
    })
}

/// Seconds since the Unix epoch, as Player's server clock reads.
fn wall_clock() -> f64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0.0, |d| d.as_secs_f64())
}
