//! Subscribes every robot's laser of a player-sim (or Player) server run on its own, so that
//! the server's own CPU can be measured with every laser scanned (player-sim scans a laser
//! only while a client subscribes to it). Keeps the subscriptions for SECONDS, then reports
//! how far the newest scan id advanced on the slowest client.
//!
//! `cargo run --release -p player-sim --example subscribe_all -- ROBOTS [SECONDS] [FIRST_PORT] [--pose]`
//! e.g. with `player-sim stage-worlds/swarm1024.world` running: `-- 1024 60`. With `--pose`
//! each client also subscribes to its robot's position2d, as a viewer does.

use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use player_proto::client::{Client, ClientOptions};

fn main() -> Result<()> {
    let mut args = std::env::args().skip(1);
    let robots: u16 = args.next().context("ROBOTS")?.parse()?;
    let seconds: f64 = args.next().map_or(Ok(60.0), |s| s.parse())?;
    let first: u16 = args.next().map_or(Ok(6665), |s| s.parse())?;
    let pose = match args.next().as_deref() {
        None => false,
        Some("--pose") => true,
        Some(other) => anyhow::bail!("expected --pose after FIRST_PORT, got {other:?}"),
    };
    let mut clients = Vec::new();
    for port in first..first + robots {
        let client = Client::connect("127.0.0.1", port, ClientOptions::default())
            .with_context(|| format!("connecting to {port}"))?;
        client.laser(0).subscribe()?;
        if pose {
            client.position2d(0).subscribe()?;
        }
        clients.push(client);
    }
    let scan_id = |c: &Client| c.laser(0).scan().map_or(0, |(s, _)| s.id);
    std::thread::sleep(Duration::from_secs(2));
    let ids: Vec<u32> = clients.iter().map(scan_id).collect();
    println!("{} lasers subscribed", clients.len());
    let started = Instant::now();
    std::thread::sleep(Duration::from_secs_f64(seconds));
    let elapsed = started.elapsed().as_secs_f64();
    let slowest = clients
        .iter()
        .zip(&ids)
        .map(|(c, &before)| scan_id(c).saturating_sub(before))
        .min()
        .unwrap_or(0);
    println!("newest scan advanced by at least {slowest} per client in {elapsed:.1} s");
    Ok(())
}
