//! The frames a run drew, for `--frame-stats`: how many, how often, and when the first whole
//! picture came — every server connected and every device in use reporting — after which the
//! rate is the one the viewer keeps (the start-up, a thousand robots connecting, is apart).

use std::time::{Duration, Instant};

use super::frame_times::FRAME_TIMES;

/// Frames drawn since a run started.
#[derive(Debug, Clone, Copy)]
pub struct FrameCount {
    started: Instant,
    frames: u64,
    /// When the first whole picture was drawn, and the frames drawn up to it.
    full: Option<(Instant, u64)>,
}

impl FrameCount {
    pub fn new(started: Instant) -> FrameCount {
        FrameCount {
            started,
            frames: 0,
            full: None,
        }
    }

    /// A frame was drawn; `whole` tells whether it showed every robot's data.
    pub fn drawn(&mut self, whole: bool) {
        self.frames += 1;
        if whole && self.full.is_none() {
            self.full = Some((Instant::now(), self.frames));
        }
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
            "frames: {} in {:.2} s ({:.1} per second){whole}\nper frame: {}",
            self.frames,
            elapsed.as_secs_f64(),
            rate(self.frames, elapsed),
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
}
