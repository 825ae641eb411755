//! `relay --zenoh`: 8 robots, 1 000 observers, three ways in one run — straight to the robots
//! (the baseline), through `player-relay` alone, and from another "site" through Zenoh: the
//! robots' relay publishes them into Zenoh as a client of one router, and the observers are
//! spread over `--bridges` remote processes (4), each serving every robot found as Player
//! servers (`FromZenoh`, what `player-relay --from-zenoh` runs). Every process is its own, so
//! its CPU is its own; the site's link to the router goes through a counting forwarder, so
//! the bytes that leave the robots' site are measured, not estimated.

use std::time::Duration;

use anyhow::Result;
use bench::clock::{SharedWindow, unix_seconds};
use bench::observers::connect_observers;
use bench::process_stats::ProcessSample;
use bench::recorder::LatencySummary;
use bench::traffic::{DEVICES, bodies};

use crate::roles::RoleProcess;
use crate::uplink::Uplink;
use crate::{Args, DRAIN, SETUP_TIMEOUT};

/// One phase's figures.
struct Phase {
    name: &'static str,
    latency: Option<LatencySummary>,
    /// Messages sent inside the window and received, over the rate's nominal count. The window's
    /// ends fall between a device's messages wherever they fall, so a device can count one more
    /// or one fewer than rate × seconds: 100.1 % is a full delivery, not a duplicate.
    received: f64,
    failed: usize,
    /// (process, CPU seconds per second) for each process of the phase.
    cpu: Vec<(String, f64)>,
    /// Bytes per second from the robots' site to the router, when measured.
    uplink: Option<f64>,
}

fn measure(
    args: &Args,
    name: &'static str,
    ports: &[u16],
    processes: &[(&str, &RoleProcess)],
    uplink: Option<&Uplink>,
) -> Result<Phase> {
    let window = SharedWindow::default();
    let observers = connect_observers(ports, args.observers, window.clone(), SETUP_TIMEOUT)?;
    std::thread::sleep(Duration::from_secs_f64(args.warmup));
    let sample =
        || -> Result<Vec<ProcessSample>> { processes.iter().map(|(_, p)| p.sample()).collect() };
    let (before, up_before) = (sample()?, uplink.map(Uplink::bytes_up));
    let start = unix_seconds();
    window.set(start, start + args.seconds);
    std::thread::sleep(Duration::from_secs_f64(args.seconds));
    let (after, up_after) = (sample()?, uplink.map(Uplink::bytes_up));
    std::thread::sleep(DRAIN);
    let crowd = observers.finish();
    let expected = args.observers as f64 * DEVICES.len() as f64 * args.rate_hz * args.seconds;
    Ok(Phase {
        name,
        latency: LatencySummary::of(&crowd.latencies),
        received: crowd.latencies.len() as f64 / expected,
        failed: crowd.failed,
        cpu: processes
            .iter()
            .zip(before.iter().zip(&after))
            .map(|((what, _), (a, b))| {
                (
                    what.to_string(),
                    (b.cpu_seconds - a.cpu_seconds) / args.seconds,
                )
            })
            .collect(),
        uplink: up_before
            .zip(up_after)
            .map(|(a, b)| (b - a) as f64 / args.seconds),
    })
}

pub fn run(args: &Args) -> Result<()> {
    let robots = RoleProcess::spawn(args, "robots", &[])?;
    let upstream: Vec<String> = robots.ports.iter().map(u16::to_string).collect();
    let upstream = ["--upstream".to_string(), upstream.join(",")];
    eprintln!("{} robots on {:?}", args.robots, robots.ports);
    let direct = measure(args, "direct", &robots.ports, &[("robots", &robots)], None)?;
    let relay = RoleProcess::spawn(args, "relay", &upstream)?;
    let alone = measure(
        args,
        "player-relay alone",
        &relay.ports,
        &[("robots", &robots), ("relay", &relay)],
        None,
    )?;
    drop(relay);

    let router = RoleProcess::spawn(args, "zenoh-router", &[])?;
    let uplink = Uplink::start(router.ports[0])?;
    let to = |port: u16| ["--router".to_string(), port.to_string()];
    let site_args = [&upstream[..], &to(uplink.port())[..]].concat();
    let site = RoleProcess::spawn(args, "zenoh-site", &site_args)?;
    let bridges = (0..args.bridges)
        .map(|_| RoleProcess::spawn(args, "zenoh-bridge", &to(router.ports[0])))
        .collect::<Result<Vec<_>>>()?;
    let ports: Vec<u16> = bridges.iter().flat_map(|b| b.ports.clone()).collect();
    eprintln!(
        "Zenoh: router on {}, the site's uplink through {}, {} bridges serving {} ports",
        router.ports[0],
        uplink.port(),
        bridges.len(),
        ports.len()
    );
    let mut processes = vec![
        ("robots", &robots),
        ("site relay", &site),
        ("router", &router),
    ];
    processes.extend(bridges.iter().map(|b| ("bridge", b)));
    let zenoh = measure(args, "through Zenoh", &ports, &processes, Some(&uplink))?;
    print_report(args, &[direct, alone, zenoh]);
    Ok(())
}

fn print_report(args: &Args, phases: &[Phase]) {
    // One copy of every robot's stream: each message as a Player client receives it.
    let message_bytes: usize = bodies(args.beams)
        .iter()
        .map(|b| player_proto::wire::HEADER_LEN + b.encoded_len())
        .sum();
    let one_copy = message_bytes as f64 * args.robots as f64 * args.rate_hz;
    println!(
        "{} robots (position2d + {}-beam laser at {} Hz), {} observers ({} bridges in the Zenoh phase), {} s window; one copy of every robot's stream: {:.1} kB/s\n",
        args.robots,
        args.beams,
        args.rate_hz,
        args.observers,
        args.bridges,
        args.seconds,
        one_copy / 1e3
    );
    println!(
        "| path | p50 ms | p99 ms | max ms | received | failed | CPU, % of a core | site uplink |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    let ms = |s: f64| s * 1e3;
    for p in phases {
        let (p50, p99, max) = p.latency.map_or((f64::NAN, f64::NAN, f64::NAN), |l| {
            (ms(l.p50), ms(l.p99), ms(l.max))
        });
        let mut cpu: Vec<(String, f64)> = Vec::new();
        for (what, c) in &p.cpu {
            match cpu.iter_mut().find(|(w, _)| w == what) {
                Some((_, sum)) => *sum += c,
                None => cpu.push((what.clone(), *c)),
            }
        }
        let cpu: Vec<String> = cpu
            .iter()
            .map(|(what, c)| format!("{what} {:.1}", c * 100.0))
            .collect();
        let uplink = p.uplink.map_or("—".to_string(), |b| {
            format!("{:.1} kB/s = {:.2} copies", b / 1e3, b / one_copy)
        });
        println!(
            "| {} | {p50:.2} | {p99:.2} | {max:.1} | {:.1} % | {} | {} | {uplink} |",
            p.name,
            p.received * 100.0,
            p.failed,
            cpu.join(", ")
        );
    }
    if let [direct, rest @ ..] = phases
        && let Some(d) = direct.latency
    {
        for p in rest {
            if let Some(l) = p.latency {
                println!(
                    "\nadded {}: p50 {:+.2} ms, p99 {:+.2} ms",
                    p.name,
                    ms(l.p50 - d.p50),
                    ms(l.p99 - d.p99)
                );
            }
        }
    }
}
