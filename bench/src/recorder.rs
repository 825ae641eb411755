//! What a receiver saw inside the measurement window: how many messages it stored and the
//! latency of each, from the server's send stamp to the moment it was stored as newest data.

use crate::clock::SharedWindow;

/// Latency samples of one receiver (a robot thread, or the single polling thread).
#[derive(Debug, Clone)]
pub struct Recorder {
    window: SharedWindow,
    /// Seconds from send to store, one per stored message sent inside the window.
    latencies: Vec<f64>,
    /// Messages stored whose send time is outside the window (warm-up, drain).
    outside: u64,
}

impl Recorder {
    pub fn new(window: SharedWindow) -> Recorder {
        Recorder {
            window,
            latencies: Vec::new(),
            outside: 0,
        }
    }

    /// A message sent at `sent` (clock seconds) was stored at `stored`.
    pub fn record(&mut self, sent: f64, stored: f64) {
        if self.window.contains(sent) {
            self.latencies.push(stored - sent);
        } else {
            self.outside += 1;
        }
    }

    pub fn merge(&mut self, other: Recorder) {
        self.latencies.extend(other.latencies);
        self.outside += other.outside;
    }

    /// Messages stored that were sent inside the window.
    pub fn stored(&self) -> u64 {
        self.latencies.len() as u64
    }

    pub fn latencies(&self) -> &[f64] {
        &self.latencies
    }
}

/// p50, p99 and max of a set of latencies, in seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LatencySummary {
    pub p50: f64,
    pub p99: f64,
    pub max: f64,
}

impl LatencySummary {
    /// `None` when there are no samples (nothing arrived).
    pub fn of(samples: &[f64]) -> Option<LatencySummary> {
        if samples.is_empty() {
            return None;
        }
        let mut sorted = samples.to_vec();
        sorted.sort_by(f64::total_cmp);
        let rank =
            |q: f64| sorted[((q * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len()) - 1];
        Some(LatencySummary {
            p50: rank(0.50),
            p99: rank(0.99),
            max: sorted[sorted.len() - 1],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentiles_are_nearest_rank() {
        let samples: Vec<f64> = (1..=100).rev().map(f64::from).collect();
        let s = LatencySummary::of(&samples).unwrap();
        assert_eq!((s.p50, s.p99, s.max), (50.0, 99.0, 100.0));
        assert_eq!(LatencySummary::of(&[]), None);
    }

    #[test]
    fn only_messages_sent_inside_the_window_are_sampled() {
        let window = SharedWindow::default();
        window.set(10.0, 20.0);
        let mut r = Recorder::new(window);
        r.record(5.0, 5.1);
        r.record(10.0, 10.25);
        r.record(20.0, 20.1);
        assert_eq!(r.stored(), 1);
        assert_eq!(r.latencies(), &[0.25]);
    }
}
