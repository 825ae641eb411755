//! `/clock` when the relay simulates: ROS 2 nodes with `use_sim_time` follow the simulation's
//! time, not the wall's. The simulation tells a [`SimClock`] its time after each step; a
//! thread publishes it on `/clock` (`rosgraph_msgs/msg/Clock`) as it changes; and every
//! message the front publishes is stamped no later than it, so stamps and `/clock` agree.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use ros2_client::qos::{Durability, History, Reliability, WhenFull};
use ros2_client::{Context, QosProfile};

use super::LiveError;
use super::node::spun_node;
use super::publishers::Outs;
use crate::msgs::{Clock, Time};

/// How often the clock thread looks whether the simulation stepped (Stage steps every 100 ms
/// of simulated time; a 20x simulation every 5 ms of the wall's).
const LOOK: Duration = Duration::from_millis(2);

/// Reliable (a `ros2 topic echo` asks for it; rclcpp's clock subscription, best effort, takes
/// it too), the newest only: a late tick is worth nothing.
const CLOCK: QosProfile = QosProfile::publisher_default()
    .reliability(Reliability::Reliable {
        when_full: WhenFull::Wait(Duration::from_millis(5)),
    })
    .durability(Durability::Volatile)
    .history(History::KeepLast { depth: 1 });

/// The simulated time, seconds since the simulation began: written by the simulation after
/// each step, read by whoever stamps. Cheap to clone and to read (no lock).
#[derive(Debug, Clone)]
pub struct SimClock(Arc<AtomicU64>);

impl Default for SimClock {
    fn default() -> Self {
        SimClock(Arc::new(AtomicU64::new(f64::NAN.to_bits())))
    }
}

impl SimClock {
    pub fn new() -> SimClock {
        SimClock::default()
    }

    /// The simulation has reached `seconds`.
    pub fn set(&self, seconds: f64) {
        self.0.store(seconds.to_bits(), Ordering::Release);
    }

    /// The simulated time, once the simulation has stepped.
    pub fn now(&self) -> Option<f64> {
        let seconds = f64::from_bits(self.0.load(Ordering::Acquire));
        seconds.is_finite().then_some(seconds)
    }

    /// A message's Player timestamp as the stamp it gets beside this clock: its own when it
    /// is simulated time (a sensor's, stamped by the step that made it), the simulated time
    /// now when it is later than that (a driver stamping with the server's wall clock, as
    /// Player's amcl and planners do).
    pub fn stamp(&self, player_time: f64) -> f64 {
        match self.now() {
            Some(now) if player_time > now || player_time.is_nan() => now,
            _ => player_time,
        }
    }
}

/// The thread publishing `/clock` from its own node, `/player_relay`.
pub struct ClockThread {
    stopping: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl ClockThread {
    pub fn start(context: &Context, clock: SimClock) -> Result<ClockThread, LiveError> {
        let mut node = spun_node(context, "/", "player_relay", "the simulation's clock")?;
        let stopping = Arc::new(AtomicBool::new(false));
        let stop = stopping.clone();
        let thread = std::thread::Builder::new()
            .name("ros2 /clock".into())
            .spawn(move || {
                let mut out = Outs::<Clock>::default();
                let mut said = None;
                while !stop.load(Ordering::Relaxed) {
                    std::thread::sleep(LOOK);
                    let Some(now) = clock.now() else { continue };
                    if said == Some(now) {
                        continue;
                    }
                    said = Some(now);
                    let tick = Clock {
                        clock: Time::from_seconds(now),
                    };
                    if let Err(e) = out.publish(&mut node, "/clock", CLOCK, tick, "/clock") {
                        tracing::warn!("{e}");
                        return;
                    }
                }
            })
            .map_err(|e| LiveError::Create {
                robot: "the simulation".into(),
                what: "the /clock thread".into(),
                message: e.to_string(),
            })?;
        Ok(ClockThread {
            stopping,
            thread: Some(thread),
        })
    }
}

impl Drop for ClockThread {
    fn drop(&mut self) {
        self.stopping.store(true, Ordering::Relaxed);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stamps_are_never_ahead_of_the_simulated_clock() {
        let clock = SimClock::new();
        assert_eq!(clock.now(), None);
        assert_eq!(
            clock.stamp(1.7e9),
            1.7e9,
            "no simulation yet: as Player said"
        );
        clock.set(12.5);
        assert_eq!(clock.stamp(12.4), 12.4, "a sensor's step");
        assert_eq!(clock.stamp(12.5), 12.5);
        assert_eq!(clock.stamp(1.7e9), 12.5, "a wall-clock stamp");
        assert_eq!(clock.stamp(f64::NAN), 12.5);
    }
}
