//! One robot as a ROS 2 node: `/ns/player`, its conversion (which remembers what the robot's
//! devices said of themselves), its publishers ([`super::publishers`]) and what ROS 2 may tell
//! it ([`super::inputs`]).

use player_proto::RobotId;
use player_proto::message::Message;
use ros2_client::{Context, Node, NodeName, NodeOptions};

use super::LiveError;
use super::inputs::{Commands, Inputs};
use super::publishers::{LATCHED, Publishers};
use crate::converter::Converter;
use crate::msgs::{OccupancyGrid, PoseStamped, PoseWithCovarianceStamped, TFMessage, Twist};
use crate::names::namespace;
use crate::out::Converted;

/// A robot's node.
pub struct RobotNode {
    node: Node,
    converter: Converter,
    outs: Publishers,
    inputs: Option<Inputs>,
}

/// A node named `/namespace/name` whose spinner (which answers ROS 2's graph: node and topic
/// discovery, `ros_discovery_info`) runs on a thread of its own; `who` names it in errors.
pub(super) fn spun_node(
    context: &Context,
    namespace: &str,
    name: &str,
    who: &str,
) -> Result<Node, LiveError> {
    let failed = |what: &str, e: &dyn std::fmt::Display| LiveError::Create {
        robot: who.to_string(),
        what: what.to_string(),
        message: e.to_string(),
    };
    let node_name = NodeName::new(namespace, name).map_err(|e| failed("a node name", &e))?;
    let mut node = context
        .new_node(node_name, NodeOptions::new())
        .map_err(|e| failed("its node", &e))?;
    let spinner = node
        .spinner()
        .map_err(|e| failed("its node's spinner", &e))?;
    std::thread::Builder::new()
        .name(format!("ros2 {namespace}/{name}"))
        .spawn(move || futures::executor::block_on(spinner.spin()))
        .map_err(|e| failed("its node's thread", &e))?;
    Ok(node)
}

impl RobotNode {
    pub(super) fn new(
        context: &Context,
        robot: &RobotId,
        commands: Commands,
    ) -> Result<RobotNode, LiveError> {
        let ns = namespace(robot);
        let mut node = spun_node(context, &format!("/{ns}"), "player", &robot.to_string())?;
        let inputs = Inputs::new(&mut node, &ns, commands)?;
        Ok(RobotNode {
            node,
            converter: Converter::new(ns),
            outs: Publishers::default(),
            inputs,
        })
    }

    /// The robot's namespace.
    pub fn namespace(&self) -> &str {
        self.converter.namespace()
    }

    /// The robot's conversion, to tell it what the devices said of themselves in replies
    /// that did not pass through [`RobotNode::publish`].
    pub fn converter(&mut self) -> &mut Converter {
        &mut self.converter
    }

    /// Publishes what `message` is in ROS 2; how many ROS 2 messages it made.
    pub fn publish(&mut self, message: &Message) -> Result<usize, LiveError> {
        let converted = self.converter.convert(message);
        let count = converted.len();
        for c in converted {
            self.send(c)?;
        }
        Ok(count)
    }

    /// Publishes one message already converted.
    pub fn send(&mut self, converted: Converted) -> Result<(), LiveError> {
        let who = self.converter.namespace().to_string();
        self.outs.send(&mut self.node, converted, &who)
    }

    /// The `cmd_vel`s received since the last call, oldest first (the twists of
    /// `TwistStamped`s).
    pub fn cmd_vels(&self) -> Vec<Twist> {
        self.inputs.as_ref().map_or_else(Vec::new, Inputs::cmd_vels)
    }

    /// The goals (`goal_pose`, as rviz2's "2D Goal Pose" sends them) since the last call.
    pub fn goals(&self) -> Vec<PoseStamped> {
        self.inputs.as_ref().map_or_else(Vec::new, Inputs::goals)
    }

    /// The poses a localizer is told to start from (`initialpose`) since the last call.
    pub fn initial_poses(&self) -> Vec<PoseWithCovarianceStamped> {
        self.inputs
            .as_ref()
            .map_or_else(Vec::new, Inputs::initial_poses)
    }

    /// Publishes a map on `topic` (`/map`), kept for subscribers who come later.
    pub fn publish_map(&mut self, topic: &str, grid: OccupancyGrid) -> Result<(), LiveError> {
        let who = self.converter.namespace().to_string();
        self.outs
            .maps
            .publish(&mut self.node, topic, LATCHED, grid, &who)
    }

    /// Publishes the robot's fixed transforms (its sensors on its base) on `/tf_static`, kept
    /// for subscribers who come later.
    pub fn publish_static(&mut self, transforms: TFMessage) -> Result<(), LiveError> {
        let who = self.converter.namespace().to_string();
        self.outs
            .tf
            .publish(&mut self.node, "/tf_static", LATCHED, transforms, &who)
    }
}
