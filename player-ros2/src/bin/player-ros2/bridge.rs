//! The bridge's loop: each robot's newest data, as it arrives, published in ROS 2; each
//! robot's newest `cmd_vel`, checked, sent to its base; a base whose commands stopped coming,
//! stopped.

use std::collections::HashMap;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

use anyhow::{Context, Result};
use player_proto::RobotId;
use player_proto::client::{Client, ClientOptions, ConnectionState};
use player_proto::wire::DevAddr;
use player_ros2::convert::MAPPED;
use player_ros2::live::steer::{Steering, latched};
use player_ros2::live::{RobotNode, Ros2};

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

/// One robot: its Player client and its ROS 2 node.
struct Bridged {
    robot: RobotId,
    client: Client,
    node: RobotNode,
    subscribed: bool,
    seen: HashMap<(DevAddr, u8), u64>,
    steering: Steering,
}

pub fn run(robots: &[RobotId], domain: u16, read_only: bool) -> Result<()> {
    let ros2 = Ros2::join(domain)?;
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
        let node = ros2.robot(robot, read_only)?;
        tracing::info!(
            "{robot}: ROS 2 namespace /{} on domain {domain}",
            node.namespace()
        );
        bridged.push(Bridged {
            robot: robot.clone(),
            client,
            node,
            subscribed: false,
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
        if !self.subscribed && self.client.state() == ConnectionState::Connected {
            self.subscribe();
        }
        for stamped in self.client.newest_data() {
            let header = &stamped.message.header;
            let key = (header.addr, header.subtype);
            if self.seen.get(&key).is_some_and(|&seq| seq >= stamped.seq) {
                continue;
            }
            self.seen.insert(key, stamped.seq);
            if let Err(e) = self.node.publish(&stamped.message) {
                tracing::warn!("{}: {e}", self.robot);
            }
        }
        self.steering.steer(&self.node, &self.client);
    }

    fn subscribe(&mut self) {
        self.subscribed = true;
        for device in self.client.devices() {
            if MAPPED.contains(&device.addr.interf)
                && let Err(e) = self.client.subscribe(device.addr)
            {
                tracing::warn!("{}: cannot subscribe to {}: {e}", self.robot, device.addr);
            }
        }
        latched(&self.robot, &self.client, &mut self.node);
    }
}
