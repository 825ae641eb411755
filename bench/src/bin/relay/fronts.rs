//! `relay --fronts`: the relay's fronts under load. The robots publish as in the load phases;
//! one relay carries them to web pages (`--web`) and Foxglove clients (`--foxglove`) at once,
//! while one plain Player observer per robot, connected straight to it, gives the baseline
//! latency of the same messages in the same window.

use std::time::Duration;

use anyhow::Result;
use bench::clock::{SharedWindow, unix_seconds};
use bench::crowd::CrowdReport;
use bench::foxglove_clients::connect_foxglove_clients;
use bench::observers::connect_observers;
use bench::pages::connect_pages;
use bench::recorder::LatencySummary;
use bench::traffic::DEVICES;

use crate::roles::RoleProcess;
use crate::{Args, DRAIN, SETUP_TIMEOUT};

pub fn run(args: &Args) -> Result<()> {
    let robots = RoleProcess::spawn(args, "robots", &[])?;
    let upstream: Vec<String> = robots.ports.iter().map(u16::to_string).collect();
    let relay = RoleProcess::spawn(args, "relay", &["--upstream".into(), upstream.join(",")])?;
    // The relay announces its robots' ports, then the page's and the Foxglove server's.
    let [.., web, foxglove] = relay.ports[..] else {
        anyhow::bail!("the relay announced no fronts: {:?}", relay.ports);
    };
    eprintln!(
        "{} robots on {:?}; the relay's page on {web}, Foxglove on {foxglove}; {} pages, {} Foxglove clients",
        args.robots, robots.ports, args.pages, args.foxglove_clients
    );
    let (r0, q0) = (robots.sample()?, relay.sample()?);
    std::thread::sleep(Duration::from_secs_f64(args.warmup));
    let (r1, q1) = (robots.sample()?, relay.sample()?);
    let idle_relay = (q1.cpu_seconds - q0.cpu_seconds) / args.warmup;
    let idle_robots = (r1.cpu_seconds - r0.cpu_seconds) / args.warmup;

    let window = SharedWindow::default();
    let direct = connect_observers(
        &robots.ports,
        robots.ports.len(),
        window.clone(),
        SETUP_TIMEOUT,
    )?;
    // Either crowd may be left out (0) to see one front's cost alone.
    let pages = (args.pages > 0)
        .then(|| connect_pages(web, args.pages, window.clone(), SETUP_TIMEOUT))
        .transpose()?;
    let foxglove_clients = (args.foxglove_clients > 0)
        .then(|| {
            connect_foxglove_clients(
                foxglove,
                args.foxglove_clients,
                window.clone(),
                SETUP_TIMEOUT,
            )
        })
        .transpose()?;
    std::thread::sleep(Duration::from_secs_f64(args.warmup));
    let (r2, q2) = (robots.sample()?, relay.sample()?);
    let start = unix_seconds();
    window.set(start, start + args.seconds);
    std::thread::sleep(Duration::from_secs_f64(args.seconds));
    let (r3, q3) = (robots.sample()?, relay.sample()?);
    std::thread::sleep(DRAIN);
    let direct = direct.finish();
    let pages = pages.map(|c| c.finish()).unwrap_or_default();
    let foxglove_clients = foxglove_clients.map(|c| c.finish()).unwrap_or_default();

    let per_second = |a: f64, b: f64| (b - a) / args.seconds;
    let per_client = (args.robots * DEVICES.len()) as f64 * args.rate_hz * args.seconds;
    println!(
        "{} robots (position2d + {}-beam laser at {} Hz), {} s window; idle: robots {:.1} %, relay {:.1} % of a core (surveying, no clients)\n",
        args.robots,
        args.beams,
        args.rate_hz,
        args.seconds,
        idle_robots * 100.0,
        idle_relay * 100.0
    );
    println!("| clients | count | p50 ms | p99 ms | max ms | received | failed |");
    println!("|---|---|---|---|---|---|---|");
    let row = |name: &str, count: usize, crowd: &CrowdReport, expected: f64| {
        if count == 0 {
            return None;
        }
        let ms = |s: f64| s * 1e3;
        let l = LatencySummary::of(&crowd.latencies);
        let (p50, p99, max) = l.map_or((f64::NAN, f64::NAN, f64::NAN), |l| {
            (ms(l.p50), ms(l.p99), ms(l.max))
        });
        println!(
            "| {name} | {count} | {p50:.2} | {p99:.2} | {max:.1} | {:.1} % | {} |",
            100.0 * crowd.latencies.len() as f64 / expected,
            crowd.failed
        );
        l
    };
    // A direct observer watches one robot; a page watches them all.
    let d = row(
        "Player, straight to its robot",
        robots.ports.len(),
        &direct,
        robots.ports.len() as f64 * DEVICES.len() as f64 * args.rate_hz * args.seconds,
    );
    let p = row(
        "web page, through the relay",
        args.pages,
        &pages,
        args.pages as f64 * per_client,
    );
    let f = row(
        "Foxglove client, through the relay",
        args.foxglove_clients,
        &foxglove_clients,
        args.foxglove_clients as f64 * per_client,
    );
    println!(
        "\nrelay: {:.1} % of a core, RSS {:.1} → {:.1} MiB with the clients; robots {:.1} % of a core",
        per_second(q2.cpu_seconds, q3.cpu_seconds) * 100.0,
        q1.rss_bytes as f64 / 1048576.0,
        q3.rss_bytes as f64 / 1048576.0,
        per_second(r2.cpu_seconds, r3.cpu_seconds) * 100.0,
    );
    for (front, l) in [("web page", p), ("Foxglove server", f)] {
        if let (Some(d), Some(l)) = (d, l) {
            println!(
                "added by the relay's {front}: p50 {:+.2} ms, p99 {:+.2} ms",
                (l.p50 - d.p50) * 1e3,
                (l.p99 - d.p99) * 1e3
            );
        }
    }
    Ok(())
}
