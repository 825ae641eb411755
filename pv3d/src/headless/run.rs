//! `--headless` with no screenshot: the viewer runs offscreen as it would in a window — data
//! taken, plugins run, scripts said, the UI painted at the redraw interval — for a recording,
//! a script or a measurement on a machine with no display, until `--quit-after` (or until the
//! process is stopped).

use std::time::{Duration, Instant};

use super::gl::HeadlessError;
use super::ui::HeadlessUi;
use crate::app::frame_times::{FRAME_TIMES, Stage};
use crate::app::{FrameCount, Viewer};

/// How an offscreen run goes.
#[derive(Debug, Clone, Copy)]
pub struct HeadlessRun {
    /// The offscreen picture's size in pixels (what a window of that size would draw).
    pub size: (u32, u32),
    /// How often the viewer takes new data and paints, as a window's redraw interval.
    pub interval: Duration,
    /// When to stop; `None` runs until the process is stopped.
    pub quit_after: Option<Duration>,
    /// Where the frame statistics count from (the process's start, to include a world's).
    pub counted_from: Instant,
}

/// What an offscreen run did.
#[derive(Debug, Clone, Copy)]
pub struct HeadlessSummary {
    /// UI passes painted, and when the first whole picture was.
    pub frames: FrameCount,
    /// How long it ran.
    pub elapsed: Duration,
}

/// Runs `viewer` offscreen as `run` says, then stops every plugin as a closed window does.
pub fn run_headless(
    viewer: &mut Viewer,
    run: &HeadlessRun,
) -> Result<HeadlessSummary, HeadlessError> {
    let mut ui = HeadlessUi::new(run.size.0, run.size.1)?;
    let started = Instant::now();
    let frames = paint_until(viewer, &mut ui, started, run.quit_after, run.interval);
    let frames = frames.counted_from(run.counted_from);
    viewer.stop_all();
    Ok(HeadlessSummary {
        frames,
        elapsed: started.elapsed(),
    })
}

/// Takes data and paints once per `interval` until `until` has passed since `started` (for
/// ever if `None`); returns the passes painted. Shared with the screenshot run.
pub(super) fn paint_until(
    viewer: &mut Viewer,
    ui: &mut HeadlessUi,
    started: Instant,
    until: Option<Duration>,
    interval: Duration,
) -> FrameCount {
    let mut frames = FrameCount::new(started);
    loop {
        let pass_started = Instant::now();
        FRAME_TIMES.timed(Stage::Update, || viewer.update(pass_started));
        ui.run(|ui| FRAME_TIMES.timed(Stage::Interface, || viewer.ui(ui)));
        FRAME_TIMES.record(Stage::Whole, pass_started.elapsed());
        frames.drawn(frames.whole_drawn() || viewer.every_device_reporting());
        let left = until.map(|until| until.saturating_sub(started.elapsed()));
        if left.is_some_and(|left| left.is_zero()) {
            return frames;
        }
        // The interval is counted from the pass's start, as a window's redraw interval is.
        let rest = interval.saturating_sub(pass_started.elapsed());
        std::thread::sleep(left.map_or(rest, |left| rest.min(left)));
    }
}
