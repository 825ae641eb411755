//! The topics a device's data becomes, known from the device alone — before it sent any.
//!
//! A live server advertises a robot's channels from its device list: a viewer must be able
//! to subscribe to a laser that has not sent yet, because a robot's server sends a device's
//! data only while someone is subscribed to it, and the relay subscribes only while a viewer
//! looks. Each topic comes with an empty message of the schema its data is converted to (for
//! the channel's schema). This must agree with [`crate::Converter`]'s conversion of data (the
//! tests hold the two together); what only replies make (geometry transforms, map grids)
//! comes with the survey's questions anyway, and a camera's schema (JPEG or raw) is known only
//! from its first frame, so it is advertised then.

use foxglove::messages::{FrameTransform, LaserScan, PoseInFrame, SceneUpdate};
use player_proto::wire::Interface;

use crate::{FoxgloveMessage, Output};

/// The channels the data of `interf:index` of `robot` is published on, each with an empty
/// message of its schema; none for a device whose data makes no channel of its own.
pub fn device_topics(robot: &str, interf: Interface, index: u16) -> Vec<Output> {
    let Some(kind) = interf.name() else {
        return Vec::new();
    };
    let topic = |what: &str| format!("/{robot}/{kind}/{index}/{what}");
    let output = |topic: String, message| Output { topic, message };
    match interf {
        Interface::LASER | Interface::RANGER | Interface::SONAR => vec![output(
            topic("scan"),
            FoxgloveMessage::LaserScan(LaserScan::default()),
        )],
        Interface::POSITION2D => vec![
            output(
                format!("/{robot}/tf"),
                FoxgloveMessage::FrameTransform(FrameTransform::default()),
            ),
            output(
                topic("pose"),
                FoxgloveMessage::PoseInFrame(PoseInFrame::default()),
            ),
        ],
        Interface::LOCALIZE => vec![output(
            topic("pose"),
            FoxgloveMessage::PoseInFrame(PoseInFrame::default()),
        )],
        Interface::FIDUCIAL => vec![output(
            topic("fiducials"),
            FoxgloveMessage::SceneUpdate(SceneUpdate::default()),
        )],
        Interface::PLANNER => vec![output(
            topic("path"),
            FoxgloveMessage::SceneUpdate(SceneUpdate::default()),
        )],
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use player_proto::interfaces::laser::{Laser, LaserScan as PlayerScan};
    use player_proto::interfaces::position2d::{Position2d, Position2dData};
    use player_proto::message::{Body, Message};
    use player_proto::wire::{DevAddr, HEADER_LEN, MsgType};

    use super::*;
    use crate::Converter;

    /// What the converter makes of `body`, data of `interf:index`: topic and schema name.
    fn converted(interf: Interface, index: u16, body: Body) -> Vec<(String, String)> {
        let message = Message::typed(DevAddr::local(interf, index), MsgType::Data, body).at(1.0);
        let wire = message.to_bytes();
        let body = wire.slice(HEADER_LEN..);
        let outputs = Converter::new().server_message("r", &message.header, &body);
        outputs
            .iter()
            .map(|o| (o.topic.clone(), o.message.schema().name))
            .collect()
    }

    fn advertised(interf: Interface, index: u16) -> Vec<(String, String)> {
        device_topics("r", interf, index)
            .iter()
            .map(|o| (o.topic.clone(), o.message.schema().name))
            .collect()
    }

    #[test]
    fn a_devices_data_goes_where_its_channels_were_advertised() {
        let scan = Body::Laser(Laser::Scan(PlayerScan {
            ranges: vec![1.0; 3],
            resolution: 1.0,
            ..PlayerScan::default()
        }));
        assert_eq!(
            converted(Interface::LASER, 1, scan),
            advertised(Interface::LASER, 1)
        );
        let state = Body::Position2d(Position2d::State(Position2dData::default()));
        let mut made = converted(Interface::POSITION2D, 0, state);
        let mut said = advertised(Interface::POSITION2D, 0);
        made.sort();
        said.sort();
        assert_eq!(made, said);
    }
}
