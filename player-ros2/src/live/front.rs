//! ROS 2 as a front of the relay (`player-relay --ros2`): each robot the relay carries becomes
//! a ROS 2 node the moment it arrives; every message its server sends is published through
//! the same conversion as the bridge's; and, through the relay's upstream client, ROS 2's
//! commands reach the robot unless the front is read-only.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::Duration;

use player_front::Front;
use player_proto::RobotId;
use player_proto::capture::Direction;
use player_proto::client::{Client, ConnectionState, ConnectionTap, TapEvent};
use player_proto::message::Message;

use super::steer::{Steering, latched};
use super::{LiveError, RobotNode, Ros2};
use crate::convert::MAPPED;

/// How often each robot's commands from ROS 2 are looked for.
const TICK: Duration = Duration::from_millis(20);

/// The ROS 2 front.
pub struct Ros2Front {
    ros2: Ros2,
    domain: u16,
    read_only: bool,
    nodes: Mutex<HashMap<RobotId, Arc<Mutex<RobotNode>>>>,
    stopping: Arc<AtomicBool>,
    steering: Mutex<Vec<JoinHandle<()>>>,
}

impl Ros2Front {
    /// Joins ROS 2 domain `domain`; `read_only`: publish only.
    pub fn start(domain: u16, read_only: bool) -> Result<Ros2Front, LiveError> {
        Ok(Ros2Front {
            ros2: Ros2::join(domain)?,
            domain,
            read_only,
            nodes: Mutex::default(),
            stopping: Arc::default(),
            steering: Mutex::default(),
        })
    }

    pub fn domain(&self) -> u16 {
        self.domain
    }
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

impl Front for Ros2Front {
    fn name(&self) -> &str {
        "ROS 2"
    }

    fn arrived(&self, robot: &RobotId) -> ConnectionTap {
        let node = match self.ros2.robot(robot, self.read_only) {
            Ok(node) => Arc::new(Mutex::new(node)),
            Err(e) => {
                tracing::warn!("{robot}: not in ROS 2: {e}");
                return Arc::new(|_, _| {});
            }
        };
        tracing::info!(
            "{robot}: ROS 2 node /{}/player on domain {}",
            lock(&node).namespace(),
            self.domain
        );
        lock(&self.nodes).insert(robot.clone(), node.clone());
        let robot = robot.clone();
        Arc::new(move |_, event| {
            let TapEvent::Frame {
                direction: Direction::ServerToClient,
                header,
                body,
            } = event
            else {
                return;
            };
            // Decoded only when ROS 2 has a counterpart for it: the tap runs on the robot's
            // thread for every message.
            if !MAPPED.contains(&header.addr.interf) {
                return;
            }
            let Ok(message) = Message::decode(*header, body.clone()) else {
                return;
            };
            if let Err(e) = lock(&node).publish(&message) {
                tracing::debug!("{robot}: {e}");
            }
        })
    }

    fn commands_through(&self, robot: &RobotId, client: Arc<Client>) {
        let Some(node) = lock(&self.nodes).get(robot).cloned() else {
            return;
        };
        let (who, stopping, read_only) = (robot.clone(), self.stopping.clone(), self.read_only);
        let robot = robot.clone();
        let thread = std::thread::Builder::new()
            .name(format!("ros2 steer {robot}"))
            .spawn(move || {
                let mut steering = Steering::new(&robot);
                let mut latched_done = false;
                while !stopping.load(Ordering::Relaxed) {
                    std::thread::sleep(TICK);
                    if !latched_done && client.state() == ConnectionState::Connected {
                        latched_done = true;
                        latched(&robot, &client, &mut lock(&node));
                    }
                    if !read_only {
                        let node = lock(&node);
                        steering.steer(&node, &client);
                    }
                }
            });
        match thread {
            Ok(thread) => lock(&self.steering).push(thread),
            Err(e) => tracing::warn!("{who}: ROS 2 commands not passed on: {e}"),
        }
    }

    fn stop(&self) {
        self.stopping.store(true, Ordering::Relaxed);
        for thread in lock(&self.steering).drain(..) {
            let _ = thread.join();
        }
    }
}
