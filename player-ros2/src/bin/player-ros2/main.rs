//! `player-ros2 HOST:PORT[=NAME]...`: Player robots as ROS 2 nodes over DDS. Each robot is a
//! Player client here; its data goes out on its ROS 2 topics, and its `cmd_vel` drives its base
//! (unless `--read-only`). See docs/ROS2.md.

mod bridge;

use std::process::ExitCode;

use clap::Parser;
use player_proto::RobotId;
use player_ros2::live::Commands;

/// Player robots as ROS 2 nodes: scans, odometry, /tf and more out, cmd_vel in.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// The robots: HOST:PORT, or HOST:PORT=NAME for its ROS 2 namespace (else HOST_PORT).
    #[arg(required = true, value_name = "HOST:PORT[=NAME]")]
    robots: Vec<RobotId>,

    /// The ROS 2 domain, 0 to 232; by default ROS_DOMAIN_ID, else 0.
    #[arg(long)]
    ros_domain: Option<u16>,

    /// Publish only: no cmd_vel reaches a robot.
    #[arg(long)]
    read_only: bool,

    /// cmd_vel is a geometry_msgs/TwistStamped (Jazzy's Nav2 and teleop), not a Twist.
    #[arg(long, conflicts_with = "read_only")]
    twist_stamped: bool,
}

fn commands(cli: &Cli) -> Commands {
    match (cli.read_only, cli.twist_stamped) {
        (true, _) => Commands::ReadOnly,
        (false, true) => Commands::TwistStamped,
        (false, false) => Commands::Twist,
    }
}

fn main() -> ExitCode {
    // RustDDS warns of every sample a peer's unreachable locator did not take, and
    // ros2-client tells of every topic it makes: not news to a person running a bridge.
    program_edge::logging::init("info,rustdds=error,ros2_client=error");
    let cli = Cli::parse();
    let result = player_ros2::live::domain(cli.ros_domain)
        .map_err(anyhow::Error::from)
        .and_then(|d| bridge::run(&cli.robots, d, commands(&cli)));
    program_edge::exit::exit_code("player-ros2", result)
}
