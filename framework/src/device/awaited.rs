//! A "get" request a plugin sends once (its device's geometry, its config) and whose typed
//! reply it picks up on a later update, so that the UI thread never waits for the server.

use player_proto::body_kind::BodyKind;

use super::{DeviceAccess, PendingReply, RequestError};

/// One typed request in flight, polled from `update`.
pub struct Awaited<T> {
    kind: BodyKind<T>,
    pending: Option<PendingReply>,
}

impl<T> std::fmt::Debug for Awaited<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let state = if self.pending.is_some() {
            "waiting"
        } else {
            "done"
        };
        write!(f, "Awaited({:?}, {state})", self.kind)
    }
}

impl<T: Clone> Awaited<T> {
    /// Sends the request of `kind` with an empty body; without a device nothing is sent and
    /// nothing will arrive.
    pub fn fetch(device: Option<&dyn DeviceAccess>, kind: BodyKind<T>) -> Awaited<T> {
        Awaited {
            kind,
            pending: device.map(|d| d.fetch(kind)),
        }
    }

    /// The reply, the one time it is there: the structure the request promises, or why there
    /// is none (an ACK with another body reads as a refusal). `None` while it is on its way
    /// and after it was taken.
    pub fn take(&mut self) -> Option<Result<T, RequestError>> {
        let outcome = self.pending.as_ref()?.try_get()?;
        self.pending = None;
        Some(outcome.and_then(|reply| self.kind.reply_of(&reply)))
    }

    /// Whether the reply is still to come.
    pub fn is_waiting(&self) -> bool {
        self.pending.is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::device::RecordingDevice;
    use player_proto::DevAddr;
    use player_proto::interfaces::sonar::{Sonar, SonarGeometry, SonarPower};
    use player_proto::message::Message;
    use player_proto::wire::MsgType;

    fn ack(body: Sonar) -> Message {
        let addr: DevAddr = "sonar:0".parse().unwrap();
        Message::typed(addr, MsgType::Ack, body)
    }

    #[test]
    fn a_late_reply_is_taken_once_and_typed() {
        let device = RecordingDevice::default();
        let mut geometry = Awaited::fetch(Some(&device), Sonar::REQ_GET_GEOM);
        assert!(geometry.take().is_none(), "not answered yet");
        assert!(geometry.is_waiting());
        let answered = device.answer_later(
            Sonar::REQ_GET_GEOM.kind(),
            Ok(ack(Sonar::Geometry(SonarGeometry::default()))),
        );
        assert_eq!(answered, 1);
        assert_eq!(geometry.take(), Some(Ok(SonarGeometry::default())));
        assert!(geometry.take().is_none(), "taken already");
        let sent = device.requests.lock().unwrap();
        assert_eq!(sent.len(), 1, "sent once");
        assert_eq!(sent[0].0, Sonar::REQ_GET_GEOM.kind());
    }

    #[test]
    fn a_reply_of_another_structure_is_an_error() {
        let device = RecordingDevice::default();
        let wrong = ack(Sonar::Power(SonarPower::default()));
        device.reply_to(Sonar::REQ_GET_GEOM.kind(), Ok(wrong));
        let mut geometry = Awaited::fetch(Some(&device), Sonar::REQ_GET_GEOM);
        assert!(matches!(geometry.take(), Some(Err(RequestError::Nack(_)))));
    }

    #[test]
    fn without_a_device_nothing_arrives() {
        let mut geometry = Awaited::fetch(None, Sonar::REQ_GET_GEOM);
        assert!(!geometry.is_waiting());
        assert!(geometry.take().is_none());
    }
}
