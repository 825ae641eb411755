//! A robot node's publishers: one per topic its data goes to, made when the first message
//! for it comes, each with the QoS ROS gives its kind of data — sensor data best effort, the
//! rest reliable, what stays for latecomers (maps, fixed transforms, plans) transient local.

use std::collections::HashMap;

use ros2_client::pubsub::Publisher;
use ros2_client::qos::{Durability, History, Reliability, WhenFull};
use ros2_client::{MessageTypeName, Name, Node, QosProfile};
use serde::Serialize;

use super::LiveError;
use crate::msgs::{
    BatteryState, CameraInfo, Clock, CompressedImage, Image, LaserScan, OccupancyGrid, Odometry,
    Path, PointCloud2, PoseStamped, PoseWithCovarianceStamped, RosMessage, TFMessage, Twist,
    TwistStamped,
};
use crate::out::{Converted, RosOut};

impl ros2_client::Message for LaserScan {}
impl ros2_client::Message for Odometry {}
impl ros2_client::Message for TFMessage {}
impl ros2_client::Message for PoseWithCovarianceStamped {}
impl ros2_client::Message for Path {}
impl ros2_client::Message for BatteryState {}
impl ros2_client::Message for Twist {}
impl ros2_client::Message for TwistStamped {}
impl ros2_client::Message for PoseStamped {}
impl ros2_client::Message for OccupancyGrid {}
impl ros2_client::Message for Image {}
impl ros2_client::Message for CompressedImage {}
impl ros2_client::Message for CameraInfo {}
impl ros2_client::Message for PointCloud2 {}
impl ros2_client::Message for Clock {}

/// Sensor data as ROS's sensor QoS has it: best effort, the newest few.
pub const SENSOR: QosProfile = QosProfile::publisher_default()
    .reliability(Reliability::BestEffort)
    .durability(Durability::Volatile)
    .history(History::KeepLast { depth: 5 });

/// The rest: reliable.
pub const RELIABLE: QosProfile = QosProfile::publisher_default()
    .reliability(Reliability::Reliable {
        when_full: WhenFull::Wait(std::time::Duration::from_millis(10)),
    })
    .durability(Durability::Volatile)
    .history(History::KeepLast { depth: 10 });

/// What stays for those who come later: a map, the sensors' fixed transforms.
pub const LATCHED: QosProfile = QosProfile::publisher_default()
    .reliability(Reliability::Reliable {
        when_full: WhenFull::Wait(std::time::Duration::from_millis(100)),
    })
    .durability(Durability::TransientLocal)
    .history(History::KeepLast { depth: 1 });

/// The publishers of one message type, by topic.
pub struct Outs<T: Serialize>(HashMap<String, Publisher<T>>);

impl<T: Serialize> Default for Outs<T> {
    fn default() -> Self {
        Outs(HashMap::new())
    }
}

/// `pkg/msg/Type` as ros2-client names it.
pub fn type_name<T: RosMessage>() -> MessageTypeName {
    let package = T::TYPE.split('/').next().unwrap_or_default();
    let name = T::TYPE.rsplit('/').next().unwrap_or_default();
    MessageTypeName::new(package, name)
}

/// `/a/b/c` as ROS 2's (namespace, base name).
fn split(topic: &str) -> (&str, &str) {
    match topic.rfind('/') {
        Some(0) | None => ("/", topic.trim_start_matches('/')),
        Some(i) => (&topic[..i], &topic[i + 1..]),
    }
}

impl<T: RosMessage + ros2_client::Message + std::fmt::Debug + 'static> Outs<T> {
    /// Publishes `message` on `topic`, making its publisher the first time (`who` names the
    /// node in errors).
    pub fn publish(
        &mut self,
        node: &mut Node,
        topic: &str,
        qos: QosProfile,
        message: T,
        who: &str,
    ) -> Result<(), LiveError> {
        if !self.0.contains_key(topic) {
            let failed = |e: &dyn std::fmt::Display| LiveError::Create {
                robot: who.to_string(),
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
            self.0.insert(topic.to_string(), publisher);
        }
        if let Some(publisher) = self.0.get(topic) {
            // A best-effort sample nobody takes, or a reliable one a slow reader holds up past
            // its wait, is dropped: the next one replaces it.
            if let Err(e) = publisher.publish(message) {
                tracing::debug!(topic, "not published: {e:?}");
            }
        }
        Ok(())
    }
}

/// Every publisher of a robot's node, by type.
#[derive(Default)]
pub struct Publishers {
    scans: Outs<LaserScan>,
    odometry: Outs<Odometry>,
    pub tf: Outs<TFMessage>,
    poses: Outs<PoseWithCovarianceStamped>,
    paths: Outs<Path>,
    batteries: Outs<BatteryState>,
    pub maps: Outs<OccupancyGrid>,
    images: Outs<Image>,
    jpegs: Outs<CompressedImage>,
    infos: Outs<CameraInfo>,
    clouds: Outs<PointCloud2>,
}

impl Publishers {
    /// Publishes one converted message with its kind's QoS.
    pub fn send(&mut self, node: &mut Node, c: Converted, who: &str) -> Result<(), LiveError> {
        let topic = &c.topic;
        match c.message {
            RosOut::LaserScan(m) => self.scans.publish(node, topic, SENSOR, m, who),
            RosOut::Odometry(m) => self.odometry.publish(node, topic, RELIABLE, m, who),
            RosOut::Tf(m) => self.tf.publish(node, topic, RELIABLE, m, who),
            RosOut::PoseWithCovarianceStamped(m) => {
                self.poses.publish(node, topic, RELIABLE, m, who)
            }
            // A plan stays for rviz2 opened later (a planner's path comes once per plan).
            RosOut::Path(m) => self.paths.publish(node, topic, LATCHED, m, who),
            RosOut::BatteryState(m) => self.batteries.publish(node, topic, RELIABLE, m, who),
            RosOut::Image(m) => self.images.publish(node, topic, SENSOR, m, who),
            RosOut::CompressedImage(m) => self.jpegs.publish(node, topic, SENSOR, m, who),
            RosOut::CameraInfo(m) => self.infos.publish(node, topic, SENSOR, m, who),
            RosOut::PointCloud2(m) => self.clouds.publish(node, topic, SENSOR, m, who),
            RosOut::OccupancyGrid(m) => self.maps.publish(node, topic, LATCHED, m, who),
        }
    }
}
