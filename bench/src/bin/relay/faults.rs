//! Reliability under faults, with the same robots and relay processes as the load phases:
//!
//! * every observer vanishes at once, mid-stream: how soon the relay has let go of their
//!   connections, and what memory it keeps;
//! * the relay is killed (SIGKILL) mid-stream and started again on the same ports: how soon
//!   ordinary `Client` observers notice, and how soon after the restart they have fresh data.

use std::sync::Arc;
use std::sync::mpsc::{Receiver, sync_channel};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use bench::clock::SharedWindow;
use bench::observers::connect_observers;
use bench::recorder::LatencySummary;
use player_proto::client::{Backoff, Client, ClientOptions, ConnectionState};

use crate::roles::RoleProcess;
use crate::{Args, SETUP_TIMEOUT};

/// Reconnecting `Client`s in the relay-killed scenario: what a viewer would be.
const CLIENT_OBSERVERS: usize = 40;
/// How often the relay's sockets are counted while it lets go of vanished observers (a
/// measurement of another process: there is no signal to wait on).
const SOCKET_POLL: Duration = Duration::from_millis(2);
/// The observers' retry timing after losing the relay.
const OBSERVER_BACKOFF: Backoff = Backoff {
    initial: Duration::from_millis(50),
    max: Duration::from_millis(200),
    max_attempts: None,
};

pub fn run(args: &Args) -> Result<()> {
    let robots = RoleProcess::spawn(args, "robots", &[])?;
    let upstream: Vec<String> = robots.ports.iter().map(u16::to_string).collect();
    let relay = RoleProcess::spawn(args, "relay", &["--upstream".into(), upstream.join(",")])?;
    vanishing_observers(args, &relay)?;
    let listen: Vec<String> = relay.ports.iter().map(u16::to_string).collect();
    let extra = [
        "--upstream".to_string(),
        upstream.join(","),
        "--listen".into(),
        listen.join(","),
    ];
    relay_killed(args, relay, &robots, &extra)
}

/// Rounds of a crowd coming and vanishing: memory the first round leaves with the allocator
/// must be reused by the next, not added to.
const VANISH_ROUNDS: usize = 6;

fn vanishing_observers(args: &Args, relay: &RoleProcess) -> Result<()> {
    let before = relay.sample()?;
    let mib = |b: u64| b as f64 / (1024.0 * 1024.0);
    let mut after_rounds = Vec::new();
    for round in 1..=VANISH_ROUNDS {
        let crowd = connect_observers(
            &relay.ports,
            args.observers,
            SharedWindow::default(),
            SETUP_TIMEOUT,
        )?;
        std::thread::sleep(Duration::from_secs_f64(args.warmup));
        let loaded = relay.sample()?;
        let gone_at = Instant::now();
        crowd.vanish();
        let released = loop {
            let now = relay.sample()?;
            if now.sockets <= before.sockets {
                break now;
            }
            if gone_at.elapsed() > SETUP_TIMEOUT {
                bail!("the relay still holds {} sockets", now.sockets);
            }
            std::thread::sleep(SOCKET_POLL);
        };
        println!(
            "round {round}: {} observers vanish at once: the relay held {} sockets, back to {} \
             after {:.1} ms; RSS {:.1} MiB with them",
            args.observers,
            loaded.sockets,
            released.sockets,
            gone_at.elapsed().as_secs_f64() * 1e3,
            mib(loaded.rss_bytes),
        );
        after_rounds.push(format!("{:.1}", mib(released.rss_bytes)));
    }
    println!(
        "relay RSS {:.1} MiB before any observer, after each round: {} MiB",
        mib(before.rss_bytes),
        after_rounds.join(", ")
    );
    Ok(())
}

/// A `Client` through the relay with a signal on data and state changes.
struct Watcher {
    client: Client,
    woken: Receiver<()>,
}

impl Watcher {
    fn connect(port: u16) -> Result<Watcher> {
        let (wake, woken) = sync_channel(1);
        let options = ClientOptions {
            backoff: OBSERVER_BACKOFF,
            notifier: Some(Arc::new(move || {
                let _ = wake.try_send(());
            })),
            read_only: true,
            ..ClientOptions::default()
        };
        let client = Client::connect("127.0.0.1", port, options)?;
        client.laser(0).subscribe()?;
        Ok(Watcher { client, woken })
    }

    /// Waits for a scan received after `since`; when it came.
    fn fresh_scan(&self, since: Instant, deadline: Instant) -> Option<Instant> {
        loop {
            if let Some((_, stamped)) = self.client.laser(0).scan()
                && stamped.received > since
            {
                return Some(stamped.received);
            }
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() || self.woken.recv_timeout(left).is_err() {
                return None;
            }
        }
    }
}

fn relay_killed(
    args: &Args,
    mut relay: RoleProcess,
    robots: &RoleProcess,
    extra: &[String],
) -> Result<()> {
    let ports = relay.ports.clone();
    let watchers = (0..CLIENT_OBSERVERS)
        .map(|i| Watcher::connect(ports[i % ports.len()]))
        .collect::<Result<Vec<_>>>()?;
    let start = Instant::now();
    for w in &watchers {
        w.fresh_scan(start - Duration::from_secs(1), start + SETUP_TIMEOUT)
            .context("no data before the kill")?;
    }
    let killed = Instant::now();
    relay.child.kill()?;
    let mut noticed = Vec::new();
    for w in &watchers {
        let deadline = killed + SETUP_TIMEOUT;
        w.client
            .wait_until(deadline, |s| *s != ConnectionState::Connected)
            .context("an observer never noticed the relay was gone")?;
        noticed.push(killed.elapsed().as_secs_f64());
    }
    let robot_connections_meanwhile = robots.sample()?.sockets.saturating_sub(args.robots);
    drop(relay);
    let restarted = Instant::now();
    let relay = RoleProcess::spawn(args, "relay", extra)?;
    if relay.ports != ports {
        bail!("the relay came back on {:?}, not {ports:?}", relay.ports);
    }
    let mut recovered = Vec::new();
    for w in &watchers {
        let at = w
            .fresh_scan(restarted, restarted + SETUP_TIMEOUT)
            .context("an observer got no data after the relay came back")?;
        recovered.push(at.saturating_duration_since(restarted).as_secs_f64());
    }
    let robot_connections_after = robots.sample()?.sockets.saturating_sub(args.robots);
    let summary = |v: &[f64]| LatencySummary::of(v).map_or((0.0, 0.0), |s| (s.p50, s.max));
    let (n50, nmax) = summary(&noticed);
    let (r50, rmax) = summary(&recovered);
    println!(
        "relay killed mid-stream with {CLIENT_OBSERVERS} reconnecting Client observers: all \
         noticed within {:.1} ms (p50 {:.1} ms); connections to the robots meanwhile: {}; \
         relay restarted on the same ports: fresh data at every observer after p50 {:.0} ms, \
         max {:.0} ms (backoff {:?}..{:?}; includes starting the relay process); connections \
         to the robots after: {}",
        nmax * 1e3,
        n50 * 1e3,
        robot_connections_meanwhile,
        r50 * 1e3,
        rmax * 1e3,
        OBSERVER_BACKOFF.initial,
        OBSERVER_BACKOFF.max,
        robot_connections_after,
    );
    drop(relay);
    Ok(())
}
