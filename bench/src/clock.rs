//! One monotonic clock for the server's send stamps and the clients' receive stamps.
//!
//! Server and clients run in one process, so the message header's timestamp can carry the
//! send time in seconds since a shared `Instant` epoch: no wall-clock steps, no clock offset
//! between machines, sub-microsecond resolution in an `f64`.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

/// Seconds since the benchmark's epoch.
#[derive(Debug, Clone, Copy)]
pub struct BenchClock {
    epoch: Instant,
}

impl Default for BenchClock {
    fn default() -> Self {
        BenchClock {
            epoch: Instant::now(),
        }
    }
}

impl BenchClock {
    pub fn now(&self) -> f64 {
        self.at(Instant::now())
    }

    /// An `Instant` (such as a client's receive stamp) on this clock.
    pub fn at(&self, instant: Instant) -> f64 {
        instant.saturating_duration_since(self.epoch).as_secs_f64()
    }
}

/// Seconds since the Unix epoch: the clock processes on one machine share, for a benchmark
/// whose sender and receivers are different processes (f64 keeps it to about half a
/// microsecond).
pub fn unix_seconds() -> f64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0.0, |d| d.as_secs_f64())
}

/// The measurement window `[start, end)` in clock seconds, shared by the traffic generator
/// (which counts what it publishes inside it) and the receivers (which count what they store
/// of it). Empty until set, so warm-up and drain traffic is never counted.
#[derive(Debug, Clone)]
pub struct SharedWindow {
    bounds: Arc<[AtomicU64; 2]>,
}

impl Default for SharedWindow {
    fn default() -> Self {
        let window = SharedWindow {
            bounds: Arc::new([AtomicU64::new(0), AtomicU64::new(0)]),
        };
        window.clear();
        window
    }
}

impl SharedWindow {
    pub fn set(&self, start: f64, end: f64) {
        // End first, then start: a reader never sees a new start with an old, earlier end
        // that would make it count nothing, nor a wider window than asked.
        self.bounds[1].store(end.to_bits(), Ordering::SeqCst);
        self.bounds[0].store(start.to_bits(), Ordering::SeqCst);
    }

    pub fn clear(&self) {
        self.bounds[0].store(f64::INFINITY.to_bits(), Ordering::SeqCst);
        self.bounds[1].store(f64::NEG_INFINITY.to_bits(), Ordering::SeqCst);
    }

    pub fn contains(&self, t: f64) -> bool {
        let start = f64::from_bits(self.bounds[0].load(Ordering::Relaxed));
        let end = f64::from_bits(self.bounds[1].load(Ordering::Relaxed));
        t >= start && t < end
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_empty_window_contains_nothing_and_a_set_one_is_half_open() {
        let w = SharedWindow::default();
        assert!(!w.contains(0.0));
        w.set(1.0, 2.0);
        assert!(w.contains(1.0));
        assert!(w.contains(1.5));
        assert!(!w.contains(2.0));
        w.clear();
        assert!(!w.contains(1.5));
    }
}
