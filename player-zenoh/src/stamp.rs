//! Who sent a command, and when: the Zenoh attachment of every command and request.
//!
//! A command is only worth executing while it is fresh: a velocity held up by a broken link
//! and delivered when it heals would move the robot on an order its controller gave up on
//! long ago. So commands are plain puts (never stored or latched by Zenoh), and the robot's
//! side drops any whose send time is more than [`MAX_COMMAND_AGE`] before its arrival — which
//! assumes the two machines' clocks agree well within that (NTP does).
//!
//! The attachment is 8 bytes, the send time in microseconds since the Unix epoch (big
//! endian), then the sender's identity in UTF-8: the controller id given to the bridge
//! (`--zenoh-controller` on the robot's side names the one allowed).

use std::time::{Duration, SystemTime, UNIX_EPOCH};

/// Commands older than this on arrival are dropped.
pub const MAX_COMMAND_AGE: Duration = Duration::from_millis(500);

/// A command's sender and send time.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Stamp {
    pub sender: String,
    pub sent: SystemTime,
}

impl Stamp {
    /// `sender`, now.
    pub fn now(sender: &str) -> Stamp {
        Stamp {
            sender: sender.into(),
            sent: SystemTime::now(),
        }
    }

    pub fn encode(&self) -> Vec<u8> {
        let micros = self
            .sent
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| u64::try_from(d.as_micros()).unwrap_or(u64::MAX));
        let mut out = micros.to_be_bytes().to_vec();
        out.extend_from_slice(self.sender.as_bytes());
        out
    }

    pub fn decode(raw: &[u8]) -> Option<Stamp> {
        let (micros, sender) = raw.split_first_chunk::<8>()?;
        Some(Stamp {
            sender: std::str::from_utf8(sender).ok()?.into(),
            sent: UNIX_EPOCH + Duration::from_micros(u64::from_be_bytes(*micros)),
        })
    }

    /// How long ago it was sent (zero if the sender's clock is ahead of ours).
    pub fn age(&self, now: SystemTime) -> Duration {
        now.duration_since(self.sent).unwrap_or_default()
    }

    /// Whether it is still fresh enough to act on.
    pub fn is_fresh(&self, now: SystemTime) -> bool {
        self.age(now) <= MAX_COMMAND_AGE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stamp_round_trips() {
        let stamp = Stamp::now("teacher");
        let back = Stamp::decode(&stamp.encode()).expect("decodes");
        assert_eq!(back.sender, "teacher");
        let drift = back.sent.duration_since(stamp.sent).unwrap_or_default();
        assert!(drift < Duration::from_micros(1));
        assert!(back.is_fresh(SystemTime::now()));
    }

    #[test]
    fn an_old_command_is_stale() {
        let stamp = Stamp {
            sender: "x".into(),
            sent: SystemTime::now() - Duration::from_secs(2),
        };
        assert!(!stamp.is_fresh(SystemTime::now()));
        assert_eq!(Stamp::decode(&[1, 2, 3]), None);
    }
}
