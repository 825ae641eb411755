//! Waiting without holding the GIL and without deafness to Ctrl-C.
//!
//! The robot thread calls the [`Wakeup`] whenever data arrived or the connection changed; a
//! Python caller waits on it in short slices with the GIL released, and between slices asks
//! Python whether a signal (Ctrl-C) is pending, so a blocking read is always interruptible and
//! other Python threads run meanwhile.

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

use pyo3::exceptions::{PyTimeoutError, PyValueError};
use pyo3::prelude::*;

/// How long one slice of a wait lasts at most: the latency of Ctrl-C.
const SLICE: Duration = Duration::from_millis(50);

/// A generation counter bumped by the robot thread, with a condition variable to sleep on.
/// The counter is atomic and the lock is only taken when someone sleeps, so a stream of
/// hundreds of thousands of messages a second does not make the robot thread and a reader
/// fight over a mutex.
#[derive(Default)]
pub struct Wakeup {
    generation: AtomicU64,
    sleepers: AtomicUsize,
    lock: Mutex<()>,
    changed: Condvar,
}

impl Wakeup {
    pub fn notifier(self: &Arc<Self>) -> player_proto::client::Notifier {
        let me = self.clone();
        Arc::new(move || me.bump())
    }

    fn bump(&self) {
        self.generation.fetch_add(1, Ordering::SeqCst);
        // A sleeper counted itself before checking the counter under the lock: either it saw
        // this bump, or it is counted here and gets the notification.
        if self.sleepers.load(Ordering::SeqCst) > 0 {
            let _guard = self.lock.lock().unwrap_or_else(|e| e.into_inner());
            self.changed.notify_all();
        }
    }

    pub fn generation(&self) -> u64 {
        self.generation.load(Ordering::SeqCst)
    }

    /// Sleeps until the generation moves past `seen`, or `limit` passes. (Spinning first, to
    /// save the wake-up, was tried: on two busy cores it starved the robot thread and read
    /// less, not more.)
    fn wait_past(&self, seen: u64, limit: Duration) {
        self.sleepers.fetch_add(1, Ordering::SeqCst);
        let guard = self.lock.lock().unwrap_or_else(|e| e.into_inner());
        let _ = self
            .changed
            .wait_timeout_while(guard, limit, |_| self.generation() == seen);
        self.sleepers.fetch_sub(1, Ordering::SeqCst);
    }
}

/// A timeout argument in seconds, checked: negative or NaN is a `ValueError` naming `what`.
/// Infinity waits for ever (in interruptible slices).
pub fn timeout_arg(seconds: f64, what: &str) -> PyResult<Duration> {
    if seconds.is_nan() || seconds < 0.0 {
        return Err(PyValueError::new_err(format!(
            "{what}: timeout must be 0 or more seconds, got {seconds}"
        )));
    }
    Ok(Duration::try_from_secs_f64(seconds).unwrap_or(Duration::MAX))
}

/// Polls `ready` until it yields, sleeping on `wakeup` with the GIL released in between.
/// `check` runs before each sleep and may end the wait with an error (a lost connection).
/// A timeout of zero looks once. The error on timeout says `what` was awaited.
pub fn wait_for<T>(
    py: Python<'_>,
    wakeup: &Wakeup,
    timeout: Duration,
    what: &str,
    mut ready: impl FnMut() -> Option<T>,
    mut check: impl FnMut() -> PyResult<()>,
) -> PyResult<T> {
    let deadline = Instant::now().checked_add(timeout);
    loop {
        let seen = wakeup.generation();
        if let Some(value) = ready() {
            return Ok(value);
        }
        check()?;
        let left = match deadline {
            Some(deadline) => deadline.saturating_duration_since(Instant::now()),
            None => SLICE,
        };
        if left.is_zero() {
            return Err(PyTimeoutError::new_err(format!(
                "{what}: nothing within {:.3} s",
                timeout.as_secs_f64()
            )));
        }
        py.detach(|| wakeup.wait_past(seen, left.min(SLICE)));
        py.check_signals()?;
    }
}
