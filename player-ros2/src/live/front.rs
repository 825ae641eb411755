//! ROS 2 as a front of the relay (`player-relay --ros2`): each robot the relay carries becomes
//! a ROS 2 node the moment it arrives; every message its server sends is published through
//! the same conversion as the bridge's (replies included: the geometries, configurations and
//! map tiles the relay asks for, the way-points the steering asks for); through the relay's
//! upstream client, ROS 2's commands reach the robot unless the front is read-only; and when
//! the relay simulates, the simulation's time goes out on `/clock` and stamps every message.

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

use super::clock::ClockThread;
use super::describe::describe;
use super::steer::{Steering, Told};
use super::{Commands, LiveError, RobotNode, Ros2, SimClock};
use crate::convert::MAPPED;

/// How often each robot's commands from ROS 2 are looked for.
const TICK: Duration = Duration::from_millis(20);

/// The ROS 2 front.
pub struct Ros2Front {
    ros2: Ros2,
    domain: u16,
    commands: Commands,
    /// The simulation's time, when the relay simulates.
    clock: Option<SimClock>,
    nodes: Mutex<HashMap<RobotId, Slot>>,
    stopping: Arc<AtomicBool>,
    steering: Mutex<Vec<JoinHandle<()>>>,
    /// Publishes `/clock` while the front lives.
    _clock_thread: Option<ClockThread>,
}

impl Ros2Front {
    /// Joins ROS 2 domain `domain`, taking `commands` from it; with `clock` (the relay
    /// simulates), publishes it on `/clock` and stamps every message by it.
    pub fn start(
        domain: u16,
        commands: Commands,
        clock: Option<SimClock>,
    ) -> Result<Ros2Front, LiveError> {
        let ros2 = Ros2::join(domain)?;
        let clock_thread = clock.clone().map(|c| ros2.clock(c)).transpose()?;
        Ok(Ros2Front {
            ros2,
            domain,
            commands,
            clock,
            nodes: Mutex::default(),
            stopping: Arc::default(),
            steering: Mutex::default(),
            _clock_thread: clock_thread,
        })
    }

    pub fn domain(&self) -> u16 {
        self.domain
    }
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// A robot's node while the robot is there: none from its leaving (its server went) until it
/// is back, so ROS 2 sees its node and topics go with it.
type Slot = Arc<Mutex<Option<RobotNode>>>;

impl Front for Ros2Front {
    fn name(&self) -> &str {
        "ROS 2"
    }

    fn arrived(&self, robot: &RobotId) -> ConnectionTap {
        let slot: Slot = Arc::default();
        join(&self.ros2, robot, self.commands, self.domain, &slot, false);
        lock(&self.nodes).insert(robot.clone(), slot.clone());
        let (robot, clock) = (robot.clone(), self.clock.clone());
        let (ros2, commands, domain) = (self.ros2.clone(), self.commands, self.domain);
        Arc::new(move |_, event| match event {
            TapEvent::Opened(_) => {
                if lock(&slot).is_none() {
                    join(&ros2, &robot, commands, domain, &slot, true);
                }
            }
            TapEvent::Closed(why) => {
                // Said as player-ros2 says it; the relay keeps reconnecting.
                if lock(&slot).take().is_some() {
                    tracing::warn!(
                        "{robot}: lost its Player server ({why}): out of ROS 2, reconnecting"
                    );
                }
            }
            TapEvent::Frame {
                direction: Direction::ServerToClient,
                header,
                body,
            } => {
                // Decoded only when ROS 2 has a counterpart for it: the tap runs on the robot's
                // thread for every message.
                if !MAPPED.contains(&header.addr.interf) {
                    return;
                }
                let Ok(mut message) = Message::decode(*header, body.clone()) else {
                    return;
                };
                if let Some(clock) = &clock {
                    message.header.timestamp = clock.stamp(message.header.timestamp);
                }
                if let Some(node) = lock(&slot).as_mut()
                    && let Err(e) = node.publish(&message)
                {
                    tracing::debug!("{robot}: {e}");
                }
            }
            TapEvent::Frame { .. } => {}
        })
    }

    fn commands_through(&self, robot: &RobotId, client: Arc<Client>) {
        let Some(slot) = lock(&self.nodes).get(robot).cloned() else {
            return;
        };
        let (who, stopping) = (robot.clone(), self.stopping.clone());
        let read_only = self.commands == Commands::ReadOnly;
        let robot = robot.clone();
        // Whatever is asked of the robot here is answered through the tap, which takes the
        // node's lock: it is never held while waiting for an answer.
        let thread = std::thread::Builder::new()
            .name(format!("ros2 steer {robot}"))
            .spawn(move || {
                let mut steering = Steering::new(&robot);
                let mut described = false;
                while !stopping.load(Ordering::Relaxed) {
                    std::thread::sleep(TICK);
                    let Some(ns) = lock(&slot).as_ref().map(|n| n.namespace().to_string()) else {
                        // Gone: described again, and its plan asked again, once it is back.
                        described = false;
                        steering = Steering::new(&robot);
                        continue;
                    };
                    if !described && client.state() == ConnectionState::Connected {
                        described = true;
                        let said = describe(&robot, &client);
                        if let Some(node) = lock(&slot).as_mut() {
                            said.publish(&robot, node);
                        }
                    }
                    if !read_only {
                        let told = lock(&slot).as_ref().map(Told::take).unwrap_or_default();
                        steering.steer(&told, &client);
                    }
                    // The way-points' reply reaches ROS 2 through the tap.
                    let _ = steering.plan(&ns, &client);
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

/// Makes `robot`'s node into `slot` (`back`: after it left), or says why it could not.
fn join(ros2: &Ros2, robot: &RobotId, commands: Commands, domain: u16, slot: &Slot, back: bool) {
    match ros2.robot(robot, commands) {
        Ok(node) => {
            match back {
                true => tracing::info!("{robot}: back in ROS 2 as /{}/player", node.namespace()),
                false => tracing::info!(
                    "{robot}: ROS 2 node /{}/player on domain {domain}",
                    node.namespace()
                ),
            }
            *lock(slot) = Some(node);
        }
        Err(e) => tracing::warn!("{robot}: not in ROS 2: {e}"),
    }
}
