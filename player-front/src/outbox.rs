//! One viewer's queue of what is still to be written to it, filled by the robots' threads and
//! emptied by the viewer's task, a burst at a time (one write for all that waited).
//!
//! Newest wins: data is bounded in number and in bytes, and past either bound the oldest is
//! dropped (a live view wants the newest; a camera's raw frame may be a megabyte). The newest
//! message is always kept, however big. Control messages (what the viewer must know to
//! understand the data: advertisements, statuses) are never dropped; a viewer that lets
//! [`Bounds::control`] of them pile up is not reading and is closed.

use std::collections::VecDeque;
use std::sync::{Mutex, MutexGuard};

use axum::extract::ws::Utf8Bytes;
use tokio::sync::Notify;

/// What a queued message weighs against [`Bounds::bytes`].
pub trait Weigh {
    fn weight(&self) -> usize;
}

/// How much one viewer's outbox holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bounds {
    /// Data messages before the oldest are dropped.
    pub messages: usize,
    /// Bytes of data before the oldest are dropped.
    pub bytes: usize,
    /// Control messages before the viewer is closed.
    pub control: usize,
}

/// What the viewer's task takes at once.
#[derive(Debug)]
pub struct Batch<D> {
    pub control: Vec<Utf8Bytes>,
    pub data: Vec<D>,
    /// Data dropped since the last batch (the viewer fell behind).
    pub dropped: u64,
}

struct Queue<D> {
    control: VecDeque<Utf8Bytes>,
    data: VecDeque<D>,
    bytes: usize,
    dropped: u64,
    /// Set when the viewer must go (control backlog full, or the server stops).
    closed: bool,
}

pub struct Outbox<D> {
    bounds: Bounds,
    queue: Mutex<Queue<D>>,
    ready: Notify,
}

impl<D: Weigh> Outbox<D> {
    pub fn new(bounds: Bounds) -> Outbox<D> {
        Outbox {
            bounds,
            queue: Mutex::new(Queue {
                control: VecDeque::new(),
                data: VecDeque::new(),
                bytes: 0,
                dropped: 0,
                closed: false,
            }),
            ready: Notify::new(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, Queue<D>> {
        // Every change is whole under the lock: a poisoned lock still guards a usable queue.
        self.queue.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Queues a message, dropping the oldest past the bounds. Never waits on the viewer.
    pub fn push_data(&self, data: D) {
        let mut queue = self.lock();
        if queue.closed {
            return;
        }
        queue.bytes += data.weight();
        queue.data.push_back(data);
        while queue.data.len() > 1
            && (queue.data.len() > self.bounds.messages || queue.bytes > self.bounds.bytes)
        {
            if let Some(old) = queue.data.pop_front() {
                queue.bytes -= old.weight();
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
        if queue.control.len() >= self.bounds.control {
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
    pub async fn next(&self) -> Option<Batch<D>> {
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

    /// A message of so many bytes.
    struct Weighing(usize);

    impl Weigh for Weighing {
        fn weight(&self) -> usize {
            self.0
        }
    }

    const BOUNDS: Bounds = Bounds {
        messages: 256,
        bytes: 4 << 20,
        control: 1024,
    };

    fn take(outbox: &Outbox<Weighing>) -> Batch<Weighing> {
        futures_util::FutureExt::now_or_never(outbox.next())
            .flatten()
            .expect("something queued")
    }

    #[test]
    fn the_oldest_go_past_the_count_or_the_bytes_and_the_newest_stays() {
        let outbox = Outbox::new(BOUNDS);
        for _ in 0..BOUNDS.messages + 10 {
            outbox.push_data(Weighing(1));
        }
        let batch = take(&outbox);
        assert_eq!(batch.data.len(), BOUNDS.messages);
        assert_eq!(batch.dropped, 10);

        for _ in 0..10 {
            outbox.push_data(Weighing(BOUNDS.bytes / 4));
        }
        assert_eq!(take(&outbox).data.len(), 4);
        outbox.push_data(Weighing(BOUNDS.bytes * 2));
        assert_eq!(
            take(&outbox).data.len(),
            1,
            "one message over the bound is kept"
        );
    }

    #[test]
    fn control_is_kept_until_too_much_then_the_viewer_closes() {
        let outbox = Outbox::new(BOUNDS);
        outbox.push_control(Utf8Bytes::from_static("a"));
        outbox.push_data(Weighing(1));
        let batch = take(&outbox);
        assert_eq!((batch.control.len(), batch.data.len()), (1, 1));
        for _ in 0..=BOUNDS.control {
            outbox.push_control(Utf8Bytes::from_static("a"));
        }
        assert!(futures_util::FutureExt::now_or_never(outbox.next()).is_some_and(|b| b.is_none()));
    }
}
