//! The Zenoh benchmark's processes, each this binary again with `--role`: a Zenoh router, the
//! robots' site (a relay publishing them into Zenoh, as `player-relay --zenoh` does) and
//! remote bridges (each serving every robot found as Player servers, as `player-relay
//! --from-zenoh` does). Loopback only, scouting off: every session reaches exactly the
//! endpoint it is given.

use anyhow::{Result, bail};
use player_relay::{Relay, RelayConfig, Route};
use player_zenoh::{FromZenoh, FromZenohConfig, FrontConfig, Mode, ZenohFront, ZenohOptions};

use crate::roles::{announce, until_stdin_closes};
use crate::{Args, SETUP_TIMEOUT};

/// The site every robot is published under.
pub const SITE: &str = "bench";

fn tcp(port: u16) -> String {
    format!("tcp/127.0.0.1:{port}")
}

fn session(
    mode: Mode,
    listen: Option<u16>,
    connect: Option<u16>,
) -> Result<player_zenoh::zenoh::Session> {
    Ok(ZenohOptions {
        mode: Some(mode),
        listen: listen.map(tcp).into_iter().collect(),
        connect: connect.map(tcp).into_iter().collect(),
        no_scouting: true,
        ..ZenohOptions::default()
    }
    .open()?)
}

/// A router on a free port, which it announces.
pub fn serve_router() -> Result<()> {
    let port = std::net::TcpListener::bind("127.0.0.1:0")?
        .local_addr()?
        .port();
    let _router = session(Mode::Router, Some(port), None)?;
    announce(&[port])?;
    until_stdin_closes();
    Ok(())
}

/// The robots' site: a relay with a Zenoh front, a client of the router at `--router`.
pub fn serve_site(args: &Args) -> Result<()> {
    let front = std::sync::Arc::new(ZenohFront::start(
        session(Mode::Client, None, Some(args.router))?,
        FrontConfig::new(SITE),
    )?);
    let routes = args
        .upstream
        .iter()
        .map(|&port| Route::loopback(port))
        .collect();
    let relay = Relay::start(RelayConfig {
        routes,
        fronts: vec![front.clone() as _],
        ..RelayConfig::default()
    })?;
    let start = std::time::Instant::now();
    while front.announced() < args.upstream.len() {
        if start.elapsed() > SETUP_TIMEOUT {
            bail!(
                "the site announced {} of {} robots in Zenoh",
                front.announced(),
                args.upstream.len()
            );
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let ports: Vec<u16> = relay
        .robots()
        .iter()
        .filter_map(|r| r.listen_port())
        .collect();
    announce(&ports)?;
    until_stdin_closes();
    if front.dropped() > 0 {
        eprintln!(
            "the site's Zenoh front dropped {} messages",
            front.dropped()
        );
    }
    Ok(())
}

/// A remote bridge: every robot of the site served on free ports, announced once all are.
pub fn serve_bridge(args: &Args) -> Result<()> {
    let bridge = FromZenoh::start(
        session(Mode::Client, None, Some(args.router))?,
        FromZenohConfig::new(SITE, "observers"),
    )?;
    let found = bridge.wait_for_robots(args.robots, SETUP_TIMEOUT);
    if found.len() < args.robots {
        bail!("a bridge found {} of {} robots", found.len(), args.robots);
    }
    let ports: Vec<u16> = found.iter().map(|(_, port)| *port).collect();
    announce(&ports)?;
    until_stdin_closes();
    Ok(())
}
