//! One robot as a ROS 2 node: `/ns/player`, a publisher per topic its data goes to (made when
//! the first message for it comes), and its `cmd_vel` subscription.

use std::collections::HashMap;

use player_proto::RobotId;
use player_proto::message::Message;
use ros2_client::pubsub::{Publisher, Subscription};
use ros2_client::qos::{Durability, History, Reliability, WhenFull};
use ros2_client::{Context, MessageTypeName, Name, Node, NodeName, NodeOptions, QosProfile};
use serde::Serialize;

use super::LiveError;
use crate::convert::{RosOut, convert};
use crate::msgs::{
    BatteryState, LaserScan, Odometry, Path, PoseWithCovarianceStamped, RosMessage, TFMessage,
    Twist,
};
use crate::names::namespace;

impl ros2_client::Message for LaserScan {}
impl ros2_client::Message for Odometry {}
impl ros2_client::Message for TFMessage {}
impl ros2_client::Message for PoseWithCovarianceStamped {}
impl ros2_client::Message for Path {}
impl ros2_client::Message for BatteryState {}
impl ros2_client::Message for Twist {}

/// Sensor data as ROS's sensor QoS has it: best effort, the newest few.
const SENSOR: QosProfile = QosProfile::publisher_default()
    .reliability(Reliability::BestEffort)
    .durability(Durability::Volatile)
    .history(History::KeepLast { depth: 5 });

/// The rest: reliable.
const RELIABLE: QosProfile = QosProfile::publisher_default()
    .reliability(Reliability::Reliable {
        when_full: WhenFull::Wait(std::time::Duration::from_millis(10)),
    })
    .durability(Durability::Volatile)
    .history(History::KeepLast { depth: 10 });

/// The publishers of one message type, by topic.
struct Outs<T: Serialize>(HashMap<String, Publisher<T>>);

impl<T: Serialize> Default for Outs<T> {
    fn default() -> Self {
        Outs(HashMap::new())
    }
}

/// A robot's node.
pub struct RobotNode {
    ns: String,
    node: Node,
    scans: Outs<LaserScan>,
    odometry: Outs<Odometry>,
    tf: Outs<TFMessage>,
    poses: Outs<PoseWithCovarianceStamped>,
    paths: Outs<Path>,
    batteries: Outs<BatteryState>,
    cmd_vel: Option<Subscription<Twist>>,
}

/// `/a/b/c` as ROS 2's (namespace, base name).
fn split(topic: &str) -> (&str, &str) {
    match topic.rfind('/') {
        Some(0) | None => ("/", topic.trim_start_matches('/')),
        Some(i) => (&topic[..i], &topic[i + 1..]),
    }
}

/// `pkg/msg/Type` as ros2-client names it.
fn type_name<T: RosMessage>() -> MessageTypeName {
    let package = T::TYPE.split('/').next().unwrap_or_default();
    let name = T::TYPE.rsplit('/').next().unwrap_or_default();
    MessageTypeName::new(package, name)
}

impl RobotNode {
    pub(super) fn new(
        context: &Context,
        robot: &RobotId,
        read_only: bool,
    ) -> Result<RobotNode, LiveError> {
        let ns = namespace(robot);
        let failed = |what: &str, e: &dyn std::fmt::Display| LiveError::Create {
            robot: robot.to_string(),
            what: what.to_string(),
            message: e.to_string(),
        };
        let name =
            NodeName::new(&format!("/{ns}"), "player").map_err(|e| failed("a node name", &e))?;
        let mut node = context
            .new_node(name, NodeOptions::new())
            .map_err(|e| failed("its node", &e))?;
        let spinner = node
            .spinner()
            .map_err(|e| failed("its node's spinner", &e))?;
        // The spinner answers ROS 2's graph (node and topic discovery): a thread of its own.
        std::thread::Builder::new()
            .name(format!("ros2 {ns}"))
            .spawn(move || futures::executor::block_on(spinner.spin()))
            .map_err(|e| failed("its node's thread", &e))?;
        let cmd_vel = if read_only {
            None
        } else {
            let topic_name =
                Name::new(&format!("/{ns}"), "cmd_vel").map_err(|e| failed("cmd_vel", &e))?;
            let qos = QosProfile::subscription_default()
                .reliability(Reliability::Reliable {
                    when_full: WhenFull::DEFAULT,
                })
                .history(History::KeepLast { depth: 10 });
            let topic = node
                .create_topic(&topic_name, type_name::<Twist>(), &qos)
                .map_err(|e| failed("the cmd_vel topic", &e))?;
            Some(
                node.create_subscription::<Twist>(&topic, None)
                    .map_err(|e| failed("the cmd_vel subscription", &e))?,
            )
        };
        Ok(RobotNode {
            ns,
            node,
            scans: Outs::default(),
            odometry: Outs::default(),
            tf: Outs::default(),
            poses: Outs::default(),
            paths: Outs::default(),
            batteries: Outs::default(),
            cmd_vel,
        })
    }

    /// The robot's namespace.
    pub fn namespace(&self) -> &str {
        &self.ns
    }

    /// Publishes what `message` is in ROS 2; how many ROS 2 messages it made.
    pub fn publish(&mut self, message: &Message) -> Result<usize, LiveError> {
        let converted = convert(&self.ns, message);
        let count = converted.len();
        for c in converted {
            match c.message {
                RosOut::LaserScan(m) => publish(
                    &mut self.node,
                    &mut self.scans,
                    &c.topic,
                    SENSOR,
                    m,
                    &self.ns,
                )?,
                RosOut::Odometry(m) => publish(
                    &mut self.node,
                    &mut self.odometry,
                    &c.topic,
                    RELIABLE,
                    m,
                    &self.ns,
                )?,
                RosOut::Tf(m) => publish(
                    &mut self.node,
                    &mut self.tf,
                    &c.topic,
                    RELIABLE,
                    m,
                    &self.ns,
                )?,
                RosOut::PoseWithCovarianceStamped(m) => publish(
                    &mut self.node,
                    &mut self.poses,
                    &c.topic,
                    RELIABLE,
                    m,
                    &self.ns,
                )?,
                RosOut::Path(m) => publish(
                    &mut self.node,
                    &mut self.paths,
                    &c.topic,
                    RELIABLE,
                    m,
                    &self.ns,
                )?,
                RosOut::BatteryState(m) => publish(
                    &mut self.node,
                    &mut self.batteries,
                    &c.topic,
                    RELIABLE,
                    m,
                    &self.ns,
                )?,
            }
        }
        Ok(count)
    }

    /// The `cmd_vel`s received since the last call, oldest first.
    pub fn cmd_vels(&self) -> Vec<Twist> {
        let mut received = Vec::new();
        if let Some(subscription) = &self.cmd_vel {
            while let Ok(Some((twist, _))) = subscription.take() {
                received.push(twist);
            }
        }
        received
    }
}

/// Publishes `message` on `topic`, making its publisher the first time.
fn publish<T: RosMessage + ros2_client::Message + std::fmt::Debug + 'static>(
    node: &mut Node,
    outs: &mut Outs<T>,
    topic: &str,
    qos: QosProfile,
    message: T,
    ns: &str,
) -> Result<(), LiveError> {
    if !outs.0.contains_key(topic) {
        let failed = |e: &dyn std::fmt::Display| LiveError::Create {
            robot: ns.to_string(),
            what: format!("the publisher of {topic}"),
            message: e.to_string(),
        };
        let (namespace, base) = split(topic);
        let name = Name::new(namespace, base).map_err(|e| failed(&e))?;
        let dds_topic = node
            .create_topic(&name, type_name::<T>(), &qos)
            .map_err(|e| failed(&e))?;
        let publisher = node
            .create_publisher::<T>(&dds_topic, None)
            .map_err(|e| failed(&e))?;
        outs.0.insert(topic.to_string(), publisher);
    }
    if let Some(publisher) = outs.0.get(topic) {
        // A best-effort sample nobody takes, or a reliable one a slow reader holds up past
        // its wait, is dropped: the next one replaces it.
        if let Err(e) = publisher.publish(message) {
            tracing::debug!(topic, "not published: {e:?}");
        }
    }
    Ok(())
}
