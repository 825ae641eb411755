//! One robot found in Zenoh, served as an ordinary Player server: its devices from the
//! robot's `devices` queryable, a device's data from its `…/data` key while a local client is
//! subscribed to it (published with the robot's own timestamps; the robot's relay subscribes
//! upstream only to what some Zenoh subscriber matches), `GET` requests answered from the `replies` queryable, and commands and
//! other requests sent back on `…/cmd`, stamped with the bridge's identity — whether they
//! act is the robot side's decision (see [`crate::commands`]).

use std::sync::{Arc, Mutex};
use std::time::Duration;

use bytes::Bytes;
use player_proto::interfaces::player::Player;
use player_proto::message::{Body, Message};
use player_proto::server::{Device, ReplaceRule, Reply, Server, ServerConfig};
use player_proto::wire::{HEADER_LEN, Header, Interface, MsgType};
use zenoh::Session;
use zenoh::Wait;
use zenoh::qos::CongestionControl;
use zenoh::query::ConsolidationMode;

use crate::bridge_config::FromZenohConfig;
use crate::cache::CachedReply;
use crate::commands::decode_raw;
use crate::error::ZenohError;
use crate::feeds::Feeds;
use crate::keys::{Leaf, RobotKey};
use crate::stamp::Stamp;

/// How long the robot's side has to answer a query (devices, replies, a request).
const QUERY_WAIT: Duration = Duration::from_secs(3);

/// A robot being served; stops serving when dropped.
pub(crate) struct Remote {
    pub server: Arc<Server>,
    pub feeds: Feeds,
}

impl Drop for Remote {
    fn drop(&mut self) {
        self.server.shutdown();
        // Its clients went without unsubscribing: their Zenoh subscriptions go here.
        self.feeds.stop();
    }
}

/// Asks a queryable and returns every answer's payload and attachment.
fn ask(
    session: &Session,
    key: String,
    request: Option<(Bytes, Vec<u8>)>,
) -> Result<Vec<(Bytes, Option<Bytes>)>, ZenohError> {
    // Several answers share one key (a device list, then driver names): Zenoh's default
    // consolidation would keep only the last.
    let mut get = session
        .get(key)
        .consolidation(ConsolidationMode::None)
        .timeout(QUERY_WAIT);
    if let Some((payload, attachment)) = request {
        get = get.payload(payload).attachment(attachment);
    }
    let replies = get.wait()?;
    let mut answers = Vec::new();
    while let Ok(reply) = replies.recv() {
        if let Ok(sample) = reply.result() {
            let attachment = sample
                .attachment()
                .map(|a| Bytes::from(a.to_bytes().into_owned()));
            answers.push((
                Bytes::from(sample.payload().to_bytes().into_owned()),
                attachment,
            ));
        }
    }
    Ok(answers)
}

/// Serves `robot` on `port` (0: any free one).
pub(crate) fn serve(
    session: &Session,
    robot: &RobotKey,
    port: u16,
    config: &FromZenohConfig,
) -> Result<Remote, ZenohError> {
    let mut list = None;
    let mut drivers = Vec::new();
    for (payload, _) in ask(session, robot.devices(), None)? {
        match decode_raw(&payload).map(|m| m.body) {
            Some(Body::Player(Player::DevList(l))) => list = Some(l.devices),
            Some(Body::Player(Player::DriverInfo(info))) => drivers.push(info),
            _ => {}
        }
    }
    let list = list.ok_or_else(|| ZenohError::NotDescribed(robot.to_string()))?;
    let mut server_config = ServerConfig::default();
    server_config.bind = config.bind;
    server_config.commanders = config.commanders;
    server_config.queue_rules = vec![ReplaceRule::newest_data()];
    server_config.send_buffer = config.send_buffer;
    server_config.thread_name = "from-zenoh".into();
    let number = server_config.robot(port);
    let feeds = Feeds::default();
    for addr in list {
        let driver = drivers
            .iter()
            .find(|d| (d.addr.interf, d.addr.index) == (addr.interf, addr.index))
            .map(|d| d.driver_name.as_str().into_owned())
            .unwrap_or_default();
        let device = RemoteDevice {
            session: session.clone(),
            robot: robot.clone(),
            interf: addr.interf,
            index: addr.index,
            driver,
            identity: config.identity.clone(),
            replies: Arc::default(),
            feeds: feeds.clone(),
        };
        server_config.device(number, addr, device);
    }
    let server = Arc::new(Server::start(server_config)?);
    feeds.serve_on(server.publisher(), server.port(0));
    Ok(Remote { server, feeds })
}

/// A device of a robot found in Zenoh.
struct RemoteDevice {
    session: Session,
    robot: RobotKey,
    interf: Interface,
    index: u16,
    driver: String,
    identity: String,
    /// The robot side's cached replies, fetched when first asked for.
    replies: Arc<Mutex<Vec<CachedReply>>>,
    /// The robot's data subscriptions in Zenoh, one per device a local client looks at.
    feeds: Feeds,
}

impl RemoteDevice {
    fn key(&self, leaf: Leaf) -> String {
        self.robot.device(self.interf, self.index, leaf)
    }

    fn cached(&self, subtype: u8, request: &Bytes) -> Option<Bytes> {
        let replies = self.replies.lock().unwrap_or_else(|e| e.into_inner());
        replies
            .iter()
            .find(|r| r.subtype == subtype && r.request == *request)
            .map(|r| r.reply.clone())
    }

    fn refresh(&self) {
        let Ok(answers) = ask(&self.session, self.key(Leaf::Replies), None) else {
            return;
        };
        let fresh = answers
            .into_iter()
            .filter_map(|(reply, request)| {
                let subtype = Header::decode_slice(&reply)?.ok()?.subtype;
                Some(CachedReply {
                    subtype,
                    request: request.unwrap_or_default(),
                    reply,
                })
            })
            .collect();
        *self.replies.lock().unwrap_or_else(|e| e.into_inner()) = fresh;
    }

    /// The robot side's answer to `request`: cached if it describes the device, else asked.
    fn answer(&self, request: &Message) -> Option<Bytes> {
        let raw = request.to_bytes();
        let body = raw.slice(HEADER_LEN..);
        let subtype = request.header.subtype;
        if let Some(reply) = self.cached(subtype, &body) {
            return Some(reply);
        }
        self.refresh();
        if let Some(reply) = self.cached(subtype, &body) {
            return Some(reply);
        }
        let stamp = Stamp::now(&self.identity).encode();
        let answers = ask(&self.session, self.key(Leaf::Cmd), Some((raw, stamp))).ok()?;
        answers.into_iter().next().map(|(reply, _)| reply)
    }
}

impl Device for RemoteDevice {
    fn driver_name(&self) -> &str {
        &self.driver
    }

    /// The first local subscriber subscribes to the device's data in Zenoh.
    fn on_subscribe(&mut self) -> bool {
        let key = self.key(Leaf::Data);
        match self
            .feeds
            .subscribed(&self.session, (self.interf, self.index), key)
        {
            Ok(()) => true,
            Err(e) => {
                // Refused, as a Player driver that cannot start: no data would come.
                tracing::warn!(robot = %self.robot, "cannot subscribe to its data in Zenoh: {e}");
                false
            }
        }
    }

    /// The last local subscriber gone, the Zenoh subscription goes too.
    fn on_unsubscribe(&mut self) {
        self.feeds.unsubscribed((self.interf, self.index));
    }

    fn on_command(&mut self, command: &Message) {
        let sent = self
            .session
            .put(self.key(Leaf::Cmd), command.to_bytes())
            .attachment(Stamp::now(&self.identity).encode())
            .congestion_control(CongestionControl::Drop)
            .wait();
        if let Err(e) = sent {
            tracing::warn!(robot = %self.robot, "command not sent to Zenoh: {e}");
        }
    }

    /// Blocks this server worker for the answer; `block_in_place` lets the runtime move the
    /// other connections' work to another worker meanwhile.
    fn on_request(&mut self, request: &Message) -> Reply {
        let answer = tokio::task::block_in_place(|| self.answer(request));
        match answer.as_deref().and_then(decode_raw) {
            Some(reply) if reply.header.msg_type == MsgType::Ack => Reply::Ack(reply.body),
            _ => Reply::Nack,
        }
    }
}
