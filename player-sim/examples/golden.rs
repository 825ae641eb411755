//! Measures a Player server simulating a Stage world — real Player + Stage, or player-sim — for
//! player-sim's golden tests (`player-sim/golden/measure.sh` runs it; see golden/README.md).
//!
//! ```text
//! golden pick WORLD                       the first robot with a ranger: "NAME RANGERS"
//! golden plan WORLD ROBOT COUNT SEED        poses where ROBOT stands clear, one "x y a" a line
//! golden read PORT ROBOT RANGERS POSES      ROBOT placed at each pose (simulation:0), then the
//!                                           ranges of ranger:0..RANGERS: one JSON line a pose
//! golden drive PORT ROBOT "x y a" VX VA STEPS
//!                                           ROBOT placed, driven at (VX, VA) for about STEPS
//!                                           steps: its true pose at the simulated times
//!                                           sampled on the way, one JSON line
//! golden odom PORT INDEX "vx vy va" STEPS   position2d:INDEX commanded at (vx, vy, va) for about
//!                                           STEPS steps: the pose it reports at each step,
//!                                           from one before the command, one JSON line
//! golden goto PORT ROBOT INDEX "x y a" STEPS
//!                                           position2d:INDEX sent to (x, y, a) (position
//!                                           control): ROBOT's true pose sampled, one JSON line
//! ```
//! `plan` reads the world with player-sim's own loader; the others are Player clients.

use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::common::{Pose2d, Pose3d};
use player_proto::interfaces::simulation::{
    Simulation as SimMsg, SimulationPose2d, SimulationPose3d,
};
use player_proto::message::Body;
use player_proto::wire::{Interface, PlayerString};
use player_sim::sim::{Simulation, ranger_scan};
use player_sim::world::{Pose, World};

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let a: Vec<&str> = args.iter().map(String::as_str).collect();
    match a.as_slice() {
        ["pick", world] => pick(world),
        ["plan", world, robot, count, seed] => plan(world, robot, count.parse()?, seed.parse()?),
        ["read", port, robot, rangers, poses] => {
            read(port.parse()?, robot, rangers.parse()?, poses)
        }
        ["drive", port, robot, start, vx, va, steps] => drive(
            port.parse()?,
            robot,
            parse_pose(start)?,
            (vx.parse()?, va.parse()?),
            steps.parse()?,
        ),
        ["odom", port, index, command, steps] => odom(
            port.parse()?,
            index.parse()?,
            parse_pose(command)?,
            steps.parse()?,
        ),
        ["goto", port, robot, index, goal, steps] => goto(
            port.parse()?,
            robot,
            index.parse()?,
            parse_pose(goal)?,
            steps.parse()?,
        ),
        _ => bail!("usage: see the top of player-sim/examples/golden.rs"),
    }
}

fn parse_pose(text: &str) -> Result<Pose> {
    let n: Vec<f64> = text
        .split_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .with_context(|| format!("a pose {text:?}"))?;
    match n.as_slice() {
        [x, y, a] => Ok(Pose {
            x: *x,
            y: *y,
            a: *a,
        }),
        _ => bail!("a pose is \"x y a\", not {text:?}"),
    }
}

/// A small deterministic generator (xorshift64*), so that a seed gives the same poses.
struct Draw(u64);

impl Draw {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn pick(world: &str) -> Result<()> {
    let world = World::load(std::path::Path::new(world))?;
    let robot = world
        .robots
        .iter()
        .find(|r| !r.rangers.is_empty())
        .context("no robot with a ranger")?;
    println!("{} {}", robot.name, robot.rangers.len());
    Ok(())
}

/// Poses where `robot` stands at least 0.5 m from anything its rangers see, within the
/// floorplan (or 8 m of where it starts), and prints them with the rangers' count.
fn plan(world: &str, robot: &str, count: usize, seed: u64) -> Result<()> {
    let mut world = World::load(std::path::Path::new(world))?;
    for r in &mut world.robots {
        r.controller = None;
    }
    let mut sim = Simulation::new(world);
    let i = sim.robot_index(robot).context("no such robot")?;
    let start = sim.robots[i].pose;
    let (low, high) = match &sim.world.floor {
        Some(g) => (
            g.origin,
            (
                g.origin.0 + g.width as f64 * g.cell.0,
                g.origin.1 + g.height as f64 * g.cell.1,
            ),
        ),
        None => (
            (start.x - 8.0, start.y - 8.0),
            (start.x + 8.0, start.y + 8.0),
        ),
    };
    let rangers = sim.world.robots[i].rangers.clone();
    let mut draw = Draw(seed.wrapping_mul(2_654_435_761).max(1));
    let mut found = 0;
    for _ in 0..200_000 {
        if found == count {
            break;
        }
        let pose = Pose {
            x: low.0 + draw.unit() * (high.0 - low.0),
            y: low.1 + draw.unit() * (high.1 - low.1),
            a: (draw.unit() * 2.0 - 1.0) * std::f64::consts::PI,
        };
        let pose = Pose {
            x: (pose.x * 1000.0).round() / 1000.0,
            y: (pose.y * 1000.0).round() / 1000.0,
            a: (pose.a * 1000.0).round() / 1000.0,
        };
        sim.robots[i].pose = pose;
        let floor_free = sim.world.floor.as_ref().is_none_or(|g| {
            (0..16).all(|k| {
                let t = k as f64 * std::f64::consts::TAU / 16.0;
                g.raycast(pose.x, pose.y, t, 0.6).is_none() && !g.occupied_at(pose.x, pose.y)
            })
        });
        let clear = floor_free
            && rangers.iter().all(|r| {
                ranger_scan(&sim, i, r)
                    .iter()
                    .all(|&d| d >= 0.5 || d.is_nan())
            });
        if clear {
            println!("{} {} {}", pose.x, pose.y, pose.a);
            found += 1;
        }
    }
    eprintln!("{found} poses; {} rangers", rangers.len());
    Ok(())
}

fn connect(port: u16) -> Result<Client> {
    let options = ClientOptions {
        request_timeout: Duration::from_secs(10),
        ..ClientOptions::default()
    };
    Client::connect("127.0.0.1", port, options).with_context(|| format!("connecting to {port}"))
}

fn set_pose(client: &Client, robot: &str, pose: Pose) -> Result<()> {
    let body = Body::Simulation(SimMsg::SetPose2d(SimulationPose2d {
        name: PlayerString::new(robot),
        pose: Pose2d::new(pose.x, pose.y, pose.a),
    }));
    client.request(
        client.addr(Interface::SIMULATION, 0),
        SimMsg::REQ_SET_POSE2D.subtype(),
        body,
    )?;
    Ok(())
}

/// The robot's true pose (x, y, yaw) and the simulated time, as GET_POSE3D tells them.
fn true_pose3d(client: &Client, robot: &str) -> Result<([f64; 3], f64)> {
    let body = Body::Simulation(SimMsg::Pose3d(SimulationPose3d {
        name: PlayerString::new(robot),
        pose: Pose3d::default(),
        simtime: 0.0,
    }));
    let addr = client.addr(Interface::SIMULATION, 0);
    let reply = client.request(addr, SimMsg::REQ_GET_POSE3D.subtype(), body)?;
    match reply.body {
        Body::Simulation(SimMsg::Pose3d(p)) => {
            // Stage tells microseconds.
            Ok(([p.pose.px, p.pose.py, p.pose.pyaw], p.simtime / 1e6))
        }
        other => bail!("GET_POSE3D answered {other:?}"),
    }
}

/// The newest odometry's server time, waiting up to 10 s for one.
/// The robot's true pose and the simulated time, `[t, x, y, a]`, sampled again and again for
/// `span` simulated seconds (or `limit` wall seconds): one sample per simulated time.
fn true_poses(client: &Client, robot: &str, span: f64, limit: u64) -> Result<Vec<[f64; 4]>> {
    let mut samples: Vec<[f64; 4]> = Vec::new();
    let deadline = Instant::now() + Duration::from_secs(limit);
    while Instant::now() < deadline {
        let (pose, time) = true_pose3d(client, robot)?;
        if samples.last().is_some_and(|s| time <= s[0]) {
            continue;
        }
        samples.push([time, pose[0], pose[1], pose[2]]);
        if time >= samples[0][0] + span {
            break;
        }
    }
    Ok(samples)
}

fn odometry_time(client: &Client) -> Result<f64> {
    wait(|| client.position2d(0).state().map(|(_, s)| s.server_time))
}

fn wait<T>(mut get: impl FnMut() -> Option<T>) -> Result<T> {
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        if let Some(v) = get() {
            return Ok(v);
        }
        if Instant::now() > deadline {
            bail!("nothing came within 10 s");
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// Waits until the odometry is at least `steps` steps past `after` (0.1 s steps at most:
/// every stock world runs them), and returns its time.
fn wait_past(client: &Client, after: f64, steps: f64, interval: f64) -> Result<f64> {
    wait(|| {
        let now = client.position2d(0).state()?.1.server_time;
        (now >= after + (steps - 0.5) * interval).then_some(now)
    })
}

/// The step from two consecutive odometry times.
fn interval(client: &Client) -> Result<f64> {
    let first = odometry_time(client)?;
    let second = wait(|| {
        let t = client.position2d(0).state()?.1.server_time;
        (t > first).then_some(t)
    })?;
    Ok(second - first)
}

fn read(port: u16, robot: &str, rangers: u16, poses: &str) -> Result<()> {
    let client = connect(port)?;
    client.position2d(0).subscribe()?;
    for k in 0..rangers {
        client.ranger(k).subscribe()?;
    }
    let dt = interval(&client)?;
    for line in std::fs::read_to_string(poses)?.lines() {
        let pose = parse_pose(line)?;
        set_pose(&client, robot, pose)?;
        let placed = odometry_time(&client)?;
        // Two whole steps after the pose was set: readings of the new pose on every ranger.
        let t = wait_past(&client, placed, 2.0, dt)?;
        let mut scans = Vec::new();
        for k in 0..rangers {
            let ranges = wait(|| {
                let (r, s) = client.ranger(k).ranges()?;
                (s.server_time >= t - 1e-9).then_some(r.ranges)
            })?;
            scans.push(
                ranges
                    .iter()
                    .map(|r| (r * 10_000.0).round() / 10_000.0)
                    .collect::<Vec<_>>(),
            );
        }
        let line = serde_json::json!({ "pose": [pose.x, pose.y, pose.a], "ranges": scans });
        println!("{line}");
    }
    Ok(())
}

fn drive(port: u16, robot: &str, start: Pose, (vx, va): (f64, f64), steps: u32) -> Result<()> {
    let client = connect(port)?;
    let base = client.position2d(0);
    base.subscribe()?;
    let dt = interval(&client)?;
    base.set_velocity(0.0, 0.0, 0.0);
    set_pose(&client, robot, start)?;
    wait_past(&client, odometry_time(&client)?, 2.0, dt)?;
    base.set_velocity(vx, 0.0, va);
    // The true pose and simulated time while the command holds, asked again and again: Player
    // answers a request only every few steps, so a test drives from one sample to another
    // (steps apart by their simulated times) instead of from the command's first step.
    let samples = true_poses(&client, robot, f64::from(steps) * dt, 30)?;
    base.set_velocity(0.0, 0.0, 0.0);
    let line = serde_json::json!({
        "start": [start.x, start.y, start.a],
        "command": [vx, va],
        "interval": dt,
        "samples": samples,
    });
    println!("{line}");
    Ok(())
}

/// The pose position2d:`index` reports at each step while commanded at `command` (x, y, a as
/// vx, vy, va), from the step before the command: Stage's odometry, step by step.
fn odom(port: u16, index: u16, command: Pose, steps: u32) -> Result<()> {
    let client = connect(port)?;
    let base = client.position2d(index);
    base.subscribe()?;
    let state = || base.state().map(|(s, t)| (t.server_time, s.pos));
    let first = wait(|| state().map(|(t, _)| t))?;
    let dt = wait(|| state().and_then(|(t, _)| (t > first).then_some(t - first)))?;
    let mut samples: Vec<[f64; 4]> = Vec::new();
    let record = |samples: &mut Vec<[f64; 4]>| -> Result<f64> {
        let last = samples.last().map_or(f64::NEG_INFINITY, |s| s[0]);
        let (t, p) = wait(|| state().filter(|(t, _)| *t > last))?;
        samples.push([t, p.px, p.py, p.pa]);
        Ok(t)
    };
    let start = record(&mut samples)?;
    base.set_velocity(command.x, command.y, command.a);
    while record(&mut samples)? < start + f64::from(steps + 2) * dt {}
    base.set_velocity(0.0, 0.0, 0.0);
    let line = serde_json::json!({
        "index": index,
        "command": [command.x, command.y, command.a],
        "interval": dt,
        "samples": samples,
    });
    println!("{line}");
    Ok(())
}

/// ROBOT's true pose sampled while position2d:`index` steers to `goal`.
fn goto(port: u16, robot: &str, index: u16, goal: Pose, steps: u32) -> Result<()> {
    let client = connect(port)?;
    let base = client.position2d(index);
    base.subscribe()?;
    let first = wait(|| base.state().map(|(_, s)| s.server_time))?;
    let dt = wait(|| {
        let t = base.state()?.1.server_time;
        (t > first).then_some(t - first)
    })?;
    base.go_to(Pose2d::new(goal.x, goal.y, goal.a));
    let samples = true_poses(&client, robot, f64::from(steps) * dt, 60)?;
    base.set_velocity(0.0, 0.0, 0.0);
    let line = serde_json::json!({
        "goal": [goal.x, goal.y, goal.a],
        "interval": dt,
        "samples": samples,
    });
    println!("{line}");
    Ok(())
}
