//! What the robots' taps and the viewers share: the channels, and who is subscribed to what.
//! Every frame from a server goes through its robot's own [`Converter`] (which devices are
//! robots, ranger geometry, map tiles being assembled), on the robot's thread and outside the
//! hub's lock, which a thousand robots' threads share;
//! each [`Output`] is encoded once and its shared bytes queued to every subscriber, with the
//! Player timestamp as log time. Subscribing, latching and publishing happen under one lock,
//! so a new subscriber gets what was latched and then everything after it, nothing twice or
//! lost between the two.
//!
//! Watching drives subscribing: a channel knows the devices whose data it carries (its
//! sources), and a viewer's subscription holds a [`Look`] at each, through the robot's
//! [`Watch`]; the relay subscribes upstream to a device while some look is held. Data of a
//! device that has its channels and no viewer on them is not converted at all. A device's
//! channels are made from the robot's device list ([`crate::device_topics`]), before it sent
//! anything: a viewer may subscribe to a laser that sends only once someone does. What only
//! its first data tells (a camera's image schema) makes its channel then.

use std::collections::{BTreeSet, HashMap, HashSet};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{SystemTime, UNIX_EPOCH};

use bytes::Bytes;
use foxglove::messages::log::Level;
use player_front::{Device, Look, Watch};
use player_proto::capture::Direction;
use player_proto::client::TapEvent;
use player_proto::interfaces::player::{self, Player};
use player_proto::message::{Body, Message};
use player_proto::wire::{Header, Interface, MsgType};

use super::channels::Channels;
use super::outbox::{Data, Outbox};
use super::refusal::Refusal;
use super::wire::{ChannelId, SubscriptionId};
use crate::frames::timestamp;
use crate::{Converter, Output, device_topics, log};

/// A connected viewer, numbered from 1.
pub type ViewerId = u64;

/// A device of a robot, by the robot's name.
type Source = (String, Device);

/// A viewer's subscription: its channel, and its looks at the devices the channel carries.
struct Subscription {
    channel: ChannelId,
    looks: Vec<(Source, Look)>,
}

struct Viewer {
    outbox: Arc<Outbox>,
    subscriptions: HashMap<SubscriptionId, Subscription>,
}

struct Subscriber {
    viewer: ViewerId,
    subscription: SubscriptionId,
    outbox: Arc<Outbox>,
}

#[derive(Default)]
struct State {
    channels: Channels,
    viewers: HashMap<ViewerId, Viewer>,
    subscribers: HashMap<ChannelId, Vec<Subscriber>>,
    next_viewer: ViewerId,
    /// The relay's subscriptions to each robot that subscribes as viewers look; a robot
    /// without one (a client that subscribes by itself) is converted whole.
    watches: HashMap<String, Watch>,
    /// The devices whose data each channel carries.
    sources: HashMap<ChannelId, BTreeSet<Source>>,
    /// Devices whose data has made its channels.
    known: HashSet<Source>,
    /// Viewers' looks held now, per device.
    looked: HashMap<Source, usize>,
}

#[derive(Default)]
pub struct Hub {
    state: Mutex<State>,
}

impl Hub {
    fn lock(&self) -> MutexGuard<'_, State> {
        // Every change is whole under the lock: a poisoned lock still guards a usable value.
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// One tap event of the connection to `robot`, on its robot thread: converting and
    /// queueing for the viewers never waits on them.
    pub fn event(
        &self,
        robot: &str,
        converter: &Mutex<Converter>,
        time: SystemTime,
        event: TapEvent<'_>,
    ) {
        let (level, text) = match event {
            TapEvent::Opened(banner) => (
                Level::Info,
                format!("connected (Player {})", banner.version),
            ),
            TapEvent::Closed(reason) => (Level::Warning, format!("connection closed: {reason}")),
            TapEvent::Frame {
                direction: Direction::ServerToClient,
                header,
                body,
            } => return self.frame(robot, converter, header, body),
            TapEvent::Frame { .. } => return,
        };
        let time = system_timestamp(time);
        let output = log(robot, time, level, &text);
        self.lock().publish(output, time.total_nanos(), None);
    }

    fn frame(&self, robot: &str, converter: &Mutex<Converter>, header: &Header, body: &Bytes) {
        if is_device_list(header) {
            self.advertise_devices(robot, header, body);
        }
        let source = (header.msg_type == MsgType::Data)
            .then(|| (robot.to_string(), (header.addr.interf, header.addr.index)));
        if let Some(source) = &source {
            let state = self.lock();
            let watched = state.watches.contains_key(robot);
            let unlooked = !state.looked.contains_key(source);
            if watched && unlooked && state.known.contains(source) {
                // Its channels exist and nobody is on them: nothing to convert.
                return;
            }
        }
        let outputs = converter
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .server_message(robot, header, body);
        if outputs.is_empty() {
            return;
        }
        let log_time = timestamp(header.timestamp).total_nanos();
        let mut state = self.lock();
        for output in outputs {
            state.publish(output, log_time, source.as_ref());
        }
    }

    /// The channels of every device `robot`'s server lists (its answer to the device list
    /// request, which every connection asks first), advertised before any data: a viewer
    /// subscribes to a device that sends nothing until someone does.
    fn advertise_devices(&self, robot: &str, header: &Header, body: &Bytes) {
        let devices = match Message::decode(*header, body.clone()) {
            Ok(Message {
                body: Body::Player(Player::DevList(list)),
                ..
            }) => list.devices,
            Ok(_) => return,
            Err(e) => {
                tracing::debug!("{robot}: device list not read: {e}");
                return;
            }
        };
        let mut state = self.lock();
        for addr in devices {
            let source = (robot.to_string(), (addr.interf, addr.index));
            for output in device_topics(robot, addr.interf, addr.index) {
                state.advertise(&output, &source);
            }
        }
    }

    /// The relay subscribes to `robot` as viewers look, through `watch`.
    pub fn watch(&self, robot: &str, watch: Watch) {
        self.lock().watches.insert(robot.to_string(), watch);
    }

    /// Devices looked at now, over every robot (for tests and benches).
    pub fn looks(&self) -> usize {
        self.lock().looked.len()
    }

    /// A new viewer: its id, with the channels so far advertised to it.
    pub fn join(&self, outbox: Arc<Outbox>) -> ViewerId {
        let mut state = self.lock();
        state.next_viewer += 1;
        let id = state.next_viewer;
        if let Some(advertise) = state.channels.advertise_all() {
            outbox.push_control(advertise);
        }
        let viewer = Viewer {
            outbox,
            subscriptions: HashMap::new(),
        };
        state.viewers.insert(id, viewer);
        id
    }

    /// The viewer is gone: so are its subscriptions.
    pub fn leave(&self, viewer: ViewerId) {
        let mut state = self.lock();
        if let Some(gone) = state.viewers.remove(&viewer) {
            for subscription in gone.subscriptions.into_values() {
                state.unlist(subscription, viewer);
            }
        }
    }

    /// Subscribes the viewer (the latched messages of the channel first), or says why not.
    pub fn subscribe(
        &self,
        viewer: ViewerId,
        subscription: SubscriptionId,
        channel: ChannelId,
    ) -> Result<(), Refusal> {
        let mut state = self.lock();
        let state = &mut *state;
        if !state.channels.contains(channel) {
            return Err(Refusal::UnknownChannel(channel));
        }
        let Some(entry) = state.viewers.get_mut(&viewer) else {
            return Ok(());
        };
        if entry.subscriptions.contains_key(&subscription) {
            return Err(Refusal::SubscriptionInUse(subscription));
        }
        if entry.subscriptions.values().any(|s| s.channel == channel) {
            return Err(Refusal::AlreadySubscribed(channel));
        }
        // The relay subscribes to what the channel carries while the viewer is on it.
        let mut looks = Vec::new();
        for source in state.sources.get(&channel).into_iter().flatten() {
            if let Some(watch) = state.watches.get(&source.0) {
                looks.push((source.clone(), watch.look(source.1)));
                *state.looked.entry(source.clone()).or_default() += 1;
            }
        }
        entry
            .subscriptions
            .insert(subscription, Subscription { channel, looks });
        for (payload, log_time) in state.channels.latched(channel) {
            entry.outbox.push_data(Data {
                subscription,
                log_time: *log_time,
                payload: payload.clone(),
            });
        }
        let subscriber = Subscriber {
            viewer,
            subscription,
            outbox: entry.outbox.clone(),
        };
        state
            .subscribers
            .entry(channel)
            .or_default()
            .push(subscriber);
        Ok(())
    }

    pub fn unsubscribe(
        &self,
        viewer: ViewerId,
        subscription: SubscriptionId,
    ) -> Result<(), Refusal> {
        let mut state = self.lock();
        let gone = state
            .viewers
            .get_mut(&viewer)
            .and_then(|v| v.subscriptions.remove(&subscription))
            .ok_or(Refusal::UnknownSubscription(subscription))?;
        state.unlist(gone, viewer);
        Ok(())
    }

    pub fn viewers(&self) -> usize {
        self.lock().viewers.len()
    }

    pub fn topics(&self) -> Vec<String> {
        let mut topics: Vec<String> = self.lock().channels.topics().map(String::from).collect();
        topics.sort();
        topics
    }

    /// Closes every viewer (the server stops).
    pub fn close_all(&self) {
        for viewer in self.lock().viewers.values() {
            viewer.outbox.close();
        }
    }
}

impl State {
    /// Makes `output`'s channel (advertised to every viewer if new) as one carrying the data
    /// of `source`.
    fn advertise(&mut self, output: &Output, source: &Source) -> ChannelId {
        let (channel, advertise) = self.channels.channel_of(output);
        self.sources
            .entry(channel)
            .or_default()
            .insert(source.clone());
        if let Some(advertise) = advertise {
            for viewer in self.viewers.values() {
                viewer.outbox.push_control(advertise.clone());
            }
        }
        channel
    }

    /// Encodes `output` once and queues it to the channel's subscribers; `source` is the
    /// device whose data made it, if data did.
    fn publish(&mut self, output: Output, log_time: u64, source: Option<&Source>) {
        let channel = match source {
            Some(source) => {
                self.known.insert(source.clone());
                self.advertise(&output, source)
            }
            None => {
                let (channel, advertise) = self.channels.channel_of(&output);
                if let Some(advertise) = advertise {
                    for viewer in self.viewers.values() {
                        viewer.outbox.push_control(advertise.clone());
                    }
                }
                channel
            }
        };
        let subscribed = self
            .subscribers
            .get(&channel)
            .is_some_and(|s| !s.is_empty());
        if !subscribed && !Channels::latches(&output) {
            // Nobody to send it to, and nothing a later subscriber is sent: not encoded.
            return;
        }
        let payload = Bytes::from(output.message.encode());
        self.channels.latch(channel, &output, &payload, log_time);
        for subscriber in self.subscribers.get(&channel).into_iter().flatten() {
            subscriber.outbox.push_data(Data {
                subscription: subscriber.subscription,
                log_time,
                payload: payload.clone(),
            });
        }
    }

    /// The viewer's `subscription` ended: off its channel's list, and its looks let go.
    fn unlist(&mut self, subscription: Subscription, viewer: ViewerId) {
        if let Some(list) = self.subscribers.get_mut(&subscription.channel) {
            list.retain(|s| s.viewer != viewer);
        }
        for (source, look) in subscription.looks {
            drop(look);
            if let Some(n) = self.looked.get_mut(&source) {
                *n -= 1;
                if *n == 0 {
                    self.looked.remove(&source);
                }
            }
        }
    }
}

/// Whether `header` is a server's answer to the device list request.
fn is_device_list(header: &Header) -> bool {
    header.msg_type == MsgType::Ack
        && header.addr.interf == Interface::PLAYER
        && header.subtype == player::REQ_DEVLIST
}

fn system_timestamp(time: SystemTime) -> foxglove::messages::Timestamp {
    timestamp(
        time.duration_since(UNIX_EPOCH)
            .map_or(0.0, |d| d.as_secs_f64()),
    )
}
