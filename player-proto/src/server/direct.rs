//! A connection's data written by the publishing thread itself. Waking each connection's
//! writer task for every step cost a task wake-up per connection per step, and on a machine
//! where a thread's wake-up is dear (a VM) that was a good part of what serving 1 024 robots
//! costs. So where the server lets it (`ServerConfig::publisher_writes`, as player-sim
//! does), the publisher, having queued a step's messages, encodes each connection's
//! sendable messages and offers them to its socket in one non-blocking write. What the socket
//! does not take — a slow client, a full send buffer — is handed to the writer task, which
//! owns the socket from then until it has written it all; meanwhile the publisher only wakes
//! it. Either way the bytes leave in queue order, never interleaved, and a publisher never
//! blocks on a client.
//!
//! Locks: the direct-write state, then the queue (both briefly), never the other way.

use std::io::{self, Write};
use std::net::TcpStream;

use std::sync::Mutex;

use bytes::{Buf, BytesMut};

use super::queue::OutQueue;

/// The publisher's side of a connection's socket.
#[derive(Debug, Default)]
pub(crate) struct DirectWrite {
    /// A second handle on the connection's socket (non-blocking) for the publisher's writes;
    /// none once the connection is closed, or if one could not be made (every write then
    /// goes through the writer task).
    socket: Option<TcpStream>,
    /// The writer task has the socket: it is writing, or will write `leftover`. The publisher
    /// leaves the socket alone and wakes the writer instead.
    writer_has_it: bool,
    /// Bytes a publisher's write left over, for the writer to send before anything newer.
    leftover: BytesMut,
}

impl DirectWrite {
    pub fn new(socket: Option<TcpStream>) -> DirectWrite {
        DirectWrite {
            socket,
            ..DirectWrite::default()
        }
    }
}

/// What the writer task is to send when it takes the socket.
pub(crate) struct WriterTurn {
    /// What a publisher's write left over: first.
    pub leftover: BytesMut,
    /// Then these, in order.
    pub messages: Vec<std::sync::Arc<crate::message::Message>>,
}

/// Called through the session ([`super::state::SessionState`]), which lends its lock on this,
/// its queue and the waking of its writer task: the direct writes need those, not the session.
impl DirectWrite {
    /// Writes what is sendable now from this thread, in one non-blocking write into `scratch`
    /// (reused between connections), or wakes the writer task when it has the socket or the
    /// socket would not take it all.
    pub fn flush_now(
        this: &Mutex<DirectWrite>,
        queue: &Mutex<OutQueue>,
        wake_writer: impl Fn(),
        scratch: &mut BytesMut,
    ) {
        let mut direct = this.lock().expect("direct write");
        if direct.writer_has_it || direct.socket.is_none() {
            drop(direct);
            wake_writer();
            return;
        }
        let ready = queue.lock().expect("queue").take_sendable();
        if ready.is_empty() {
            return;
        }
        scratch.clear();
        scratch.reserve(ready.iter().map(|m| m.encoded_len()).sum());
        for message in &ready {
            message.encode(scratch);
        }
        let written = match direct.socket.as_ref().map(|mut s| s.write(scratch)) {
            Some(Ok(n)) => n,
            Some(Err(e))
                if matches!(
                    e.kind(),
                    io::ErrorKind::WouldBlock | io::ErrorKind::Interrupted
                ) =>
            {
                0
            }
            Some(Err(e)) => {
                // The writer task meets the same error on its own socket and ends the
                // session; here only this handle goes.
                tracing::debug!("client write failed: {e}");
                direct.socket = None;
                0
            }
            None => 0,
        };
        if written < scratch.len() {
            scratch.advance(written);
            direct.leftover.extend_from_slice(scratch);
            direct.writer_has_it = true;
            drop(direct);
            wake_writer();
        }
    }

    /// The writer task takes the socket: what a publisher left over, then what is sendable.
    pub fn writer_takes(this: &Mutex<DirectWrite>, queue: &Mutex<OutQueue>) -> WriterTurn {
        let mut direct = this.lock().expect("direct write");
        direct.writer_has_it = true;
        WriterTurn {
            leftover: std::mem::take(&mut direct.leftover),
            messages: queue.lock().expect("queue").take_sendable(),
        }
    }

    /// The writer task has written its turn: the publisher may write again.
    pub fn writer_done(this: &Mutex<DirectWrite>) {
        this.lock().expect("direct write").writer_has_it = false;
    }

    /// Lets go of the publisher's handle on the socket, so that the connection closes when
    /// its session ends, whoever still holds the session.
    pub fn drop_socket(this: &Mutex<DirectWrite>) {
        this.lock().expect("direct write").socket = None;
    }
}
