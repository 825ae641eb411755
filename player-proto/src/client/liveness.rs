//! Telling a stalled server from a quiet one.
//!
//! A Player server sends nothing at all while none of the subscribed devices has data, so
//! silence alone proves nothing. After `timeout` of silence the robot thread sends a probe —
//! a device-list request, which the server itself answers whatever its devices do — and only
//! if nothing arrives within `timeout` again is the server declared stalled.

use std::time::Duration;

use tokio::time::Instant;

/// What the robot thread should do now.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum Verdict {
    Alive,
    /// Silent for a whole timeout: send a probe.
    Probe,
    /// The probe went unanswered too: give up on this connection.
    Stalled(String),
}

/// The liveness bookkeeping of one connection; inert when no timeout is configured.
pub(crate) struct Liveness {
    timeout: Option<Duration>,
    last_heard: Instant,
    probe_sent: Option<Instant>,
}

impl Liveness {
    pub fn new(timeout: Option<Duration>) -> Liveness {
        Liveness {
            timeout,
            last_heard: Instant::now(),
            probe_sent: None,
        }
    }

    pub fn timeout(&self) -> Duration {
        self.timeout.unwrap_or_default()
    }

    /// Notes that the reader produced something (a message, or an error that ends the
    /// connection anyway) and passes it through.
    pub fn heard<T>(&mut self, what: T) -> T {
        self.last_heard = Instant::now();
        self.probe_sent = None;
        what
    }

    /// When to call [`Liveness::check`] next; `None` when disabled.
    pub fn deadline(&self) -> Option<Instant> {
        let timeout = self.timeout?;
        Some(match self.probe_sent {
            Some(sent) => sent + timeout,
            None => self.last_heard + timeout,
        })
    }

    pub fn check(&mut self, now: Instant) -> Verdict {
        let Some(timeout) = self.timeout else {
            return Verdict::Alive;
        };
        match self.probe_sent {
            Some(sent) if now >= sent + timeout => Verdict::Stalled(format!(
                "server stalled: nothing received for {:?}, not even the reply to a device-list probe",
                now - self.last_heard
            )),
            Some(_) => Verdict::Alive,
            None if now >= self.last_heard + timeout => {
                self.probe_sent = Some(now);
                Verdict::Probe
            }
            None => Verdict::Alive,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn disabled_never_probes() {
        let mut l = Liveness::new(None);
        assert_eq!(l.deadline(), None);
        assert_eq!(
            l.check(Instant::now() + Duration::from_secs(3600)),
            Verdict::Alive
        );
    }

    #[test]
    fn silence_probes_then_stalls_and_any_message_resets() {
        let t = Duration::from_secs(1);
        let mut l = Liveness::new(Some(t));
        let start = l.last_heard;
        assert_eq!(l.check(start + t / 2), Verdict::Alive);
        assert_eq!(l.check(start + t), Verdict::Probe);
        assert_eq!(l.deadline(), Some(start + 2 * t));
        assert_eq!(l.check(start + t + t / 2), Verdict::Alive);
        assert!(matches!(l.check(start + 2 * t), Verdict::Stalled(_)));

        let mut l = Liveness::new(Some(t));
        let start = l.last_heard;
        assert_eq!(l.check(start + t), Verdict::Probe);
        l.heard(());
        assert_eq!(
            l.deadline(),
            Some(l.last_heard + t),
            "the probe is forgotten"
        );
        assert_eq!(l.check(l.last_heard + t / 2), Verdict::Alive);
        assert_eq!(l.check(l.last_heard + t), Verdict::Probe);
    }
}
