//! What a plugin sees of the Player device it was made for: the newest data, commands,
//! requests and the link state. pv3d implements this over the Player client; tests feed known
//! data through [`RecordingDevice`].
//!
//! The seam speaks the client's own types ([`Stamped`], [`PendingReply`], [`RequestError`],
//! [`ConnectionState`]) and names messages by [`MessageKind`], never by a subtype number: a
//! plugin writes `device.latest_of::<LaserScan>()` or `Awaited::fetch(device,
//! Laser::REQ_GET_GEOM)`.

mod awaited;
mod recording;

use player_proto::body_kind::{BodyKind, DataBody};
use player_proto::interfaces::kind::MessageKind;
use player_proto::message::Body;

pub use awaited::Awaited;
pub use player_proto::client::{ConnectionState, PendingReply, RequestError, Responder, Stamped};
pub use recording::{RecordingDevice, ReplyOutcome};

/// Which sample of one data kind a plugin took last, so that it acts on each sample once
/// however often it is updated.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LastTaken {
    seq: Option<u64>,
}

impl LastTaken {
    /// Whether `sample` is another than the one taken last; if so, it is now the one taken.
    pub fn is_new(&mut self, sample: &Stamped) -> bool {
        let new = self.seq != Some(sample.seq);
        self.seq = Some(sample.seq);
        new
    }

    /// The device's newest sample of `kind`, unless it was taken already.
    pub fn newest(
        &mut self,
        device: Option<&dyn DeviceAccess>,
        kind: MessageKind,
    ) -> Option<Stamped> {
        device?.latest(kind).filter(|s| self.is_new(s))
    }

    /// The device's newest `T` and its sample, unless that sample was taken already.
    pub fn newest_of<T: DataBody>(
        &mut self,
        device: Option<&dyn DeviceAccess>,
    ) -> Option<(T, Stamped)> {
        let sample = self.newest(device, T::KIND.kind())?;
        let body = T::KIND.of(&sample.message)?.clone();
        Some((body, sample))
    }

    /// Forgets the sample taken, so that the newest is taken again (to redraw it).
    pub fn forget(&mut self) {
        self.seq = None;
    }
}

/// Access to one device.
pub trait DeviceAccess: Send + Sync {
    /// The newest DATA message of `kind` this device sent, if any.
    fn latest(&self, kind: MessageKind) -> Option<Stamped>;
    /// Sends a command (fire and forget). The subtype comes from the typed body.
    fn command(&self, body: Body);
    /// Sends a request of `kind`; the reply arrives later.
    fn request(&self, kind: MessageKind, body: Body) -> PendingReply;
    fn link_state(&self) -> ConnectionState;
    /// Whether this device is only observed (commands and configuration requests are refused
    /// before they are sent): a plugin then offers no tele-operation.
    fn read_only(&self) -> bool {
        false
    }
}

impl dyn DeviceAccess + '_ {
    /// The newest DATA message whose body is a `T`, with the body.
    pub fn latest_of<T: DataBody>(&self) -> Option<(T, Stamped)> {
        let sample = self.latest(T::KIND.kind())?;
        let body = T::KIND.of(&sample.message)?.clone();
        Some((body, sample))
    }

    /// Asks for what a "get" request of `kind` returns (the request body is empty).
    pub fn fetch<T>(&self, kind: BodyKind<T>) -> PendingReply {
        self.request(kind.kind(), Body::Empty)
    }

    /// Whether the device's server is connected now.
    pub fn is_connected(&self) -> bool {
        self.link_state() == ConnectionState::Connected
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::DevAddr;
    use player_proto::interfaces::sonar::{Sonar, SonarData};
    use player_proto::message::Message;
    use player_proto::wire::MsgType;

    #[test]
    fn each_sample_is_taken_once_until_forgotten() {
        let device = RecordingDevice::default();
        let ranges = Sonar::DATA_RANGES.kind();
        let mut taken = LastTaken::default();
        assert!(taken.newest(Some(&device), ranges).is_none(), "nothing yet");
        let addr: DevAddr = "sonar:0".parse().unwrap();
        let data = Sonar::Ranges(SonarData { ranges: vec![1.0] });
        device.push(Message::typed(addr, MsgType::Data, data));
        assert!(taken.newest(Some(&device), ranges).is_some());
        assert!(
            taken.newest(Some(&device), ranges).is_none(),
            "the same sample again"
        );
        taken.forget();
        let (typed, _) = taken.newest_of::<SonarData>(Some(&device)).unwrap();
        assert_eq!(typed.ranges, [1.0], "taken again after forget, typed");
        assert!(taken.newest(None, ranges).is_none(), "no device, no sample");
    }

    #[test]
    fn typed_reads_find_the_kind_asked_for_only() {
        let device = RecordingDevice::default();
        let device: &dyn DeviceAccess = &device;
        assert!(device.latest_of::<SonarData>().is_none());
        let addr: DevAddr = "sonar:0".parse().unwrap();
        let data = Sonar::Ranges(SonarData { ranges: vec![2.0] });
        let recording = RecordingDevice::default();
        recording.push(Message::typed(addr, MsgType::Data, data));
        let device: &dyn DeviceAccess = &recording;
        assert_eq!(device.latest_of::<SonarData>().unwrap().0.ranges, [2.0]);
        assert!(
            device
                .latest_of::<player_proto::interfaces::sonar::SonarGeometry>()
                .is_none(),
            "geometry data is another subtype"
        );
    }
}
