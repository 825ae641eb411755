//! An Xvfb server for the tests that open a real window (eframe + glow + winit on X11) with
//! Mesa. Needs Xvfb (`scripts/setup.sh` installs it).

use std::path::Path;
use std::process::{Child, Command, Output, Stdio};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};

/// An Xvfb server on a display of its own, stopped when dropped.
pub struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    pub fn start() -> Xvfb {
        // Tests of one file run in parallel: each takes displays of its own, so that one
        // never mistakes the other's Xvfb for the one it started (and loses it when the other
        // test ends).
        static NEXT: AtomicU32 = AtomicU32::new(0);
        let base = 40 + std::process::id() % 400 + 100 * NEXT.fetch_add(1, Ordering::Relaxed);
        for n in base..base + 50 {
            if Path::new(&format!("/tmp/.X11-unix/X{n}")).exists()
                || Path::new(&format!("/tmp/.X{n}-lock")).exists()
            {
                continue;
            }
            let child = Command::new("Xvfb")
                .args([
                    &format!(":{n}"),
                    "-screen",
                    "0",
                    "1024x768x24",
                    "-nolisten",
                    "tcp",
                ])
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .expect("Xvfb is needed for the window tests: run scripts/setup.sh");
            let mut xvfb = Xvfb {
                child,
                display: format!(":{n}"),
            };
            let deadline = Instant::now() + Duration::from_secs(10);
            while Instant::now() < deadline {
                if Path::new(&format!("/tmp/.X11-unix/X{n}")).exists() {
                    return xvfb;
                }
                if xvfb.child.try_wait().ok().flatten().is_some() {
                    break; // lost a race for that display: try the next
                }
                std::thread::sleep(Duration::from_millis(20));
            }
            let _ = xvfb.child.kill();
        }
        panic!("could not start Xvfb on any display from :{base}");
    }

    /// The pv3d binary, drawing on this display.
    pub fn command(&self) -> Command {
        let mut command = Command::new(env!("CARGO_BIN_EXE_pv3d"));
        command
            .env("DISPLAY", &self.display)
            .env_remove("WAYLAND_DISPLAY");
        command
    }

    /// Runs pv3d with `args` on this display to the end.
    pub fn pv3d(&self, args: &[&str]) -> Output {
        self.command().args(args).output().expect("pv3d runs")
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
