//! The hand-over from a robot thread to the publishing task. The tap runs on the robot's
//! thread and must never wait, so it pushes onto a bounded queue; when the queue is full the
//! oldest DATA message makes room — newest data wins, as everywhere in the relay — and is
//! counted. Connection events and replies are never dropped: they are few, and losing one
//! would leave a robot announced that is gone, or a device undescribed.

use std::collections::VecDeque;
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::SystemTime;

use bytes::Bytes;
use player_proto::capture::Direction;
use player_proto::wire::Header;
use tokio::sync::Notify;

use crate::keys::RobotKey;

/// What a robot thread tells the publishing task.
#[derive(Debug, Clone)]
pub enum FrontEvent {
    Opened(RobotKey),
    Frame {
        robot: RobotKey,
        time: SystemTime,
        direction: Direction,
        header: Header,
        body: Bytes,
    },
    Closed(RobotKey, String),
}

impl FrontEvent {
    fn is_data(&self) -> bool {
        matches!(self, FrontEvent::Frame { direction: Direction::ServerToClient, header, .. }
            if header.msg_type == player_proto::wire::MsgType::Data)
    }
}

/// A bounded queue that drops the oldest data when full.
pub struct EventQueue {
    events: Mutex<VecDeque<FrontEvent>>,
    capacity: usize,
    dropped: AtomicU64,
    ready: Notify,
}

impl EventQueue {
    pub fn new(capacity: usize) -> EventQueue {
        EventQueue {
            events: Mutex::new(VecDeque::with_capacity(capacity)),
            capacity: capacity.max(1),
            dropped: AtomicU64::new(0),
            ready: Notify::new(),
        }
    }

    /// Never blocks for longer than a push onto a short list.
    pub fn push(&self, event: FrontEvent) {
        {
            let mut events = self.events.lock().unwrap_or_else(|e| e.into_inner());
            if events.len() >= self.capacity {
                match events.iter().position(FrontEvent::is_data) {
                    Some(oldest) => {
                        events.remove(oldest);
                        self.dropped.fetch_add(1, Ordering::Relaxed);
                    }
                    None if event.is_data() => {
                        self.dropped.fetch_add(1, Ordering::Relaxed);
                        return;
                    }
                    None => {}
                }
            }
            events.push_back(event);
        }
        self.ready.notify_one();
    }

    /// Everything queued, waiting for something if nothing is.
    pub async fn take_all(&self) -> Vec<FrontEvent> {
        loop {
            {
                let mut events = self.events.lock().unwrap_or_else(|e| e.into_inner());
                if !events.is_empty() {
                    return events.drain(..).collect();
                }
            }
            self.ready.notified().await;
        }
    }

    /// DATA messages dropped because the publishing task fell behind.
    pub fn dropped(&self) -> u64 {
        self.dropped.load(Ordering::Relaxed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::wire::{DevAddr, Interface, MsgType};

    fn data(seq: u32) -> FrontEvent {
        FrontEvent::Frame {
            robot: RobotKey::new("a", "h", 1),
            time: SystemTime::now(),
            direction: Direction::ServerToClient,
            header: Header {
                addr: DevAddr {
                    host: 0,
                    robot: 1,
                    interf: Interface::LASER,
                    index: 0,
                },
                msg_type: MsgType::Data,
                subtype: 1,
                timestamp: 0.0,
                seq,
                size: 0,
            },
            body: Bytes::new(),
        }
    }

    #[tokio::test]
    async fn a_full_queue_drops_its_oldest_data_and_keeps_events() {
        let queue = EventQueue::new(2);
        queue.push(FrontEvent::Opened(RobotKey::new("a", "h", 1)));
        queue.push(data(1));
        queue.push(data(2));
        queue.push(data(3));
        assert_eq!(queue.dropped(), 2);
        let events = queue.take_all().await;
        assert!(matches!(events[0], FrontEvent::Opened(_)));
        assert!(matches!(&events[1], FrontEvent::Frame { header, .. } if header.seq == 3));
    }
}
