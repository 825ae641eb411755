//! A real window (under Xvfb) whose Player server answers only after the window is up: the
//! server's plugins must appear when it answers, with nobody touching the window. Before, they
//! waited for the next window event (a mouse move), and an untouched window never got them.

mod support;

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Child, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::{served::from_cfg, sim::Simulation, world::World};
use support::xvfb::Xvfb;

/// The checkout's top folder.
fn repo_root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// One robot with a laser (configs/single-laser.pv3d.xml) on 127.0.0.1:`port`.
fn single_laser_on(port: u16, dir: &Path) -> String {
    let templates = repo_root().join("configs/templates");
    let file = dir.join("late.pv3d.xml");
    let text = format!(
        r#"<pv3d xmlns:xi="http://www.w3.org/2001/XInclude">
  <handlers>
    <playerClient host="127.0.0.1" port="{port}"/>
    <playerDeviceMask interface="position2d">
      <xi:include href="{t}/position2d.pv3d.xml"/>
    </playerDeviceMask>
    <playerDeviceMask interface="laser">
      <xi:include href="{t}/laser.pv3d.xml"/>
    </playerDeviceMask>
  </handlers>
  <plugin library="libpv3d_lights"/>
  <plugin library="libpv3d_ground"/>
</pv3d>"#,
        t = templates.display()
    );
    std::fs::write(&file, text).unwrap();
    file.to_string_lossy().into_owned()
}

/// stage-worlds/simple.world with every device on `port`, as a server started late would be.
fn serve_simple_world_on(port: u16) -> Running {
    let world_file = repo_root().join("stage-worlds/simple.world");
    let world = World::load(&world_file).expect("world");
    let mut devices =
        from_cfg(&world_file.with_extension("cfg"), &world, &mut Vec::new()).expect("cfg");
    for device in &mut devices {
        device.port = port;
    }
    serve(Simulation::new(world), devices, ServeOptions::default()).expect("the server starts")
}

/// The pv3d process, killed when dropped, and its log lines as they come.
struct Running3d {
    child: Child,
    lines: Receiver<String>,
    seen: Vec<String>,
}

impl Running3d {
    /// Waits for a log line containing `text`; panics with the log so far after `timeout`.
    fn wait_for(&mut self, text: &str, timeout: Duration) -> String {
        let deadline = Instant::now() + timeout;
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            match self.lines.recv_timeout(left) {
                Ok(line) => {
                    self.seen.push(line.clone());
                    if line.contains(text) {
                        return line;
                    }
                }
                Err(RecvTimeoutError::Timeout) => {
                    panic!(
                        "no {text:?} within {timeout:?}; log:\n{}",
                        self.seen.join("\n")
                    )
                }
                Err(RecvTimeoutError::Disconnected) => {
                    panic!("pv3d ended before {text:?}; log:\n{}", self.seen.join("\n"))
                }
            }
        }
    }
}

impl Drop for Running3d {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

#[test]
fn a_server_answering_after_the_window_opened_gets_its_plugins_without_input() {
    let xvfb = Xvfb::start();
    let dir = tempfile::tempdir().unwrap();
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port();
    let composition = single_laser_on(port, dir.path());
    let mut child = xvfb
        .command()
        // The safety net if the test is killed: the window closes by itself.
        .args([
            &composition,
            "--connect-timeout",
            "0",
            "--quit-after",
            "120",
        ])
        .env("RUST_LOG", "info,pv3d::app::window=debug")
        .env("NO_COLOR", "1")
        .stderr(Stdio::piped())
        .spawn()
        .expect("pv3d runs");
    let stderr = child.stderr.take().expect("piped");
    let (send, lines) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            if send.send(line).is_err() {
                return;
            }
        }
    });
    let mut pv3d = Running3d {
        child,
        lines,
        seen: Vec::new(),
    };
    pv3d.wait_for("first frame", Duration::from_secs(60));
    // The window's start-up frames are over once the client has been refused a few more
    // times (its retries back off, doubling: 0.1, 0.2, 0.4, 0.8, 1.6 s…); its next try comes
    // a second or more later, with the window idle. Nobody touches the window from here on.
    for _ in 0..4 {
        pv3d.wait_for("connection lost", Duration::from_secs(30));
    }
    let _server = serve_simple_world_on(port);
    let line = pv3d.wait_for("answered late", Duration::from_secs(20));
    assert!(
        line.contains("2 plugins"),
        "the robot and its laser: {line}"
    );
}
