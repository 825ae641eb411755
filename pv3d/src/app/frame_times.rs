//! Where a frame's time goes, stage by stage, for `--frame-stats`: the plugins' update, the
//! scene flattened into batches, the 3D view's GL calls, the whole interface pass, and the
//! whole frame as eframe counts it (everything but the buffer swap).
//!
//! The stages are timed where they run — the GL calls inside egui's paint callback, long after
//! the view asked for them — so the totals live in process-wide counters rather than being
//! threaded through every layer. Counting costs two relaxed atomic adds per stage per frame.

use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// A part of the frame that is timed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// `Viewer::update`: servers followed, every plugin run.
    Update,
    /// The scene flattened into vertex batches (when it or the camera changed).
    Batch,
    /// The 3D view's paint callback: uploads and draw calls (Mesa rasterises later, on its
    /// own threads, and the swap waits for it).
    ViewPaint,
    /// `Viewer::ui`: panels, item tree, status panel, the view's layout and labels.
    Interface,
    /// The whole frame as eframe measures it: update, interface, tessellation, painting.
    Whole,
}

const STAGES: [Stage; 5] = [
    Stage::Update,
    Stage::Batch,
    Stage::ViewPaint,
    Stage::Interface,
    Stage::Whole,
];

impl Stage {
    fn name(self) -> &'static str {
        match self {
            Stage::Update => "update",
            Stage::Batch => "batch",
            Stage::ViewPaint => "view GL calls",
            Stage::Interface => "interface",
            Stage::Whole => "whole frame",
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

struct Counter {
    nanos: AtomicU64,
    count: AtomicU64,
}

/// Totals per stage; the viewer's are [`FRAME_TIMES`].
pub struct FrameTimes {
    counters: [Counter; STAGES.len()],
}

/// The process's frame times, printed by `--frame-stats`.
pub static FRAME_TIMES: FrameTimes = FrameTimes::new();

impl FrameTimes {
    pub const fn new() -> FrameTimes {
        #[allow(clippy::declare_interior_mutable_const)] // a template for the array below
        const ZERO: Counter = Counter {
            nanos: AtomicU64::new(0),
            count: AtomicU64::new(0),
        };
        FrameTimes {
            counters: [ZERO; STAGES.len()],
        }
    }

    /// Adds one occurrence of `stage` that took `took`.
    pub fn record(&self, stage: Stage, took: Duration) {
        let counter = &self.counters[stage.index()];
        let nanos = u64::try_from(took.as_nanos()).unwrap_or(u64::MAX);
        counter.nanos.fetch_add(nanos, Ordering::Relaxed);
        counter.count.fetch_add(1, Ordering::Relaxed);
    }

    /// Runs `work` and records how long it took as `stage`.
    pub fn timed<T>(&self, stage: Stage, work: impl FnOnce() -> T) -> T {
        let start = Instant::now();
        let result = work();
        self.record(stage, start.elapsed());
        result
    }

    /// The mean time of each stage that ran, e.g. `update 4.1 ms, batch 9.8 ms (×88), …`: a
    /// stage that ran in fewer frames than the first one listed says in how many.
    pub fn summary(&self) -> String {
        let mut first_count = None;
        let parts: Vec<String> = STAGES
            .iter()
            .filter_map(|&stage| {
                let counter = &self.counters[stage.index()];
                let count = counter.count.load(Ordering::Relaxed);
                if count == 0 {
                    return None;
                }
                let mean_ms = counter.nanos.load(Ordering::Relaxed) as f64 / count as f64 / 1e6;
                let runs = match *first_count.get_or_insert(count) {
                    first if first == count => String::new(),
                    _ => format!(" (×{count})"),
                };
                Some(format!("{} {mean_ms:.1} ms{runs}", stage.name()))
            })
            .collect();
        parts.join(", ")
    }
}

impl Default for FrameTimes {
    fn default() -> Self {
        FrameTimes::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stages_are_averaged_and_named() {
        let times = FrameTimes::new();
        times.record(Stage::Update, Duration::from_millis(2));
        times.record(Stage::Update, Duration::from_millis(4));
        times.timed(Stage::Batch, || ());
        let summary = times.summary();
        assert!(summary.starts_with("update 3.0 ms, batch "), "{summary}");
        assert!(summary.contains("(×1)"), "{summary}");
        assert!(!summary.contains("view GL calls"), "{summary}");
    }
}
