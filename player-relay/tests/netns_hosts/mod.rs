//! The namespaced hosts of the Zenoh test: sites A (robot), B (router), C (this test's own
//! namespace) and D (a second observer site), joined by veth pairs through B, and the
//! programs started in them; everything is removed when dropped.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

pub const RELAY: &str = env!("CARGO_BIN_EXE_player-relay");

/// Another workspace program, built beside the relay (`cargo test --workspace` builds every
/// package's binaries before it runs any test).
pub fn program(name: &str) -> PathBuf {
    let path = Path::new(RELAY).with_file_name(name);
    assert!(
        path.exists(),
        "{} is not built: run `cargo test --workspace` (or build it first: cargo build --bin {name})",
        path.display()
    );
    path
}

/// Addresses: A–B on 10.77.1.0/24, B–C on 10.77.2.0/24 (C is this namespace).
pub const A: &str = "10.77.1.1";
pub const B_TO_A: &str = "10.77.1.2";
pub const B_TO_C: &str = "10.77.2.1";
pub const C: &str = "10.77.2.2";
/// B–D on 10.77.3.0/24; B forwards between C and D so that this namespace reaches D's relay.
pub const B_TO_D: &str = "10.77.3.1";
pub const D: &str = "10.77.3.2";

fn ip(args: &[&str]) {
    let status = Command::new("ip").args(args).status().expect("ip runs");
    assert!(status.success(), "ip {}", args.join(" "));
}

/// The namespaces and links, and the processes in them; all removed when dropped.
pub struct Hosts {
    pub a: String,
    pub b: String,
    pub d: String,
    /// B's end of the B–C link (cut and healed by the test).
    b_to_c: String,
    c_end: String,
    children: Vec<Child>,
}

impl Hosts {
    pub fn build() -> Hosts {
        let tag = std::process::id() % 100_000;
        let hosts = Hosts {
            a: format!("pz-a-{tag}"),
            b: format!("pz-b-{tag}"),
            d: format!("pz-d-{tag}"),
            b_to_c: format!("pzbc{tag}"),
            c_end: format!("pzc{tag}"),
            children: Vec::new(),
        };
        let (a_end, b_to_a) = (format!("pza{tag}"), format!("pzba{tag}"));
        ip(&["netns", "add", &hosts.a]);
        ip(&["netns", "add", &hosts.b]);
        ip(&["netns", "add", &hosts.d]);
        let (d_end, b_to_d) = (format!("pzd{tag}"), format!("pzbd{tag}"));
        ip(&[
            "link", "add", &d_end, "type", "veth", "peer", "name", &b_to_d,
        ]);
        ip(&["link", "set", &d_end, "netns", &hosts.d]);
        ip(&["link", "set", &b_to_d, "netns", &hosts.b]);
        ip(&[
            "link", "add", &a_end, "type", "veth", "peer", "name", &b_to_a,
        ]);
        ip(&["link", "set", &a_end, "netns", &hosts.a]);
        ip(&["link", "set", &b_to_a, "netns", &hosts.b]);
        ip(&[
            "link",
            "add",
            &hosts.c_end,
            "type",
            "veth",
            "peer",
            "name",
            &hosts.b_to_c,
        ]);
        ip(&["link", "set", &hosts.b_to_c, "netns", &hosts.b]);
        for (ns, dev, addr) in [
            (&hosts.a, &a_end, A),
            (&hosts.b, &b_to_a, B_TO_A),
            (&hosts.b, &hosts.b_to_c, B_TO_C),
            (&hosts.b, &b_to_d, B_TO_D),
            (&hosts.d, &d_end, D),
        ] {
            ip(&["-n", ns, "addr", "add", &format!("{addr}/24"), "dev", dev]);
            ip(&["-n", ns, "link", "set", dev, "up"]);
            ip(&["-n", ns, "link", "set", "lo", "up"]);
        }
        ip(&["addr", "add", &format!("{C}/24"), "dev", &hosts.c_end]);
        ip(&["link", "set", &hosts.c_end, "up"]);
        // C reaches D's relay through B, as one site reaches another through its router.
        ip(&["route", "add", "10.77.3.0/24", "via", B_TO_C]);
        ip(&["-n", &hosts.d, "route", "add", "default", "via", B_TO_D]);
        let forward = Command::new("ip")
            .args([
                "netns",
                "exec",
                &hosts.b,
                "sysctl",
                "-qw",
                "net.ipv4.ip_forward=1",
            ])
            .status()
            .expect("sysctl runs");
        assert!(forward.success(), "B forwards");
        hosts
    }

    /// Runs the relay with `args` in namespace `ns` (this one with `None`).
    pub fn relay(&mut self, ns: Option<&str>, args: &[&str]) {
        let child = self
            .command(ns, Path::new(RELAY), args)
            .stdout(Stdio::null())
            .spawn()
            .expect("the relay starts");
        self.children.push(child);
    }

    /// `program` with `args` in namespace `ns` (this one with `None`), run from the
    /// repository's root, to be spawned by the caller (who keeps the child).
    pub fn command(&self, ns: Option<&str>, program: &Path, args: &[&str]) -> Command {
        let mut command = match ns {
            Some(ns) => {
                let mut c = Command::new("ip");
                c.args(["netns", "exec", ns]).arg(program);
                c
            }
            None => Command::new(program),
        };
        command
            .args(args)
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
            .stdin(Stdio::null())
            .env("RUST_LOG", "warn");
        command
    }

    pub fn set_b_to_c(&self, up: bool) {
        ip(&[
            "-n",
            &self.b,
            "link",
            "set",
            &self.b_to_c,
            if up { "up" } else { "down" },
        ]);
    }
}

impl Drop for Hosts {
    fn drop(&mut self) {
        for child in &mut self.children {
            let _ = child.kill();
            let _ = child.wait();
        }
        let _ = Command::new("ip")
            .args(["link", "del", &self.c_end])
            .status();
        for ns in [&self.a, &self.b, &self.d] {
            let _ = Command::new("ip").args(["netns", "del", ns]).status();
        }
    }
}

pub fn is_root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("Uid:"))
                .map(|l| l.split_whitespace().nth(1) == Some("0"))
        })
        .unwrap_or(false)
}

/// A free port on this namespace's loopback, for C's Player server.
pub fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
        .expect("a free port")
}

pub fn wait_until(timeout: Duration, mut done: impl FnMut() -> bool) -> Option<Duration> {
    let start = Instant::now();
    while start.elapsed() < timeout {
        if done() {
            return Some(start.elapsed());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    None
}

/// A program the test waits for, or kills if the test ends first.
pub struct Program(pub Child);

impl Program {
    /// Waits at most `timeout` for it to exit by itself; whether it did, successfully.
    pub fn wait_exit(&mut self, timeout: Duration) -> bool {
        let start = Instant::now();
        while start.elapsed() < timeout {
            if let Ok(Some(status)) = self.0.try_wait() {
                return status.success();
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        false
    }
}

impl Drop for Program {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}
