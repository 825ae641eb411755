//! The replay's clock: where in the recording playback is, and how it moves — playing at a
//! speed, paused, stepped, seeked. Control requests (the `log` device) change it from server
//! threads; the playback thread waits on it for the next message to fall due.

use std::sync::{Condvar, Mutex};
use std::time::{Duration, Instant};

use player_proto::interfaces::log::LogPlayback;

const NS_PER_S: f64 = 1e9;

/// Why the playback thread woke.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Wake {
    /// The message waited for is due.
    Due,
    /// Playback was moved to `to` (ns from the start): read from there; `seeks` is the
    /// count of seeks to wait with from now on.
    Seek {
        to: u64,
        seeks: u64,
    },
    /// Something else changed (play, pause, speed), or the wait's limit passed.
    Changed,
    Stop,
}

#[derive(Debug)]
struct State {
    playing: bool,
    speed: f64,
    /// Position (ns from the recording's first message) at `anchor`.
    position_at_anchor: u64,
    anchor: Instant,
    /// Bumped by every seek; the playback thread compares it with the one it read from.
    seeks: u64,
    /// Bumped by every change, seeks included.
    changes: u64,
    /// A step to the next message is asked for.
    step_to_next: bool,
    stopped: bool,
}

impl State {
    fn position(&self, duration: u64) -> u64 {
        if !self.playing {
            return self.position_at_anchor;
        }
        let ran = self.anchor.elapsed().as_secs_f64() * self.speed * NS_PER_S;
        self.position_at_anchor
            .saturating_add(ran as u64)
            .min(duration)
    }

    /// Makes the current position the anchor, before the speed or state changes.
    fn re_anchor(&mut self, duration: u64) {
        self.position_at_anchor = self.position(duration);
        self.anchor = Instant::now();
    }
}

/// Shared between the control device and the playback thread.
#[derive(Debug)]
pub struct Clock {
    state: Mutex<State>,
    changed: Condvar,
    /// ns from the first message to the last.
    duration: u64,
}

impl Clock {
    /// The count of seeks a clock starts with: the playback thread waits from it, not from the
    /// count when the thread first looks, since the servers answer seeks from their start.
    pub const SEEKS_AT_START: u64 = 0;

    pub fn new(duration: u64, speed: f64, playing: bool) -> Clock {
        Clock {
            state: Mutex::new(State {
                playing,
                speed,
                position_at_anchor: 0,
                anchor: Instant::now(),
                seeks: Self::SEEKS_AT_START,
                changes: 0,
                step_to_next: false,
                stopped: false,
            }),
            changed: Condvar::new(),
            duration,
        }
    }

    fn change(&self, f: impl FnOnce(&mut State, u64)) {
        let mut state = self.state.lock().expect("clock");
        state.re_anchor(self.duration);
        f(&mut state, self.duration);
        state.changes += 1;
        self.changed.notify_all();
    }

    /// Play or pause. Playing at the end starts again from the beginning.
    pub fn set_playing(&self, playing: bool) {
        self.change(|s, duration| {
            if playing && !s.playing && s.position_at_anchor >= duration {
                s.position_at_anchor = 0;
                s.seeks += 1;
            }
            s.playing = playing;
        });
    }

    /// Recorded seconds per real second; refused unless above 0 and finite.
    pub fn set_speed(&self, speed: f64) -> bool {
        if !(speed > 0.0 && speed.is_finite()) {
            return false;
        }
        self.change(|s, _| s.speed = speed);
        true
    }

    /// Moves to `position` ns from the start (clamped to the recording).
    pub fn seek(&self, position: u64) {
        self.change(|s, duration| {
            s.position_at_anchor = position.min(duration);
            s.seeks += 1;
        });
    }

    /// Plays `by` ns more of the recording at once (0: up to the next message).
    pub fn step(&self, by: u64) {
        self.change(|s, duration| {
            if by == 0 {
                s.step_to_next = true;
            } else {
                s.position_at_anchor = s.position_at_anchor.saturating_add(by).min(duration);
            }
        });
    }

    /// The end of the recording was reached: stand there, paused.
    pub fn reached_end(&self) {
        self.change(|s, duration| {
            s.position_at_anchor = duration;
            s.playing = false;
            s.step_to_next = false;
        });
    }

    pub fn stop(&self) {
        self.change(|s, _| s.stopped = true);
    }

    pub fn position_ns(&self) -> u64 {
        self.state.lock().expect("clock").position(self.duration)
    }

    pub fn duration_ns(&self) -> u64 {
        self.duration
    }

    pub fn is_playing(&self) -> bool {
        self.state.lock().expect("clock").playing
    }

    /// Where playback is, as the `log` device reports it.
    pub fn playback(&self) -> LogPlayback {
        let state = self.state.lock().expect("clock");
        LogPlayback {
            state: u8::from(state.playing),
            speed: state.speed,
            position: state.position(self.duration) as f64 / NS_PER_S,
            duration: self.duration as f64 / NS_PER_S,
        }
    }

    /// The number of seeks so far ([`Clock::SEEKS_AT_START`] when it was made).
    pub fn seeks(&self) -> u64 {
        self.state.lock().expect("clock").seeks
    }

    /// Waits until the message at `due` ns is due, playback is moved (the thread read from
    /// seek number `seeks`), something else changes, or `limit` passes.
    pub fn wait_for(&self, due: u64, seeks: u64, changes: &mut u64, limit: Duration) -> Wake {
        let until = Instant::now() + limit;
        let mut state = self.state.lock().expect("clock");
        loop {
            if state.stopped {
                return Wake::Stop;
            }
            if state.seeks != seeks {
                *changes = state.changes;
                return Wake::Seek {
                    to: state.position(self.duration),
                    seeks: state.seeks,
                };
            }
            if state.step_to_next && due > state.position_at_anchor && !state.playing {
                state.position_at_anchor = due.min(self.duration);
                state.step_to_next = false;
            }
            // Read once: the position moves on while playing, and the wait below is counted
            // from the very position found short of `due` here.
            let position = state.position(self.duration);
            if position >= due {
                state.step_to_next = false;
                return Wake::Due;
            }
            if state.changes != *changes {
                *changes = state.changes;
                return Wake::Changed;
            }
            let now = Instant::now();
            if now >= until {
                return Wake::Changed;
            }
            let mut wait = until - now;
            if state.playing {
                let left = (due - position) as f64 / state.speed / NS_PER_S;
                wait = wait.min(Duration::from_secs_f64(left));
            }
            state = self.changed.wait_timeout(state, wait).expect("clock").0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LONG: Duration = Duration::from_secs(3600);

    #[test]
    fn a_paused_clock_moves_only_when_stepped_or_seeked() {
        let clock = Clock::new(10_000, 1.0, false);
        let mut changes = 0;
        assert_eq!(clock.position_ns(), 0);
        clock.step(300);
        assert_eq!(clock.wait_for(250, 0, &mut changes, LONG), Wake::Due);
        assert_eq!(clock.position_ns(), 300);
        clock.step(0);
        assert_eq!(clock.wait_for(700, 0, &mut changes, LONG), Wake::Due);
        assert_eq!(clock.position_ns(), 700);
        clock.seek(50_000);
        assert_eq!(
            clock.wait_for(9_000, 0, &mut changes, LONG),
            Wake::Seek {
                to: 10_000,
                seeks: 1
            }
        );
    }

    #[test]
    fn playing_at_the_end_starts_again() {
        let clock = Clock::new(10_000, 1.0, true);
        clock.reached_end();
        assert!(!clock.is_playing());
        assert_eq!(clock.position_ns(), 10_000);
        let seeks = clock.seeks();
        clock.set_playing(true);
        assert_eq!(clock.seeks(), seeks + 1);
        assert!(clock.position_ns() < 10_000);
    }

    #[test]
    fn bad_speeds_are_refused() {
        let clock = Clock::new(1, 1.0, true);
        assert!(!clock.set_speed(0.0));
        assert!(!clock.set_speed(f64::NAN));
        assert!(clock.set_speed(8.0));
        assert_eq!(clock.playback().speed, 8.0);
    }
}
