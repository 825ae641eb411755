//! The viewer's UI fed the input a window gets (egui events, no GL needed: the 3D view's paint
//! callback is only recorded), against a robot simulated by player-sim over TCP: the window
//! losing focus stops a driving robot; Ctrl+drag over the view drags the selected robot's
//! target without moving the camera, and letting go sends the robot there; the joystick shown
//! over the view while the robot is selected drives it, and letting go stops it.

use std::time::{Duration, Instant};

use egui::{Event, Modifiers, PointerButton, Pos2, RawInput, Rect, pos2, vec2};
use glam::Vec3;
use pv3d::app::Viewer;
use tests::{load, run_for, run_until, serve, sim_pose, viewer_for};

/// One window frame: update, then the UI with `events`.
struct Window {
    ctx: egui::Context,
    start: Instant,
}

impl Window {
    fn new() -> Window {
        Window {
            ctx: egui::Context::default(),
            start: Instant::now(),
        }
    }

    fn frame(&mut self, viewer: &mut Viewer, mut events: Vec<Event>, modifiers: Modifiers) {
        viewer.update(Instant::now());
        events.insert(0, Event::ModifiersChanged(modifiers));
        let input = RawInput {
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, vec2(1000.0, 700.0))),
            time: Some(self.start.elapsed().as_secs_f64()),
            focused: true,
            events,
            ..Default::default()
        };
        let mut output = self.ctx.run_ui(input, |ui| viewer.ui(ui));
        // Nothing is painted: drop the font texture uploads on purpose.
        output.textures_delta.clear();
        std::thread::sleep(Duration::from_millis(20));
    }

    fn idle(&mut self, viewer: &mut Viewer, frames: usize) {
        for _ in 0..frames {
            self.frame(viewer, Vec::new(), Modifiers::NONE);
        }
    }
}

fn distance(a: (f64, f64, f64), b: (f64, f64, f64)) -> f64 {
    ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
}

#[test]
fn losing_the_window_focus_stops_a_driving_robot() {
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    let running = serve("stage-worlds/simple.world", &mut composition, 2.0);
    let mut viewer = viewer_for(&composition);
    let mut window = Window::new();
    run_for(&mut viewer, Duration::from_millis(500));
    let start = sim_pose(&running, 0);
    viewer.cycle_active();
    viewer.click(
        None,
        Some(Vec3::new(start.0 as f32 + 3.0, start.1 as f32, 0.0)),
    );
    let deadline = Instant::now() + Duration::from_secs(10);
    while distance(sim_pose(&running, 0), start) < 0.3 {
        assert!(Instant::now() < deadline, "the robot never set off");
        window.idle(&mut viewer, 1);
    }

    window.frame(
        &mut viewer,
        vec![Event::WindowFocused(false)],
        Modifiers::NONE,
    );
    window.idle(&mut viewer, 10);
    let stopped = sim_pose(&running, 0);
    window.idle(&mut viewer, 20);
    let later = sim_pose(&running, 0);
    assert!(
        distance(later, stopped) < 0.02,
        "still driving after the window lost focus: {stopped:?} -> {later:?}"
    );
}

#[test]
fn ctrl_drag_over_the_view_drags_the_target_and_release_sends_it() {
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    let running = serve("stage-worlds/simple.world", &mut composition, 4.0);
    let mut viewer = viewer_for(&composition);
    let mut window = Window::new();
    run_for(&mut viewer, Duration::from_millis(500));
    window.idle(&mut viewer, 5);
    viewer.cycle_active();
    // The selected robot's panel takes room from the view, which is framed anew for its
    // shape: let that settle before the drag is watched.
    window.idle(&mut viewer, 2);
    let start = sim_pose(&running, 0);
    let camera = viewer.view.camera.clone();

    // Press in the view (right of the item tree, above the status panel), drag, let go.
    let ctrl = Modifiers::CTRL;
    let from = pos2(640.0, 260.0);
    window.frame(&mut viewer, vec![Event::PointerMoved(from)], ctrl);
    window.frame(
        &mut viewer,
        vec![Event::PointerButton {
            pos: from,
            button: PointerButton::Primary,
            pressed: true,
            modifiers: ctrl,
        }],
        ctrl,
    );
    let mut at = from;
    for _ in 0..8 {
        at += vec2(12.0, 6.0);
        window.frame(&mut viewer, vec![Event::PointerMoved(at)], ctrl);
    }
    assert_eq!(viewer.view.camera, camera, "the camera stayed put");
    let dragged_drawn = viewer
        .scene()
        .iter()
        .flat_map(|(_, o)| o.geometry.lines.iter())
        .any(|v| v.color.0 == [90, 220, 240, 255]);
    assert!(dragged_drawn, "the dragged target is drawn");
    assert!(
        distance(sim_pose(&running, 0), start) < 0.01,
        "nothing is sent while dragging"
    );
    window.frame(
        &mut viewer,
        vec![Event::PointerButton {
            pos: at,
            button: PointerButton::Primary,
            pressed: false,
            modifiers: ctrl,
        }],
        ctrl,
    );
    assert_eq!(viewer.view.camera, camera);
    run_until(
        &mut viewer,
        "the robot to head for the dropped target",
        Duration::from_secs(10),
        |_| distance(sim_pose(&running, 0), start) > 0.3,
    );
    // Without Ctrl, the same drag moves the camera (top view: pans).
    window.frame(
        &mut viewer,
        vec![Event::PointerMoved(from)],
        Modifiers::NONE,
    );
    window.frame(
        &mut viewer,
        vec![Event::PointerButton {
            pos: from,
            button: PointerButton::Primary,
            pressed: true,
            modifiers: Modifiers::NONE,
        }],
        Modifiers::NONE,
    );
    for i in 1..=4 {
        let p = from + vec2(15.0 * i as f32, 0.0);
        window.frame(&mut viewer, vec![Event::PointerMoved(p)], Modifiers::NONE);
    }
    assert_ne!(viewer.view.camera, camera, "a plain drag pans the view");
}

#[test]
fn the_joystick_over_the_view_drives_and_letting_go_stops() {
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    let running = serve("stage-worlds/simple.world", &mut composition, 2.0);
    let mut viewer = viewer_for(&composition);
    let mut window = Window::new();
    run_for(&mut viewer, Duration::from_millis(500));
    viewer.cycle_active();
    window.idle(&mut viewer, 3);
    // The pad of robot "robot" (the template's id) over the view, without opening the tree.
    let pad = window
        .ctx
        .read_response(plugins::position2d::joystick_id("robot", "view"))
        .expect("the joystick is shown over the view")
        .rect;
    let start = sim_pose(&running, 0);
    let centre = pad.center();
    window.frame(
        &mut viewer,
        vec![Event::PointerMoved(centre)],
        Modifiers::NONE,
    );
    window.frame(
        &mut viewer,
        vec![Event::PointerButton {
            pos: centre,
            button: PointerButton::Primary,
            pressed: true,
            modifiers: Modifiers::NONE,
        }],
        Modifiers::NONE,
    );
    // Push the knob up (forward), and hold it there.
    let up = centre - vec2(0.0, pad.height() * 0.4);
    let deadline = Instant::now() + Duration::from_secs(10);
    while distance(sim_pose(&running, 0), start) < 0.3 {
        assert!(
            Instant::now() < deadline,
            "the joystick did not drive the robot"
        );
        window.frame(&mut viewer, vec![Event::PointerMoved(up)], Modifiers::NONE);
    }
    let now = sim_pose(&running, 0);
    assert!(
        (now.2 - start.2).abs() < 0.05,
        "straight up is straight ahead: heading {} -> {}",
        start.2,
        now.2
    );
    window.frame(
        &mut viewer,
        vec![Event::PointerButton {
            pos: up,
            button: PointerButton::Primary,
            pressed: false,
            modifiers: Modifiers::NONE,
        }],
        Modifiers::NONE,
    );
    window.idle(&mut viewer, 10);
    let stopped = sim_pose(&running, 0);
    window.idle(&mut viewer, 20);
    assert!(
        distance(sim_pose(&running, 0), stopped) < 0.02,
        "still driving after the joystick was let go"
    );
}
