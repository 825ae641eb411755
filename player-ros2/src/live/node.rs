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
    BatteryState, CompressedImage, Image, LaserScan, OccupancyGrid, Odometry, Path, PoseStamped,
    PoseWithCovarianceStamped, RosMessage, TFMessage, Twist,
};
use crate::names::namespace;

impl ros2_client::Message for LaserScan {}
impl ros2_client::Message for Odometry {}
impl ros2_client::Message for TFMessage {}
impl ros2_client::Message for PoseWithCovarianceStamped {}
impl ros2_client::Message for Path {}
impl ros2_client::Message for BatteryState {}
impl ros2_client::Message for Twist {}
impl ros2_client::Message for PoseStamped {}
impl ros2_client::Message for OccupancyGrid {}
impl ros2_client::Message for Image {}
impl ros2_client::Message for CompressedImage {}

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

/// What stays for those who come later: a map, the sensors' fixed transforms.
const LATCHED: QosProfile = QosProfile::publisher_default()
    .reliability(Reliability::Reliable {
        when_full: WhenFull::Wait(std::time::Duration::from_millis(100)),
    })
    .durability(Durability::TransientLocal)
    .history(History::KeepLast { depth: 1 });

/// What ROS 2 may tell a robot (none when it is read-only).
struct Inputs {
    cmd_vel: Subscription<Twist>,
    goal_pose: Subscription<PoseStamped>,
    initial_pose: Subscription<PoseWithCovarianceStamped>,
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
    maps: Outs<OccupancyGrid>,
    images: Outs<Image>,
    jpegs: Outs<CompressedImage>,
    inputs: Option<Inputs>,
}

/// Every message received on `subscription` since the last look, oldest first.
fn drain<T: ros2_client::Message + 'static>(subscription: &Subscription<T>) -> Vec<T> {
    let mut received = Vec::new();
    while let Ok(Some((message, _))) = subscription.take() {
        received.push(message);
    }
    received
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
        let inputs = if read_only {
            None
        } else {
            Some(Inputs {
                cmd_vel: subscribe::<Twist>(&mut node, &ns, "cmd_vel")?,
                goal_pose: subscribe::<PoseStamped>(&mut node, &ns, "goal_pose")?,
                initial_pose: subscribe::<PoseWithCovarianceStamped>(
                    &mut node,
                    &ns,
                    "initialpose",
                )?,
            })
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
            maps: Outs::default(),
            images: Outs::default(),
            jpegs: Outs::default(),
            inputs,
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
                RosOut::Image(m) => publish(
                    &mut self.node,
                    &mut self.images,
                    &c.topic,
                    SENSOR,
                    m,
                    &self.ns,
                )?,
                RosOut::CompressedImage(m) => publish(
                    &mut self.node,
                    &mut self.jpegs,
                    &c.topic,
                    SENSOR,
                    m,
                    &self.ns,
                )?,
            }
        }
        Ok(count)
    }

    /// The `cmd_vel`s received since the last call, oldest first.
    pub fn cmd_vels(&self) -> Vec<Twist> {
        self.inputs
            .as_ref()
            .map_or_else(Vec::new, |i| drain(&i.cmd_vel))
    }

    /// The goals (`goal_pose`, as rviz2's "2D Goal Pose" sends them) since the last call.
    pub fn goals(&self) -> Vec<PoseStamped> {
        self.inputs
            .as_ref()
            .map_or_else(Vec::new, |i| drain(&i.goal_pose))
    }

    /// The poses a localizer is told to start from (`initialpose`) since the last call.
    pub fn initial_poses(&self) -> Vec<PoseWithCovarianceStamped> {
        self.inputs
            .as_ref()
            .map_or_else(Vec::new, |i| drain(&i.initial_pose))
    }

    /// Publishes a map on `topic` (`/map`), kept for subscribers who come later.
    pub fn publish_map(&mut self, topic: &str, grid: OccupancyGrid) -> Result<(), LiveError> {
        publish(
            &mut self.node,
            &mut self.maps,
            topic,
            LATCHED,
            grid,
            &self.ns,
        )
    }

    /// Publishes the robot's fixed transforms (its sensors on its base) on `/tf_static`, kept
    /// for subscribers who come later.
    pub fn publish_static(&mut self, transforms: TFMessage) -> Result<(), LiveError> {
        publish(
            &mut self.node,
            &mut self.tf,
            "/tf_static",
            LATCHED,
            transforms,
            &self.ns,
        )
    }
}

/// A reliable subscription to `/ns/base`.
fn subscribe<T: RosMessage + ros2_client::Message + 'static>(
    node: &mut Node,
    ns: &str,
    base: &str,
) -> Result<Subscription<T>, LiveError> {
    let failed = |e: &dyn std::fmt::Display| LiveError::Create {
        robot: ns.to_string(),
        what: format!("the {base} subscription"),
        message: e.to_string(),
    };
    let name = Name::new(&format!("/{ns}"), base).map_err(|e| failed(&e))?;
    let qos = QosProfile::subscription_default()
        .reliability(Reliability::Reliable {
            when_full: WhenFull::DEFAULT,
        })
        .history(History::KeepLast { depth: 10 });
    let topic = node
        .create_topic(&name, type_name::<T>(), &qos)
        .map_err(|e| failed(&e))?;
    node.create_subscription::<T>(&topic, None)
        .map_err(|e| failed(&e))
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
