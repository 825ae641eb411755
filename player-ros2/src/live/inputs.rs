//! What ROS 2 may tell a robot: `cmd_vel` (a `Twist`, or Jazzy's `TwistStamped` when asked
//! for), `goal_pose` and `initialpose`, each a reliable subscription of the robot's node.

use ros2_client::pubsub::Subscription;
use ros2_client::qos::{History, Reliability, WhenFull};
use ros2_client::{Name, Node, QosProfile};

use super::LiveError;
use super::publishers::type_name;
use crate::msgs::{PoseStamped, PoseWithCovarianceStamped, RosMessage, Twist, TwistStamped};

/// Which commands ROS 2 may give the robots, and in which type `cmd_vel` comes.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Commands {
    /// None: the robots' data goes out, nothing comes in.
    ReadOnly,
    /// `cmd_vel` as `geometry_msgs/msg/Twist` (Humble's teleop, Nav2 up to Iron).
    #[default]
    Twist,
    /// `cmd_vel` as `geometry_msgs/msg/TwistStamped` (Jazzy's Nav2 and teleop with
    /// `stamped:=true`): the header is not looked at, the twist is checked as a `Twist` is.
    TwistStamped,
}

/// The `cmd_vel` subscription, of either type.
enum CmdVel {
    Plain(Subscription<Twist>),
    Stamped(Subscription<TwistStamped>),
}

/// A robot's subscriptions.
pub struct Inputs {
    cmd_vel: CmdVel,
    goal_pose: Subscription<PoseStamped>,
    initial_pose: Subscription<PoseWithCovarianceStamped>,
}

impl Inputs {
    /// The subscriptions of the robot of namespace `ns`; none when read-only.
    pub fn new(node: &mut Node, ns: &str, commands: Commands) -> Result<Option<Inputs>, LiveError> {
        let cmd_vel = match commands {
            Commands::ReadOnly => return Ok(None),
            Commands::Twist => CmdVel::Plain(subscribe(node, ns, "cmd_vel")?),
            Commands::TwistStamped => CmdVel::Stamped(subscribe(node, ns, "cmd_vel")?),
        };
        Ok(Some(Inputs {
            cmd_vel,
            goal_pose: subscribe(node, ns, "goal_pose")?,
            initial_pose: subscribe(node, ns, "initialpose")?,
        }))
    }

    /// The `cmd_vel`s received since the last call, oldest first.
    pub fn cmd_vels(&self) -> Vec<Twist> {
        match &self.cmd_vel {
            CmdVel::Plain(s) => drain(s),
            CmdVel::Stamped(s) => drain(s).into_iter().map(|t| t.twist).collect(),
        }
    }

    pub fn goals(&self) -> Vec<PoseStamped> {
        drain(&self.goal_pose)
    }

    pub fn initial_poses(&self) -> Vec<PoseWithCovarianceStamped> {
        drain(&self.initial_pose)
    }
}

/// Every message received on `subscription` since the last look, oldest first.
fn drain<T: ros2_client::Message + 'static>(subscription: &Subscription<T>) -> Vec<T> {
    let mut received = Vec::new();
    while let Ok(Some((message, _))) = subscription.take() {
        received.push(message);
    }
    received
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
