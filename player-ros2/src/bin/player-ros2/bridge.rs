//! The bridge's loop: each robot's newest data, as it arrives, published in ROS 2; each
//! robot's newest `cmd_vel`, checked, sent to its base; a base whose commands stopped coming,
//! stopped; its planner's path when it changes. A robot whose Player server goes leaves ROS 2
//! (its node and topics go) until the client's reconnection brings it back.

use std::collections::HashMap;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

use anyhow::{Context, Result};
use player_proto::RobotId;
use player_proto::client::{Client, ClientOptions, ConnectionState};
use player_proto::wire::DevAddr;
use player_ros2::convert::MAPPED;
use player_ros2::live::steer::{Steering, Told};
use player_ros2::live::{Commands, RobotNode, Ros2, describe};

/// How long the loop sleeps at most without news (deadlines are checked as often).
const TICK: Duration = Duration::from_millis(20);

/// Something new from any robot.
#[derive(Default)]
struct News {
    pending: Mutex<bool>,
    arrived: Condvar,
}

impl News {
    fn tell(&self) {
        *self.pending.lock().unwrap_or_else(|e| e.into_inner()) = true;
        self.arrived.notify_one();
    }

    fn wait(&self, most: Duration) {
        let pending = self.pending.lock().unwrap_or_else(|e| e.into_inner());
        let (mut pending, _) = self
            .arrived
            .wait_timeout_while(pending, most, |p| !*p)
            .unwrap_or_else(|e| e.into_inner());
        *pending = false;
    }
}

/// One robot: its Player client and, while its server is there, its ROS 2 node.
struct Bridged {
    robot: RobotId,
    client: Client,
    ros2: Ros2,
    commands: Commands,
    node: Option<RobotNode>,
    /// Whether the robot has been connected since the bridge began (else it is "not yet
    /// there", not "gone").
    was_there: bool,
    seen: HashMap<(DevAddr, u8), u64>,
    steering: Steering,
}

pub fn run(robots: &[RobotId], domain: u16, commands: Commands) -> Result<()> {
    let ros2 = Ros2::join(domain)?;
    let read_only = commands == Commands::ReadOnly;
    let news = Arc::new(News::default());
    let mut bridged = Vec::new();
    for robot in robots {
        let notify = news.clone();
        let options = ClientOptions {
            read_only,
            notifier: Some(Arc::new(move || notify.tell())),
            ..ClientOptions::default()
        };
        let client = Client::spawn(robot.host(), robot.port(), options)
            .with_context(|| format!("connecting to {}", robot.server()))?;
        bridged.push(Bridged {
            robot: robot.clone(),
            client,
            ros2: ros2.clone(),
            commands,
            node: None,
            was_there: false,
            seen: HashMap::new(),
            steering: Steering::new(robot),
        });
    }
    loop {
        news.wait(TICK);
        for b in &mut bridged {
            b.step();
        }
    }
}

impl Bridged {
    fn step(&mut self) {
        let connected = self.client.state() == ConnectionState::Connected;
        if connected && self.node.is_none() {
            self.arrive();
        }
        if !connected && self.node.is_some() {
            self.leave();
        }
        let Some(node) = self.node.as_mut() else {
            return;
        };
        for stamped in self.client.newest_data() {
            let header = &stamped.message.header;
            let key = (header.addr, header.subtype);
            if self.seen.get(&key).is_some_and(|&seq| seq >= stamped.seq) {
                continue;
            }
            self.seen.insert(key, stamped.seq);
            if let Err(e) = node.publish(&stamped.message) {
                tracing::warn!("{}: {e}", self.robot);
            }
        }
        self.steering.steer(&Told::take(node), &self.client);
        if let Some(path) = self.steering.plan(node.namespace(), &self.client)
            && let Err(e) = node.send(path)
        {
            tracing::warn!("{}: {e}", self.robot);
        }
    }

    /// The robot is there (first, or back): its node, its devices subscribed, what describes
    /// them published.
    fn arrive(&mut self) {
        let mut node = match self.ros2.robot(&self.robot, self.commands) {
            Ok(node) => node,
            Err(e) => {
                tracing::warn!("{}: not in ROS 2: {e}", self.robot);
                return;
            }
        };
        tracing::info!(
            "{}: {} ROS 2 as /{}/player",
            self.robot,
            if self.was_there { "back in" } else { "in" },
            node.namespace()
        );
        self.was_there = true;
        for device in self.client.devices() {
            if MAPPED.contains(&device.addr.interf)
                && let Err(e) = self.client.subscribe(device.addr)
            {
                tracing::warn!("{}: cannot subscribe to {}: {e}", self.robot, device.addr);
            }
        }
        describe(&self.robot, &self.client).publish(&self.robot, &mut node);
        self.node = Some(node);
    }

    /// The robot's server went: its node goes (ROS 2 sees its node and topics go); the client
    /// keeps trying to reach it.
    fn leave(&mut self) {
        self.node = None;
        self.steering = Steering::new(&self.robot);
        let why = self
            .client
            .last_disconnect()
            .unwrap_or_else(|| "the connection ended".into());
        tracing::warn!(
            "{}: lost its Player server ({why}): out of ROS 2, reconnecting",
            self.robot
        );
    }
}
