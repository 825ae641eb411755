//! The newest camera frame, decoded to RGBA once, with the frame rate and age shown beside it.
//!
//! Decoding is the expensive part (a JPEG per frame), so it happens only when a message with a
//! new sequence number arrives, and not even then when its pixels are the very bytes of the
//! frame already shown: Stage republishes an unchanged image while nothing moves.

use std::collections::VecDeque;
use std::sync::Arc;
use std::time::{Duration, Instant};

use image::RgbaImage;
use player_proto::interfaces::camera::Camera;
use player_proto::message::{Body, Message};

use framework::device::{LastTaken, Stamped};

/// The frame rate is measured over this many most recent arrivals.
const RATE_WINDOW: usize = 30;
/// …and over no longer than this, so that a stalled camera's rate falls to what it really is.
const RATE_SPAN: Duration = Duration::from_secs(3);

/// What [`CameraFrames::offer`] did with a sample.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Offered {
    /// Same sequence number as before: nothing new.
    Seen,
    /// A new message, but its pixels are those already decoded.
    Unchanged,
    /// A new frame, decoded.
    Decoded,
    /// A new message that does not decode (the reason is kept for the panel).
    Failed(String),
    /// Not a camera frame.
    NotAFrame,
}

/// The newest frame of one camera and its arrival statistics.
#[derive(Debug, Default)]
pub struct CameraFrames {
    taken: LastTaken,
    /// The message whose pixels [`Self::image`] holds, to recognise a republished frame.
    decoded_from: Option<Arc<Message>>,
    image: Option<Arc<RgbaImage>>,
    /// Counts decoded frames, so that a window re-uploads its texture only when it changes.
    version: u64,
    received: Option<Instant>,
    /// (sequence number, arrival) of the newest samples: frames the viewer skipped between two
    /// of its passes still count, as the sequence numbers say how many came.
    arrivals: VecDeque<(u64, Instant)>,
    error: Option<String>,
}

impl CameraFrames {
    /// Takes a sample of the camera's data (`PLAYER_CAMERA_DATA_STATE`).
    pub fn offer(&mut self, sample: &Stamped) -> Offered {
        if !self.taken.is_new(sample) {
            return Offered::Seen;
        }
        let Body::Camera(Camera::State(frame)) = &sample.message.body else {
            return Offered::NotAFrame;
        };
        self.received = Some(sample.received);
        if self.arrivals.len() == RATE_WINDOW {
            self.arrivals.pop_front();
        }
        self.arrivals.push_back((sample.seq, sample.received));
        if let Some(Body::Camera(Camera::State(shown))) =
            self.decoded_from.as_ref().map(|m| &m.body)
            && self.image.is_some()
            && same_pixels(shown, frame)
        {
            return Offered::Unchanged;
        }
        match frame.to_rgba() {
            Ok(image) => {
                self.image = Some(Arc::new(image));
                self.decoded_from = Some(sample.message.clone());
                self.version += 1;
                self.error = None;
                Offered::Decoded
            }
            Err(e) => {
                let reason = e.to_string();
                self.error = Some(reason.clone());
                Offered::Failed(reason)
            }
        }
    }

    /// The newest frame that decoded.
    pub fn image(&self) -> Option<&Arc<RgbaImage>> {
        self.image.as_ref()
    }

    /// Increases with every decoded frame.
    pub fn version(&self) -> u64 {
        self.version
    }

    /// Why the newest frame could not be shown, if it could not.
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// How long ago the newest frame arrived.
    pub fn age(&self, now: Instant) -> Option<Duration> {
        self.received.map(|at| now.saturating_duration_since(at))
    }

    /// Frames per second the camera sends, over the recent arrivals (up to [`RATE_SPAN`]
    /// before `now`); `None` until two have come in that time.
    pub fn rate(&self, now: Instant) -> Option<f32> {
        let (first_seq, first_at) = *self
            .arrivals
            .iter()
            .find(|(_, t)| now.saturating_duration_since(*t) <= RATE_SPAN)?;
        let (last_seq, last_at) = *self.arrivals.back()?;
        let span = last_at.saturating_duration_since(first_at).as_secs_f32();
        if span <= 0.0 || last_seq <= first_seq {
            return None;
        }
        Some((last_seq - first_seq) as f32 / span)
    }

    /// "640×480, 9.8 fps, 0.1 s old" (or why there is nothing to show).
    pub fn summary(&self, now: Instant) -> String {
        let Some(age) = self.age(now) else {
            return "no frame yet".into();
        };
        let size = self.image.as_ref().map_or("no image".into(), |i| {
            format!("{}×{}", i.width(), i.height())
        });
        let rate = self.rate(now).map_or("–".into(), |r| format!("{r:.1}"));
        let mut text = format!("{size}, {rate} fps, {:.1} s old", age.as_secs_f32());
        if let Some(e) = &self.error {
            text.push_str(&format!("; newest frame not shown: {e}"));
        }
        text
    }
}

fn same_pixels(
    a: &player_proto::interfaces::camera::CameraData,
    b: &player_proto::interfaces::camera::CameraData,
) -> bool {
    (a.width, a.height, a.bpp, a.format, a.compression)
        == (b.width, b.height, b.bpp, b.format, b.compression)
        && a.image[..] == b.image[..]
}
