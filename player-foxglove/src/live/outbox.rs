//! One viewer's queue of what is still to be written to it, filled by the robots' threads and
//! emptied by the viewer's task, a burst at a time (one write for all that waited).
//!
//! Messages are bounded in number and in bytes: past either bound the oldest are dropped (a
//! live view wants the newest; a camera's raw frame may be a megabyte). The newest message is
//! always kept, however big. Control messages (advertisements, statuses) are never dropped,
//! since a viewer missing an advertisement cannot subscribe; a viewer that lets
//! [`CONTROL_BACKLOG`] of them pile up is not reading and is closed.

use std::collections::VecDeque;
use std::sync::{Mutex, MutexGuard};

use axum::extract::ws::Utf8Bytes;
use bytes::Bytes;
use tokio::sync::Notify;

use super::wire::SubscriptionId;

/// Messages queued per viewer before the oldest are dropped (the SDK's default is 1024):
/// about a second of everything 16 robots send at 10 Hz, more than a live view needs to ride
/// out a stall, and room for the burst of latched messages a subscription brings.
pub const MESSAGE_BACKLOG: usize = 256;
/// Bytes of messages queued per viewer before the oldest are dropped: four raw camera
/// frames. The payloads are shared by every viewer, so this bounds what one stalled viewer
/// keeps alive that the others have already sent.
pub const BACKLOG_BYTES: usize = 4 << 20;
/// Control messages queued per viewer before it is closed.
pub const CONTROL_BACKLOG: usize = 1024;

/// One message on one of the viewer's subscriptions; the payload is shared.
#[derive(Debug, Clone)]
pub struct Data {
    pub subscription: SubscriptionId,
    pub log_time: u64,
    pub payload: Bytes,
}

/// What the viewer's task takes at once.
#[derive(Debug, Default)]
pub struct Batch {
    pub control: Vec<Utf8Bytes>,
    pub data: Vec<Data>,
    /// Messages dropped since the last batch (the viewer fell behind).
    pub dropped: u64,
}

#[derive(Default)]
struct Queue {
    control: VecDeque<Utf8Bytes>,
    data: VecDeque<Data>,
    bytes: usize,
    dropped: u64,
    /// Set when the viewer must go (control backlog full, or the server stops).
    closed: bool,
}

#[derive(Default)]
pub struct Outbox {
    queue: Mutex<Queue>,
    ready: Notify,
}

impl Outbox {
    fn lock(&self) -> MutexGuard<'_, Queue> {
        self.queue.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Queues a message, dropping the oldest past the bounds. Never waits on the viewer.
    pub fn push_data(&self, data: Data) {
        let mut queue = self.lock();
        if queue.closed {
            return;
        }
        queue.bytes += data.payload.len();
        queue.data.push_back(data);
        while queue.data.len() > 1
            && (queue.data.len() > MESSAGE_BACKLOG || queue.bytes > BACKLOG_BYTES)
        {
            if let Some(old) = queue.data.pop_front() {
                queue.bytes -= old.payload.len();
                queue.dropped += 1;
            }
        }
        drop(queue);
        self.ready.notify_one();
    }

    /// Queues a control message; a viewer with too many waiting is closed.
    pub fn push_control(&self, text: Utf8Bytes) {
        let mut queue = self.lock();
        if queue.closed {
            return;
        }
        if queue.control.len() >= CONTROL_BACKLOG {
            queue.closed = true;
        } else {
            queue.control.push_back(text);
        }
        drop(queue);
        self.ready.notify_one();
    }

    /// Tells the viewer's task to close.
    pub fn close(&self) {
        self.lock().closed = true;
        self.ready.notify_one();
    }

    /// Waits until something is queued (or the viewer must close), then takes all of it;
    /// `None` once closed.
    pub async fn next(&self) -> Option<Batch> {
        loop {
            {
                let mut queue = self.lock();
                if queue.closed {
                    return None;
                }
                if !queue.control.is_empty() || !queue.data.is_empty() {
                    queue.bytes = 0;
                    return Some(Batch {
                        control: queue.control.drain(..).collect(),
                        data: queue.data.drain(..).collect(),
                        dropped: std::mem::take(&mut queue.dropped),
                    });
                }
            }
            self.ready.notified().await;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data(len: usize) -> Data {
        Data {
            subscription: 1,
            log_time: 0,
            payload: Bytes::from(vec![0; len]),
        }
    }

    fn take(outbox: &Outbox) -> Batch {
        futures_util::FutureExt::now_or_never(outbox.next())
            .flatten()
            .expect("something queued")
    }

    #[test]
    fn the_oldest_go_past_the_count_or_the_bytes_and_the_newest_stays() {
        let outbox = Outbox::default();
        for _ in 0..MESSAGE_BACKLOG + 10 {
            outbox.push_data(data(1));
        }
        let batch = take(&outbox);
        assert_eq!(batch.data.len(), MESSAGE_BACKLOG);
        assert_eq!(batch.dropped, 10);

        for _ in 0..10 {
            outbox.push_data(data(BACKLOG_BYTES / 4));
        }
        assert_eq!(take(&outbox).data.len(), 4);
        outbox.push_data(data(BACKLOG_BYTES * 2));
        assert_eq!(
            take(&outbox).data.len(),
            1,
            "one message over the bound is kept"
        );
    }

    #[test]
    fn control_is_kept_until_too_much_then_the_viewer_closes() {
        let outbox = Outbox::default();
        outbox.push_control(Utf8Bytes::from_static("a"));
        outbox.push_data(data(1));
        let batch = take(&outbox);
        assert_eq!((batch.control.len(), batch.data.len()), (1, 1));
        for _ in 0..=CONTROL_BACKLOG {
            outbox.push_control(Utf8Bytes::from_static("a"));
        }
        assert!(futures_util::FutureExt::now_or_never(outbox.next()).is_some_and(|b| b.is_none()));
    }
}
