//! The publishing task: takes the robot threads' events off the queue, in order, and turns
//! them into Zenoh — DATA messages put on `…/data` with congestion control *drop* (a slow
//! link loses old scans rather than holding the relay up), replies into the cache, and the
//! robot's liveliness token declared once its devices are known and undeclared when its
//! connection closes.
//!
//! Watching drives subscribing: once a robot's devices are known, each device's data key has
//! its publisher and a matching listener, and while some Zenoh subscriber matches the key the
//! front holds a look at the device (`FrontShared::matching`): the relay subscribes upstream
//! to it then, and lets it go when the last subscriber leaves.

use std::collections::HashMap;
use std::sync::Arc;

use player_proto::capture::Direction;
use player_proto::interfaces::player::{self, Player};
use player_proto::message::{Body, Message};
use player_proto::wire::{Header, Interface, MsgType};
use zenoh::pubsub::Publisher;
use zenoh::qos::CongestionControl;

use crate::cache::wire_bytes;
use crate::keys::{Leaf, RobotKey};
use crate::queue::FrontEvent;
use crate::shared::FrontShared;

/// Runs until the front stops (its task aborted, or its runtime shut down).
pub(crate) async fn run(shared: Arc<FrontShared>) {
    let mut publishers: HashMap<String, Publisher<'static>> = HashMap::new();
    loop {
        for event in shared.queue.take_all().await {
            match event {
                FrontEvent::Opened(robot) => {
                    tracing::debug!(%robot, "robot connected");
                    let mut robots = shared.robots();
                    let entry = robots.entry(robot).or_default();
                    entry.cache.clear();
                    entry.connected = true;
                }
                FrontEvent::Closed(robot, why) => {
                    let token = {
                        let mut robots = shared.robots();
                        let entry = robots.entry(robot.clone()).or_default();
                        entry.connected = false;
                        entry.cache.clear();
                        entry.token.take()
                    };
                    if let Some(token) = token {
                        tracing::info!(%robot, why, "robot gone: withdrawn from Zenoh");
                        if let Err(e) = token.undeclare().await {
                            tracing::warn!(%robot, "liveliness token not undeclared: {e}");
                        }
                    }
                }
                FrontEvent::Frame {
                    robot,
                    direction: Direction::ServerToClient,
                    header,
                    body,
                    ..
                } if header.msg_type == MsgType::Data => {
                    let key = robot.device(header.addr.interf, header.addr.index, Leaf::Data);
                    let publisher = match publishers.get(&key) {
                        Some(publisher) => publisher,
                        None => match declare(&shared, &key).await {
                            Some(publisher) => publishers.entry(key).or_insert(publisher),
                            None => continue,
                        },
                    };
                    if let Err(e) = publisher.put(wire_bytes(&header, &body)).await {
                        tracing::debug!(%robot, "data not published: {e}");
                    }
                }
                FrontEvent::Frame {
                    robot,
                    direction,
                    header,
                    body,
                    ..
                } => {
                    let announce = {
                        let mut robots = shared.robots();
                        let entry = robots.entry(robot.clone()).or_default();
                        entry.cache.observe(direction, &header, &body);
                        entry.connected && entry.token.is_none() && entry.cache.ready()
                    };
                    if direction == Direction::ServerToClient {
                        for (interf, index) in devices_listed(&header, &body) {
                            let key = robot.device(interf, index, Leaf::Data);
                            if publishers.contains_key(&key) {
                                continue;
                            }
                            let device = (interf, index);
                            if let Some(publisher) = declare(&shared, &key).await {
                                listen(&shared, &robot, device, &publisher).await;
                                publishers.insert(key, publisher);
                            }
                        }
                    }
                    if announce {
                        announce_robot(&shared, robot).await;
                    }
                }
            }
        }
    }
}

async fn declare(shared: &FrontShared, key: &str) -> Option<Publisher<'static>> {
    match shared
        .session
        .declare_publisher(key.to_string())
        .congestion_control(CongestionControl::Drop)
        .await
    {
        Ok(publisher) => Some(publisher),
        Err(e) => {
            tracing::warn!(key, "cannot publish: {e}");
            None
        }
    }
}

/// The devices a device-list reply lists; none for any other message.
fn devices_listed(header: &Header, body: &bytes::Bytes) -> Vec<(Interface, u16)> {
    let is_list = header.addr.interf == Interface::PLAYER
        && header.msg_type == MsgType::Ack
        && header.subtype == player::REQ_DEVLIST;
    match is_list.then(|| Message::decode(*header, body.clone())) {
        Some(Ok(Message {
            body: Body::Player(Player::DevList(list)),
            ..
        })) => list.devices.iter().map(|d| (d.interf, d.index)).collect(),
        _ => Vec::new(),
    }
}

/// Looks at `device` while some subscriber matches its publisher's key.
async fn listen(
    shared: &Arc<FrontShared>,
    robot: &RobotKey,
    device: (Interface, u16),
    publisher: &Publisher<'static>,
) {
    let (watching, matched) = (shared.clone(), robot.clone());
    let listening = publisher
        .matching_listener()
        .callback(move |status| watching.matching(&matched, device, status.matching()))
        .background()
        .await;
    if let Err(e) = listening {
        tracing::warn!(%robot, "no matching listener for {}:{}: {e}", device.0, device.1);
    }
}

/// Declares the robot's liveliness token: bridges see it and serve the robot.
async fn announce_robot(shared: &FrontShared, robot: RobotKey) {
    let token = match shared
        .session
        .liveliness()
        .declare_token(robot.alive())
        .await
    {
        Ok(token) => token,
        Err(e) => {
            tracing::error!(%robot, "cannot announce the robot: {e}");
            return;
        }
    };
    let mut robots = shared.robots();
    let entry = robots.entry(robot.clone()).or_default();
    if entry.connected && entry.token.is_none() {
        tracing::info!(%robot, "robot announced in Zenoh");
        entry.token = Some(token);
    }
}
