//! The frames a run drew, for `--frame-stats`: how many, how often, and when the first whole
//! picture came — every server connected and every device in use reporting — after which the
//! rate is the one the viewer keeps (the start-up, a thousand robots connecting, is apart).
//! And the longest pause between two frames: an idle window's should be nearly the whole run.

use std::time::{Duration, Instant};

use super::frame_times::FRAME_TIMES;

/// Frames drawn since a run started.
#[derive(Debug, Clone, Copy)]
pub struct FrameCount {
    started: Instant,
    frames: u64,
    /// When the first whole picture was drawn, and the frames drawn up to it.
    full: Option<(Instant, u64)>,
    /// When the last frame was drawn, and the longest time between two frames so far.
    last: Option<Instant>,
    longest_pause: Duration,
}

impl FrameCount {
    pub fn new(started: Instant) -> FrameCount {
        FrameCount {
            started,
            frames: 0,
            full: None,
            last: None,
            longest_pause: Duration::ZERO,
        }
    }

    /// A frame was drawn; `whole` tells whether it showed every robot's data.
    pub fn drawn(&mut self, whole: bool) {
        self.drawn_at(Instant::now(), whole);
    }

    fn drawn_at(&mut self, now: Instant, whole: bool) {
        self.frames += 1;
        if whole && self.full.is_none() {
            self.full = Some((now, self.frames));
        }
        if let Some(last) = self.last {
            self.longest_pause = self.longest_pause.max(now.saturating_duration_since(last));
        }
        self.last = Some(now);
    }

    /// The same count, its times from `started` (an earlier instant: the process's start).
    pub fn counted_from(self, started: Instant) -> FrameCount {
        FrameCount { started, ..self }
    }

    /// Whether the whole picture was drawn yet (then there is no need to ask again).
    pub fn whole_drawn(&self) -> bool {
        self.full.is_some()
    }

    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// The `--frame-stats` lines: the frames, the first whole one and the rate since, then
    /// the mean time of each stage of a frame ([`FRAME_TIMES`]).
    pub fn stats(&self, now: Instant) -> String {
        let rate = |frames: u64, over: Duration| frames as f64 / over.as_secs_f64().max(1e-9);
        let elapsed = now.duration_since(self.started);
        let whole = match self.full {
            Some((at, frames)) => format!(
                "; the first whole picture at {:.1} s, {:.1} per second since",
                at.duration_since(self.started).as_secs_f64(),
                rate(self.frames - frames, now.duration_since(at)),
            ),
            None => "; no whole picture (a server not connected or a device silent)".into(),
        };
        format!(
            "frames: {} in {:.2} s ({:.1} per second){whole}; longest pause between frames \
             {:.2} s\nper frame: {}",
            self.frames,
            elapsed.as_secs_f64(),
            rate(self.frames, elapsed),
            self.longest_pause.as_secs_f64(),
            FRAME_TIMES.summary()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rate_after_the_first_whole_picture_leaves_the_start_up_out() {
        let started = Instant::now() - Duration::from_secs(10);
        let mut count = FrameCount::new(started);
        count.drawn(false);
        assert!(!count.whole_drawn());
        count.drawn(true);
        count.drawn(true);
        assert!(count.whole_drawn());
        assert_eq!(count.frames(), 3);
        let stats = count.stats(Instant::now());
        assert!(stats.starts_with("frames: 3 in 10.0"), "{stats}");
        assert!(
            stats.contains("the first whole picture at 10.0 s"),
            "{stats}"
        );

        let never = FrameCount::new(started).stats(Instant::now());
        assert!(never.contains("no whole picture"), "{never}");
    }

    #[test]
    fn the_longest_pause_is_the_longest_time_between_two_frames() {
        let started = Instant::now();
        let mut count = FrameCount::new(started);
        for at_ms in [0, 10, 20, 2_500, 2_510] {
            count.drawn_at(started + Duration::from_millis(at_ms), false);
        }
        let stats = count.stats(started + Duration::from_millis(2_520));
        assert!(
            stats.contains("longest pause between frames 2.48 s"),
            "{stats}"
        );
        let one = FrameCount::new(started).stats(started);
        assert!(one.contains("longest pause between frames 0.00 s"), "{one}");
    }
}
