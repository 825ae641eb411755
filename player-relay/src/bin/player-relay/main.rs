//! `player-relay ROBOT…` — serve Player robots to many observers over one connection per
//! robot. Each ROBOT is `HOST:PORT` (observers connect to PORT + `--port-offset` on the relay)
//! or `HOST:PORT=LISTEN`.

use std::net::IpAddr;
use std::process::ExitCode;
use std::time::Duration;

use anyhow::{Result, bail};
use clap::Parser;
use player_foxglove::live::FoxgloveLive;
use player_proto::server::Commanders;
use player_relay::{DEFAULT_SEND_BUFFER, Relay, RelayConfig, Route};

mod demo;
mod zenoh;

/// Where observers of a robot on port P connect by default, when the relay shares the robots'
/// machine: P + 1000 (6665 → 7665).
const DEFAULT_PORT_OFFSET: u16 = 1000;

/// Serve Player robots to many read-only observers, with one connection per robot.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// Robot servers, `HOST:PORT` or `HOST:PORT=LISTEN`.
    #[arg(required_unless_present_any = ["demo", "world", "from_zenoh"], value_parser = parse_robot)]
    robots: Vec<(String, u16, Option<u16>)>,

    /// Relay the demo's robots instead: stage-worlds/multirobot.world simulated in-process by
    /// player-sim on free ports (no Player server needed).
    #[arg(long, conflicts_with = "robots")]
    demo: bool,

    /// Relay the robots of this Stage world, simulated in-process by player-sim on free ports
    /// (`--demo` is stage-worlds/multirobot.world).
    #[arg(long, value_name = "WORLD", conflicts_with_all = ["robots", "demo"])]
    world: Option<std::path::PathBuf>,

    /// Address observers connect to (0.0.0.0 for every interface).
    #[arg(long, default_value = "127.0.0.1")]
    bind: IpAddr,

    /// Listen on PORT + this for a robot given as `HOST:PORT` (0 when the relay runs on a
    /// machine of its own).
    #[arg(long, default_value_t = DEFAULT_PORT_OFFSET)]
    port_offset: u16,

    /// Clients from this address may command the robots; everyone else only observes.
    #[arg(long, value_name = "IP", conflicts_with = "first_to_command")]
    controller: Option<IpAddr>,

    /// The first client to command a robot's devices controls it until it disconnects.
    #[arg(long)]
    first_to_command: bool,

    /// Kernel send buffer per observer, bytes: what a slow observer may have waiting.
    #[arg(long, default_value_t = DEFAULT_SEND_BUFFER)]
    send_buffer: usize,

    /// Serve a live web page of the robots at http://BIND:PORT/ (the controller may drive
    /// from it; everyone else watches).
    #[arg(long, value_name = "PORT")]
    web: Option<u16>,

    /// Also serve every robot to Foxglove Studio and Lichtblick over the Foxglove WebSocket
    /// protocol on this port (on --bind): ws://HOST:PORT.
    #[arg(long, value_name = "PORT")]
    foxglove: Option<u16>,

    #[command(flatten)]
    zenoh: zenoh::ZenohArgs,

    /// Stop after this many seconds (default: run until killed).
    #[arg(long, value_name = "SECONDS")]
    seconds: Option<f64>,
}

fn parse_robot(text: &str) -> Result<(String, u16, Option<u16>), String> {
    let (server, listen) = match text.split_once('=') {
        Some((server, listen)) => {
            let listen = listen
                .parse::<u16>()
                .map_err(|_| format!("bad listen port {listen:?} in {text:?}"))?;
            (server, Some(listen))
        }
        None => (text, None),
    };
    let (host, port) = server
        .rsplit_once(':')
        .ok_or_else(|| format!("expected HOST:PORT[=LISTEN], got {text:?}"))?;
    let port = port
        .parse::<u16>()
        .map_err(|_| format!("bad port {port:?} in {text:?}"))?;
    if host.is_empty() {
        return Err(format!("no host in {text:?}"));
    }
    Ok((host.to_string(), port, listen))
}

fn main() -> ExitCode {
    program_edge::logging::init("info");
    program_edge::exit::exit_code("player-relay", run(Cli::parse()))
}

fn run(cli: Cli) -> Result<()> {
    if cli.seconds.is_some_and(|s| !(0.0..=1e9).contains(&s)) {
        bail!("--seconds must be from 0 to 1e9");
    }
    let demo = match (&cli.world, cli.demo) {
        (Some(world), _) => Some(demo::serve(world)?),
        (None, true) => Some(demo::serve(&demo::world_file())?),
        (None, false) => None,
    };
    let mut robots = cli.robots;
    if let Some(demo) = &demo {
        // The demo's ports are wherever the system put them: observers get free ports too.
        robots = demo
            .ports
            .iter()
            .map(|&(_, port)| ("127.0.0.1".to_string(), port, Some(0)))
            .collect();
    }
    let mut routes = Vec::new();
    for (host, port, listen) in robots {
        let listen_port = match listen {
            Some(listen) => listen,
            None => port.checked_add(cli.port_offset).ok_or_else(|| {
                anyhow::anyhow!(
                    "{host}:{port} + --port-offset {} is past the last port",
                    cli.port_offset
                )
            })?,
        };
        routes.push(Route {
            host,
            port,
            listen_port,
        });
    }
    let commanders = match (cli.controller, cli.first_to_command) {
        (Some(ip), _) => Commanders::Address(ip),
        (None, true) => Commanders::FirstToAsk,
        (None, false) => Commanders::Nobody,
    };
    // Before anything else starts: a relay that cannot listen says why, and only that.
    player_relay::check_listen_ports(cli.bind, &routes)?;
    for route in routes.iter().filter(|r| r.listen_port != 0) {
        eprintln!(
            "{}:{} → {}:{}",
            route.host, route.port, cli.bind, route.listen_port
        );
    }
    let mut fronts = Vec::new();
    // Declared before the relay, so dropped after it: no robot thread outlives its front.
    let foxglove = match cli.foxglove {
        Some(port) => {
            let live = FoxgloveLive::start(cli.bind, port)?;
            eprintln!("Foxglove WebSocket → ws://{}:{}", cli.bind, live.port());
            fronts.push(live.tap());
            Some(live)
        }
        None => None,
    };
    let web = match cli.web {
        Some(port) => {
            let web = player_web::WebFront::start(cli.bind, port, commanders)?;
            eprintln!("web page: http://{}:{}/", cli.bind, web.port());
            fronts.push(web.tap());
            Some(web)
        }
        None => None,
    };
    let zenoh = cli.zenoh.start(cli.bind, commanders)?;
    if let Some(front) = &zenoh.front {
        fronts.push(front.tap());
    }
    // With --from-zenoh alone there is nothing to relay from here.
    let relay = match routes.is_empty() && zenoh.bridge.is_some() {
        true => None,
        false => Some(Relay::start(RelayConfig {
            routes,
            bind: cli.bind,
            commanders,
            send_buffer: cli.send_buffer,
            fronts,
            fronts_command: cli.zenoh.fronts_command(),
            ..RelayConfig::default()
        })?),
    };
    let robots = relay.as_ref().map_or(&[][..], Relay::robots);
    if let Some(web) = &web {
        for robot in robots {
            web.add_robot(robot.upstream().clone());
        }
    }
    if let Some(relay) = &relay {
        zenoh.add_robots(relay);
    }
    if let Some(relay) = relay.as_ref().filter(|_| demo.is_some()) {
        relay.wait_serving(Duration::from_secs(5));
        for robot in relay.robots() {
            let upstream = robot.upstream();
            if let Some(port) = robot.listen_port() {
                eprintln!(
                    "{}:{} → {}:{port}",
                    upstream.host(),
                    upstream.port(),
                    cli.bind
                );
            }
        }
    }
    match cli.seconds {
        Some(seconds) => std::thread::sleep(Duration::from_secs_f64(seconds)),
        // Serves until killed; the relay's own threads do the work.
        None => loop {
            std::thread::park();
        },
    }
    drop(relay);
    drop(zenoh);
    drop(web);
    drop(demo);
    drop(foxglove);
    Ok(())
}
