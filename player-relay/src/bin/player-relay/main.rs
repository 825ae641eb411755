//! `player-relay ROBOT…` — serve Player robots to many observers over one connection per
//! robot. Each ROBOT is `HOST:PORT` (observers connect to PORT + `--port-offset` on the relay)
//! or `HOST:PORT=LISTEN`, and may be named for the fronts: `HOST:PORT=NAME`,
//! `HOST:PORT=LISTEN=NAME`.

use std::net::IpAddr;
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Duration;

use anyhow::{Context, Result, bail};
use clap::Parser;
use player_foxglove::live::FoxgloveLive;
use player_front::Front;
use player_proto::RobotId;
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
    /// Robot servers, `HOST:PORT` or `HOST:PORT=LISTEN`; `=NAME` after either names the robot
    /// on the web page, in Foxglove and in Zenoh (else it is `HOST:PORT` there).
    #[arg(required_unless_present_any = ["demo", "world", "from_zenoh"], value_parser = parse_robot)]
    robots: Vec<(RobotId, Option<u16>)>,

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

    /// Also in ROS 2: each robot a ROS 2 node over DDS (its scans, odometry, /tf, map out;
    /// cmd_vel, goal_pose and initialpose in, unless --ros2-read-only). See docs/ROS2.md.
    #[arg(long)]
    ros2: bool,

    /// The ROS 2 domain, 0 to 232; by default ROS_DOMAIN_ID, else 0.
    #[arg(long, requires = "ros2")]
    ros_domain: Option<u16>,

    /// ROS 2 only reads: no command from it reaches a robot.
    #[arg(long, requires = "ros2")]
    ros2_read_only: bool,

    /// cmd_vel from ROS 2 is a geometry_msgs/TwistStamped (Jazzy's Nav2 and teleop), not a Twist.
    #[arg(long, requires = "ros2", conflicts_with = "ros2_read_only")]
    ros2_twist_stamped: bool,

    #[command(flatten)]
    zenoh: zenoh::ZenohArgs,

    /// Stop after this many seconds (default: run until killed).
    #[arg(long, value_name = "SECONDS")]
    seconds: Option<f64>,
}

/// `HOST:PORT`, with `=LISTEN` (a port number) and `=NAME` (anything else) after it, either or
/// both (`HOST:PORT=LISTEN=NAME`).
fn parse_robot(text: &str) -> Result<(RobotId, Option<u16>), String> {
    let mut parts = text.split('=');
    let server = parts.next().unwrap_or_default();
    let (mut listen, mut name) = (None, None);
    for part in parts {
        if !part.is_empty() && part.chars().all(|c| c.is_ascii_digit()) {
            let port = part
                .parse::<u16>()
                .map_err(|_| format!("bad listen port {part:?} in {text:?}"))?;
            if listen.replace(port).is_some() {
                return Err(format!("two listen ports in {text:?}"));
            }
        } else if name.replace(part).is_some() {
            return Err(format!("two names in {text:?}"));
        }
    }
    let robot = server.parse::<RobotId>().map_err(|e| e.to_string())?;
    let robot = match name {
        Some(name) => robot.named(name).map_err(|e| e.to_string())?,
        None => robot,
    };
    Ok((robot, listen))
}

fn main() -> ExitCode {
    // RustDDS (--ros2) warns of every sample a peer's unreachable locator did not take: not news.
    // Its discovery calls /clock inconsistent once our Clock writer is announced: every
    // ros2-client node reads /clock under builtin_interfaces/Time's name.
    program_edge::logging::init(
        "info,rustdds=error,rustdds::discovery::discovery_db=off,ros2_client=error",
    );
    program_edge::exit::exit_code("player-relay", run(Cli::parse()))
}

fn run(cli: Cli) -> Result<()> {
    if cli.seconds.is_some_and(|s| !(0.0..=1e9).contains(&s)) {
        bail!("--seconds must be from 0 to 1e9");
    }
    // A simulation's time, for ROS 2's /clock.
    let clock = cli.ros2.then(player_ros2::live::SimClock::new);
    let demo = match (&cli.world, cli.demo) {
        (Some(world), _) => Some(demo::serve(world, clock.clone())?),
        (None, true) => Some(demo::serve(&demo::world_file(), clock.clone())?),
        (None, false) => None,
    };
    let mut robots = cli.robots;
    if let Some(demo) = &demo {
        // The demo's ports are wherever the system put them: observers get free ports too.
        robots = demo.robots.iter().map(|id| (id.clone(), Some(0))).collect();
    }
    let mut routes = Vec::new();
    for (robot, listen) in robots {
        let listen_port = match listen {
            Some(listen) => listen,
            None => robot.port().checked_add(cli.port_offset).ok_or_else(|| {
                anyhow::anyhow!(
                    "{} + --port-offset {} is past the last port",
                    robot.server(),
                    cli.port_offset
                )
            })?,
        };
        routes.push(Route { robot, listen_port });
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
            "{} → {}:{}",
            said(&route.robot),
            cli.bind,
            route.listen_port
        );
    }
    // One runtime for every front (the page, Foxglove, Zenoh), not one each.
    let runtime = fronts_runtime()?;
    let mut fronts: Vec<Arc<dyn Front>> = Vec::new();
    // Held by the relay too, which stops them once its robots have stopped.
    let foxglove = match cli.foxglove {
        Some(port) => {
            let live = Arc::new(FoxgloveLive::start_on(
                runtime.handle().clone(),
                cli.bind,
                port,
            )?);
            eprintln!("Foxglove WebSocket → ws://{}:{}", cli.bind, live.port());
            fronts.push(live.clone());
            Some(live)
        }
        None => None,
    };
    let web = match cli.web {
        Some(port) => {
            let web = Arc::new(player_web::WebFront::start_on(
                runtime.handle().clone(),
                cli.bind,
                port,
                commanders,
            )?);
            if let Some(demo) = &demo {
                web.set_walls(&player_relay::world::walls(&demo.world));
            }
            eprintln!("web page: http://{}:{}/", cli.bind, web.port());
            fronts.push(web.clone());
            Some(web)
        }
        None => None,
    };
    let zenoh = cli.zenoh.start(runtime.handle(), cli.bind, commanders)?;
    if let Some(front) = &zenoh.front {
        fronts.push(front.clone());
    }
    if cli.ros2 {
        let domain = player_ros2::live::domain(cli.ros_domain)?;
        let commands = match (cli.ros2_read_only, cli.ros2_twist_stamped) {
            (true, _) => player_ros2::live::Commands::ReadOnly,
            (false, true) => player_ros2::live::Commands::TwistStamped,
            (false, false) => player_ros2::live::Commands::Twist,
        };
        let clock = clock.filter(|_| demo.is_some());
        let front = Arc::new(player_ros2::live::Ros2Front::start(
            domain, commands, clock,
        )?);
        eprintln!(
            "ROS 2 → domain {domain}{}",
            if cli.ros2_read_only {
                ", read-only"
            } else {
                ""
            }
        );
        fronts.push(front);
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
            fronts_command: cli.zenoh.fronts_command() || (cli.ros2 && !cli.ros2_read_only),
            ..RelayConfig::default()
        })?),
    };
    if let Some(relay) = relay.as_ref().filter(|_| demo.is_some()) {
        relay.wait_serving(Duration::from_secs(5));
        for robot in relay.robots() {
            if let Some(port) = robot.listen_port() {
                eprintln!("{} → {}:{port}", said(robot.id()), cli.bind);
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
    // The relay stops its robots, then its fronts, then their runtime; the simulation goes
    // last.
    drop(relay);
    drop((zenoh, web, foxglove));
    runtime.shutdown_background();
    drop(demo);
    Ok(())
}

/// The runtime the fronts share ([`player_front::shared_runtime`]).
fn fronts_runtime() -> Result<tokio::runtime::Runtime> {
    player_front::shared_runtime().context("cannot start the fronts' runtime")
}

/// `HOST:PORT`, or `NAME (HOST:PORT)` for a named robot.
fn said(robot: &RobotId) -> String {
    match robot.name() {
        Some(name) => format!("{name} ({})", robot.server()),
        None => robot.server(),
    }
}

#[cfg(test)]
mod tests {
    use super::parse_robot;

    #[test]
    fn a_robot_may_be_given_a_listen_port_a_name_or_both() {
        let parsed = |text| parse_robot(text).map(|(id, listen)| (id.to_string(), listen));
        assert_eq!(parsed("h:6665"), Ok(("h:6665".into(), None)));
        assert_eq!(parsed("h:6665=7000"), Ok(("h:6665".into(), Some(7000))));
        assert_eq!(parsed("h:6665=r0"), Ok(("r0".into(), None)));
        assert_eq!(parsed("h:6665=7000=r0"), Ok(("r0".into(), Some(7000))));
        assert_eq!(parsed("h:6665=r0=7000"), Ok(("r0".into(), Some(7000))));
        for wrong in [
            "h:6665=1=2",
            "h:6665=a=b",
            "h:6665=99999",
            "h",
            "h:6665=a b",
        ] {
            assert!(parse_robot(wrong).is_err(), "{wrong}");
        }
    }
}
