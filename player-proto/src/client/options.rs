//! How a client connects, waits, and reconnects.

use std::fmt;
use std::sync::Arc;
use std::time::Duration;

use crate::delivery::DataMode;
use crate::wire::DEFAULT_MAX_BODY;

/// Retry timing after a server goes away: `initial`, doubling up to `max`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Backoff {
    pub initial: Duration,
    pub max: Duration,
    /// Give up (state `Failed`) after this many failed attempts; `None` = never.
    pub max_attempts: Option<u32>,
}

impl Default for Backoff {
    fn default() -> Self {
        Backoff {
            initial: Duration::from_millis(100),
            max: Duration::from_secs(5),
            max_attempts: None,
        }
    }
}

impl Backoff {
    /// The wait before attempt number `attempt` (1-based).
    pub fn delay(&self, attempt: u32) -> Duration {
        let factor = 2u32.saturating_pow(attempt.saturating_sub(1).min(16));
        self.initial.saturating_mul(factor).min(self.max)
    }
}

/// Called from the robot thread whenever new data was stored or the connection state changed.
/// Keep it cheap: wake a UI, bump a counter.
pub type Notifier = Arc<dyn Fn() + Send + Sync>;

/// Client settings; the defaults suit a viewer.
#[derive(Clone)]
pub struct ClientOptions {
    pub connect_timeout: Duration,
    /// How long a request waits for its ACK or NACK.
    pub request_timeout: Duration,
    pub data_mode: DataMode,
    /// Ask the server to keep only the newest DATA message per device and subtype in its queue
    /// (a slow reader then gets fresh data, never a backlog).
    pub replace_old_data: bool,
    /// An observer: commands and configuration requests are refused in the client, before
    /// they reach the socket (see [`super::RequestError::ReadOnly`]); Player 3 itself has no
    /// read-only access to ask the server for.
    pub read_only: bool,
    pub backoff: Backoff,
    /// Largest message body accepted; bigger ones end the connection before any allocation.
    pub max_body: usize,
    /// Requests waiting for a reply at once; more are refused at once.
    pub max_pending_requests: usize,
    /// Liveness check, off by default. When set and nothing has arrived for this long, the
    /// client sends a device-list request — which a Player server always answers, whatever
    /// its devices do — and if still nothing arrives within the same time again, the server
    /// is taken for stalled: the connection is dropped and re-established (state
    /// `Reconnecting`, [`super::Client::last_disconnect`] says why). Silence alone is never
    /// enough, because a Player server legitimately sends nothing while no device has data.
    /// Choose it longer than the biggest message takes to arrive.
    pub stall_timeout: Option<Duration>,
    /// Runs on the robot thread whenever there is something new to read: a data message was
    /// stored, or the connection state changed (a server that answered late or came back,
    /// with its device list, or one that went away). A viewer wakes its window with it.
    pub notifier: Option<Notifier>,
    /// Sees every message of the connection as it crossed the wire (a recorder).
    pub tap: Option<super::Tap>,
    /// Run the connection on these shared threads rather than a thread of its own (for
    /// programs that open hundreds of robots; see [`super::SharedIo`]).
    pub shared_io: Option<super::SharedIo>,
}

impl Default for ClientOptions {
    fn default() -> Self {
        ClientOptions {
            connect_timeout: Duration::from_secs(3),
            request_timeout: Duration::from_secs(5),
            data_mode: DataMode::Push,
            replace_old_data: true,
            read_only: false,
            backoff: Backoff::default(),
            max_body: DEFAULT_MAX_BODY,
            max_pending_requests: 256,
            stall_timeout: None,
            notifier: None,
            tap: None,
            shared_io: None,
        }
    }
}

impl fmt::Debug for ClientOptions {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("ClientOptions")
            .field("connect_timeout", &self.connect_timeout)
            .field("request_timeout", &self.request_timeout)
            .field("data_mode", &self.data_mode)
            .field("replace_old_data", &self.replace_old_data)
            .field("read_only", &self.read_only)
            .field("backoff", &self.backoff)
            .field("max_body", &self.max_body)
            .field("max_pending_requests", &self.max_pending_requests)
            .field("stall_timeout", &self.stall_timeout)
            .field("notifier", &self.notifier.is_some())
            .field("tap", &self.tap.is_some())
            .field("shared_io", &self.shared_io)
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backoff_doubles_up_to_its_ceiling() {
        let b = Backoff::default();
        assert_eq!(b.delay(1), Duration::from_millis(100));
        assert_eq!(b.delay(3), Duration::from_millis(400));
        assert_eq!(b.delay(30), Duration::from_secs(5));
    }
}
