//! The viewer in a real window (eframe + glow), and the window's own screenshot. (With no X
//! server, `--screenshot` draws offscreen instead: [`crate::headless`].)
//!
//! Redraw policy: the robot threads call a waker when data arrives or a server answers; the
//! waker asks egui for a repaint *within* the redraw interval, so however many messages arrive
//! the UI runs at most once per interval, and not at all while nothing changes. Input repaints
//! at once. The waker asks egui once per frame, not once per message: eframe turns an ask
//! into an event for the window's loop whenever its due time is sooner than the last ask's —
//! which a due time counting down always is — so a thousand robots' 20 000 messages a second
//! were as many events.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use eframe::egui;
use image::RgbaImage;

use super::frame_count::FrameCount;
use super::frame_times::{FRAME_TIMES, Stage};
use super::viewer::Viewer;

/// When the window redraws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RedrawPolicy {
    /// At most once per interval, and only when data arrived or the person acted.
    OnChange { interval: Duration },
    /// Continuously (the old behaviour, for comparison).
    WhenIdle,
}

/// Wakes the UI from other threads; set once the window exists.
#[derive(Clone, Default)]
pub struct UiWaker {
    inner: Arc<Mutex<Option<Wake>>>,
}

struct Wake {
    ctx: egui::Context,
    interval: Duration,
    /// When the last frame started: the next one is due one interval after it.
    last_frame: Instant,
    /// When a repaint was last asked for since that frame started: later messages need not ask
    /// again — unless that ask is an interval old and no frame came (asked again, in case it
    /// was lost).
    asked: Option<Instant>,
}

impl UiWaker {
    /// New data arrived, or a server answered: schedule a repaint one interval after the last frame started — not
    /// one interval from now, which would add the frame's own time to every period (a frame
    /// of 90 ms made a 0.10 s interval into 0.19 s).
    pub fn wake(&self) {
        if let Some(wake) = self.inner.lock().expect("waker").as_mut()
            && wake.asked.is_none_or(|at| at.elapsed() >= wake.interval)
        {
            wake.asked = Some(Instant::now());
            let due = wake.interval.saturating_sub(wake.last_frame.elapsed());
            wake.ctx.request_repaint_after(due);
        }
    }

    /// The wake-up to give the servers ([`super::ViewerBuilder::wake_with`]).
    pub fn notifier(&self) -> player_proto::client::Notifier {
        let waker = self.clone();
        Arc::new(move || waker.wake())
    }

    /// A frame is starting.
    fn frame_started(&self) {
        if let Some(wake) = self.inner.lock().expect("waker").as_mut() {
            wake.last_frame = Instant::now();
            wake.asked = None;
        }
    }

    fn install(&self, ctx: egui::Context, interval: Duration) {
        *self.inner.lock().expect("waker") = Some(Wake {
            ctx,
            interval,
            last_frame: Instant::now(),
            asked: None,
        });
    }
}

/// A screenshot to take, then quit.
#[derive(Debug, Clone)]
pub struct ScreenshotRequest {
    pub path: PathBuf,
    /// Seconds to let the composition run first.
    pub after: Duration,
}

struct WindowApp {
    viewer: Viewer,
    policy: RedrawPolicy,
    screenshot: Option<ScreenshotRequest>,
    quit_after: Option<Duration>,
    frame_stats: bool,
    frames: FrameCount,
    waker: UiWaker,
    started: Instant,
    shot_requested: bool,
    shot_done: Arc<Mutex<Option<Result<(), String>>>>,
}

impl eframe::App for WindowApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        self.waker.frame_started();
        if self.frames.frames() == 0 {
            tracing::debug!("the window draws its first frame");
        }
        // eframe reports the previous frame: its update, interface, tessellation, painting.
        if let Some(seconds) = frame.info().cpu_usage {
            FRAME_TIMES.record(Stage::Whole, Duration::from_secs_f32(seconds));
        }
        FRAME_TIMES.timed(Stage::Update, || self.viewer.update(Instant::now()));
        FRAME_TIMES.timed(Stage::Interface, || self.viewer.ui(ui));
        let whole = self.frames.whole_drawn() || self.viewer.every_device_reporting();
        self.frames.drawn(whole);
        if self.policy == RedrawPolicy::WhenIdle {
            ui.ctx().request_repaint();
        }
        self.take_screenshot(ui.ctx());
        if let Some(after) = self.quit_after {
            match after.checked_sub(self.started.elapsed()) {
                // One wake-up at the deadline, not polling: an idle window stays idle.
                Some(left) if !left.is_zero() => ui.ctx().request_repaint_after(left),
                _ => ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close),
            }
        }
    }

    fn on_exit(&mut self, _gl: Option<&eframe::glow::Context>) {
        self.viewer.stop_all();
        if self.frame_stats {
            eprintln!("{}", self.frames.stats(Instant::now()));
        }
    }
}

impl WindowApp {
    fn take_screenshot(&mut self, ctx: &egui::Context) {
        let Some(request) = &self.screenshot else {
            return;
        };
        if let Some(result) = self.shot_done.lock().expect("screenshot").take() {
            match result {
                Ok(()) => tracing::info!("screenshot written to {}", request.path.display()),
                Err(e) => tracing::error!("screenshot failed: {e}"),
            }
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            return;
        }
        if self.shot_requested {
            ctx.request_repaint_after(Duration::from_millis(50));
            return;
        }
        if let Some(left) = request.after.checked_sub(self.started.elapsed())
            && !left.is_zero()
        {
            ctx.request_repaint_after(left);
            return;
        }
        self.shot_requested = true;
        let path = request.path.clone();
        let done = self.shot_done.clone();
        let waker = ctx.clone();
        ctx.request_screenshot(move |image| {
            let [w, h] = image.size;
            let mut bytes: Vec<u8> = image.pixels.iter().flat_map(|c| c.to_array()).collect();
            crate::headless::as_shown(&mut bytes);
            let result = RgbaImage::from_raw(w as u32, h as u32, bytes)
                .ok_or_else(|| "screenshot has the wrong size".to_string())
                .and_then(|img| img.save(&path).map_err(|e| e.to_string()));
            *done.lock().expect("screenshot") = Some(result);
            waker.request_repaint();
        });
    }
}

/// Options of a window.
pub struct WindowOptions {
    pub title: String,
    pub size: (u32, u32),
    pub policy: RedrawPolicy,
    pub screenshot: Option<ScreenshotRequest>,
    /// Close the window this long after it opened.
    pub quit_after: Option<Duration>,
    /// On exit, print how many frames were drawn (to check the redraw policy).
    pub frame_stats: bool,
    /// Where the frame statistics count from (the process's start, to include a world's).
    pub counted_from: Instant,
}

/// Runs the viewer in a window until it is closed; `waker` is the one its servers were given
/// (see [`super::ViewerBuilder::wake_with`]).
pub fn run_window(viewer: Viewer, options: WindowOptions, waker: UiWaker) -> Result<(), String> {
    let interval = match options.policy {
        RedrawPolicy::OnChange { interval } => interval,
        RedrawPolicy::WhenIdle => Duration::ZERO,
    };
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title(&options.title)
            .with_inner_size([options.size.0 as f32, options.size.1 as f32]),
        depth_buffer: 24,
        ..Default::default()
    };
    let app = WindowApp {
        viewer,
        policy: options.policy,
        screenshot: options.screenshot,
        quit_after: options.quit_after,
        frame_stats: options.frame_stats,
        frames: FrameCount::new(options.counted_from),
        waker: waker.clone(),
        started: Instant::now(),
        shot_requested: false,
        shot_done: Arc::default(),
    };
    eframe::run_native(
        &options.title,
        native,
        Box::new(move |cc| {
            waker.install(cc.egui_ctx.clone(), interval);
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| e.to_string())
}
