//! What the handle asks of the robot thread. The handle never changes the session itself: it
//! sends one of these, and the thread alone decides what the session is and what to restore
//! after a reconnect.

use std::sync::mpsc;

use super::requests::{ReplySender, RequestError};
use crate::delivery::{DataMode, ReplaceRule};
use crate::message::Message;
use crate::wire::Interface;

/// Where the outcome of a PULL round goes: the number of DATA messages it brought.
pub(crate) type PullWaiter = mpsc::Sender<Result<usize, RequestError>>;

pub(crate) enum Command {
    /// A request to a device, answered by its reply.
    Request {
        message: Message,
        reply: ReplySender,
    },
    /// Fire and forget.
    Send(Message),
    /// Keep this device's data, now and after every reconnect, unless the server refuses.
    Subscribe {
        device: (Interface, u16),
        reply: ReplySender,
    },
    /// Stop keeping this device's data and forget what was kept.
    Unsubscribe {
        device: (Interface, u16),
        reply: ReplySender,
    },
    /// Switch PUSH/PULL, now and after every reconnect.
    SetDataMode {
        mode: DataMode,
        reply: ReplySender,
    },
    /// Add a replace rule, now and after every reconnect.
    AddReplaceRule {
        rule: ReplaceRule,
        reply: ReplySender,
    },
    /// PULL: ask for a round of data.
    Pull(PullWaiter),
    Shutdown,
}
