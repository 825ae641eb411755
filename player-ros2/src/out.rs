//! What a conversion makes: one ROS 2 message of the types Player's data becomes, with its
//! topic and time. Its own module, below both the conversion ([`crate::convert`]) and the
//! pieces that make messages for it ([`crate::camera`], [`crate::ranges`]), so that none of
//! those needs another to name what they all return.

use crate::cdr::{CdrError, serialize};
use crate::msgs::{
    BatteryState, CameraInfo, CompressedImage, Image, LaserScan, OccupancyGrid, Odometry, Path,
    PointCloud2, PoseWithCovarianceStamped, RosMessage, TFMessage, Time, schema_text,
};

/// A ROS 2 message of one of the types Player's data becomes. Short-lived (made, then sent
/// or written at once), so the sizes of its variants do not matter.
#[derive(Debug, Clone, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum RosOut {
    LaserScan(LaserScan),
    Odometry(Odometry),
    Tf(TFMessage),
    PoseWithCovarianceStamped(PoseWithCovarianceStamped),
    Path(Path),
    BatteryState(BatteryState),
    Image(Image),
    CompressedImage(CompressedImage),
    CameraInfo(CameraInfo),
    PointCloud2(PointCloud2),
    OccupancyGrid(OccupancyGrid),
}

macro_rules! each_type {
    ($self:expr, $m:ident => $e:expr) => {
        match $self {
            RosOut::LaserScan($m) => $e,
            RosOut::Odometry($m) => $e,
            RosOut::Tf($m) => $e,
            RosOut::PoseWithCovarianceStamped($m) => $e,
            RosOut::Path($m) => $e,
            RosOut::BatteryState($m) => $e,
            RosOut::Image($m) => $e,
            RosOut::CompressedImage($m) => $e,
            RosOut::CameraInfo($m) => $e,
            RosOut::PointCloud2($m) => $e,
            RosOut::OccupancyGrid($m) => $e,
        }
    };
}

fn type_of<T: RosMessage>(_: &T) -> &'static str {
    T::TYPE
}

fn schema_of<T: RosMessage>(_: &T) -> String {
    schema_text::<T>()
}

impl RosOut {
    /// `pkg/msg/Type`.
    pub fn type_name(&self) -> &'static str {
        each_type!(self, m => type_of(m))
    }

    /// The type's schema (`ros2msg`).
    pub fn schema(&self) -> String {
        each_type!(self, m => schema_of(m))
    }

    /// The message as ROS 2 serializes it.
    pub fn cdr(&self) -> Result<Vec<u8>, CdrError> {
        each_type!(self, m => serialize(m))
    }
}

/// One ROS 2 message made from a Player message: its topic, its time and itself.
#[derive(Debug, Clone, PartialEq)]
pub struct Converted {
    pub topic: String,
    pub stamp: Time,
    pub message: RosOut,
}

impl Converted {
    pub fn new(topic: String, stamp: Time, message: RosOut) -> Converted {
        Converted {
            topic,
            stamp,
            message,
        }
    }
}
