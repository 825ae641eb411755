//! The web page's test rig: a player-sim world served on loopback, the relay with the page
//! in front of it, and the page driven in a real Chromium by `tests/web/page.mjs`.

#![allow(dead_code)]

use std::net::{IpAddr, Ipv4Addr};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Arc;
use std::time::{Duration, Instant};

use player_proto::RobotId;
use player_proto::server::Commanders;
use player_relay::{Relay, RelayConfig, Route};
use player_sim::serve::{Running, ServeOptions, serve_world_file};
use player_sim::world::World;
use player_web::WebFront;

pub const LOCALHOST: IpAddr = IpAddr::V4(Ipv4Addr::LOCALHOST);

pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Serves `world` (from stage-worlds/) with its .cfg files; every port free, or each robot on
/// the port `ports` gives for its configured one (a server restarted on its old port).
pub fn serve_world(world: &str, ports: Option<&[(u16, u16)]>) -> Running {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../stage-worlds")
        .join(world);
    let options = ServeOptions {
        free_ports: ports.is_none(),
        ..ServeOptions::default()
    };
    serve_world_file(&path, options, ports.unwrap_or_default(), &mut Vec::new())
        .expect("the world is served")
}

/// The relay in front of `running`'s robots, with the web page.
pub struct Front {
    pub web: Arc<WebFront>,
    pub relay: Relay,
}

impl Front {
    pub fn start(running: &Running, rule: Commanders) -> Front {
        let web = Arc::new(WebFront::start(LOCALHOST, 0, rule).expect("the page is served"));
        let routes = running
            .ports
            .iter()
            .map(|&(_, port)| Route::loopback(port))
            .collect();
        Front::relay(running, web, routes, rule)
    }

    /// As `player-relay --world WORLD --web` shows `running` (WORLD from stage-worlds/):
    /// each robot named after its model, the world's walls drawn.
    pub fn start_as_world(running: &Running, world: &str, rule: Commanders) -> Front {
        let path = repo_root().join("stage-worlds").join(world);
        let loaded = World::load(&path).expect("the world loads");
        let names = player_relay::world::names(&path, &loaded).expect("its .cfg reads");
        let web = Arc::new(WebFront::start(LOCALHOST, 0, rule).expect("the page is served"));
        web.set_walls(&player_relay::world::walls(&loaded));
        let routes = running
            .ports
            .iter()
            .map(|&(configured, port)| Route {
                robot: match names.get(&configured) {
                    Some(name) => RobotId::new("127.0.0.1", port).named(name).unwrap(),
                    None => RobotId::new("127.0.0.1", port),
                },
                listen_port: 0,
            })
            .collect();
        Front::relay(running, web, routes, rule)
    }

    fn relay(running: &Running, web: Arc<WebFront>, routes: Vec<Route>, rule: Commanders) -> Front {
        let relay = Relay::start(RelayConfig {
            routes,
            commanders: rule,
            fronts: vec![web.clone() as _],
            ..RelayConfig::default()
        })
        .expect("the relay starts");
        assert_eq!(
            relay.wait_serving(Duration::from_secs(10)),
            running.ports.len()
        );
        Front { web, relay }
    }

    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.web.port())
    }
}

/// The name the page knows a served robot by.
pub fn robot_name(running: &Running, configured: u16) -> String {
    format!(
        "127.0.0.1:{}",
        running.port(configured).expect("a served port")
    )
}

/// Runs `tests/web/page.mjs` with `args` and returns what it printed, as JSON. Fails (not
/// skips) when the Node side is not installed: the README's setup installs it.
pub fn page(args: &[&str]) -> serde_json::Value {
    page_sized("1200x750", args)
}

/// [`page`] in a window of `viewport` (`WIDTHxHEIGHT`, CSS pixels).
pub fn page_sized(viewport: &str, args: &[&str]) -> serde_json::Value {
    let web = repo_root().join("tests/web");
    assert!(
        web.join("node_modules/playwright-core").is_dir(),
        "tests/web/node_modules is missing: run `bash scripts/setup.sh` (it installs Playwright's driver and Chromium)"
    );
    let started = Instant::now();
    let out = Command::new("node")
        .arg("page.mjs")
        .args(args)
        .current_dir(&web)
        .env("VIEWPORT", viewport)
        .output()
        .expect("node runs (scripts/setup.sh checks for it)");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "page.mjs {args:?} failed after {:?}:\n{stdout}\n{stderr}",
        started.elapsed()
    );
    let line = stdout.lines().last().unwrap_or_default();
    let seen: serde_json::Value = serde_json::from_str(line)
        .unwrap_or_else(|e| panic!("page.mjs printed no JSON ({e}):\n{stdout}\n{stderr}"));
    assert_eq!(
        seen["errors"],
        serde_json::json!([]),
        "the page's own errors"
    );
    seen
}

/// Where robot `index` is in the simulation.
pub fn sim_pose(running: &Running, index: usize) -> (f64, f64, f64) {
    let sim = running.sim.lock().expect("the simulation");
    let pose = sim.robots[index].pose;
    (pose.x, pose.y, pose.a)
}

/// Waits until `done`, at most `timeout`; whether it came.
pub fn wait_for(timeout: Duration, mut done: impl FnMut() -> bool) -> bool {
    let end = Instant::now() + timeout;
    while Instant::now() < end {
        if done() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    done()
}

/// Where screenshots go: looked at by people, kept out of the checkout.
pub fn screenshot(name: &str) -> String {
    let dir = repo_root().join("target/web-screenshots");
    std::fs::create_dir_all(&dir).expect("target/ is writable");
    dir.join(name).display().to_string()
}
