//! The recorder: a client [`Tap`] whose events go through a bounded queue to a thread that
//! writes them, buffered, and flushes whenever the queue runs dry — so a robot thread never
//! waits on the disk, and a crash loses at most what was still queued.
//!
//! Nothing is lost silently: a record the queue had no room for is counted as dropped, one
//! that arrived after writing failed (a full disk) as failed, and the first write error is
//! kept to be reported.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, SyncSender, TrySendError, sync_channel};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::SystemTime;

use super::format::{Event, Record, to_ns};
use super::sink::RecordSink;
use super::writer::{RecordingWriter, WriteError};
use crate::client::{ConnectionTap, Tap, TapEvent};

/// Records waiting for the writer at most. At the load test's 5 120 messages a second that is
/// over ten seconds of disk stall before anything is dropped.
pub const QUEUE_RECORDS: usize = 1 << 16;
/// The write buffer: large enough that a busy second of traffic is a few dozen system calls.
const BUFFER_BYTES: usize = 1 << 20;

/// Why recording could not start or did not end well.
#[derive(Debug, thiserror::Error)]
pub enum RecorderError {
    #[error("cannot create the recording {path}: {source}")]
    Create {
        path: String,
        source: std::io::Error,
    },
    #[error(transparent)]
    Write(#[from] WriteError),
    #[error("cannot start the recorder thread: {0}")]
    Thread(std::io::Error),
    #[error("the recorder thread panicked")]
    Panicked,
}

/// Declares a connection (host, port) at a time of the caller's clock; returns its tap.
pub type ConnectionOpener = Arc<dyn Fn(&str, u16, SystemTime) -> ConnectionTap + Send + Sync>;

/// Counters of a recording, readable while it runs.
#[derive(Debug, Default)]
struct Counters {
    written: AtomicU64,
    bytes: AtomicU64,
    dropped: AtomicU64,
    failed: AtomicU64,
    error: Mutex<Option<String>>,
}

/// What a recording has done so far.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct RecorderStats {
    /// Records written to the file (buffered ones included until the end).
    pub written: u64,
    /// File bytes written.
    pub bytes: u64,
    /// Records lost because the queue was full (the disk too slow).
    pub dropped: u64,
    /// Records lost because writing had failed.
    pub failed: u64,
    /// The write error that stopped the recording, if one did.
    pub error: Option<String>,
}

impl RecorderStats {
    /// Records that did not reach the file.
    pub fn lost(&self) -> u64 {
        self.dropped + self.failed
    }
}

/// What goes through the queue.
enum Item {
    Record(Record),
    /// Write what came before, flush, stop.
    Finish,
}

/// A recording in progress; [`Recorder::finish`] ends it.
pub struct Recorder {
    queue: Option<SyncSender<Item>>,
    counters: Arc<Counters>,
    connections: Arc<AtomicU32>,
    thread: Option<JoinHandle<()>>,
}

impl Recorder {
    /// Records to a new file at `path` (an existing one is replaced).
    pub fn create(path: &Path) -> Result<Recorder, RecorderError> {
        let file = File::create(path).map_err(|source| RecorderError::Create {
            path: path.display().to_string(),
            source,
        })?;
        Recorder::to_writer(BufWriter::with_capacity(BUFFER_BYTES, file))
    }

    /// Records to any writer (tests give one that fails).
    pub fn to_writer<W: Write + Send + 'static>(out: W) -> Result<Recorder, RecorderError> {
        Recorder::to_sink(RecordingWriter::new(out)?)
    }

    /// Records into any sink (another file format), started already.
    pub fn to_sink<S: RecordSink>(writer: S) -> Result<Recorder, RecorderError> {
        let counters = Arc::new(Counters::default());
        counters.bytes.store(writer.bytes(), Ordering::Relaxed);
        let (queue, records) = sync_channel(QUEUE_RECORDS);
        let thread = {
            let counters = counters.clone();
            std::thread::Builder::new()
                .name("recorder".into())
                .spawn(move || write_loop(writer, &records, &counters))
                .map_err(RecorderError::Thread)?
        };
        Ok(Recorder {
            queue: Some(queue),
            counters,
            connections: Arc::default(),
            thread: Some(thread),
        })
    }

    /// The tap to put in [`crate::client::ClientOptions::tap`]: each robot connection it is
    /// asked for gets a connection number, declared in the file at once.
    pub fn tap(&self) -> Tap {
        let opener = self.opener();
        Arc::new(move |host: &str, port: u16| opener(host, port, SystemTime::now()))
    }

    /// Like [`Self::tap`], with the time of each connection's declaration given: for a
    /// recording on a clock of its own (a simulation's).
    pub fn opener(&self) -> ConnectionOpener {
        let queue = self.queue.clone().expect("a recorder being recorded to");
        let counters = self.counters.clone();
        let connections = self.connections.clone();
        Arc::new(move |host: &str, port: u16, at: SystemTime| {
            let connection = connections.fetch_add(1, Ordering::Relaxed);
            let sink = Sink {
                queue: queue.clone(),
                counters: counters.clone(),
                connection,
            };
            sink.push(
                to_ns(at),
                Event::Connection {
                    host: host.to_string(),
                    port,
                },
            );
            let tap: ConnectionTap = Arc::new(move |time, event| sink.tapped(time, event));
            tap
        })
    }

    /// The counters so far.
    pub fn stats(&self) -> RecorderStats {
        let c = &self.counters;
        RecorderStats {
            written: c.written.load(Ordering::Relaxed),
            bytes: c.bytes.load(Ordering::Relaxed),
            dropped: c.dropped.load(Ordering::Relaxed),
            failed: c.failed.load(Ordering::Relaxed),
            error: c.error.lock().expect("recorder error").clone(),
        }
    }

    /// Writes what is queued, flushes, and returns the final counters. What taps still held
    /// by clients are handed afterwards is counted as failed: close the clients first.
    pub fn finish(mut self) -> Result<RecorderStats, RecorderError> {
        self.stop()?;
        Ok(self.stats())
    }

    fn stop(&mut self) -> Result<(), RecorderError> {
        if let Some(queue) = self.queue.take() {
            // Blocks only while the queue is full, i.e. until the writer has made room.
            let _ = queue.send(Item::Finish);
        }
        match self.thread.take() {
            Some(thread) => thread.join().map_err(|_| RecorderError::Panicked),
            None => Ok(()),
        }
    }
}

impl Drop for Recorder {
    fn drop(&mut self) {
        let _ = self.stop();
    }
}

/// One connection's way into the queue.
struct Sink {
    queue: SyncSender<Item>,
    counters: Arc<Counters>,
    connection: u32,
}

impl Sink {
    fn tapped(&self, time: SystemTime, event: TapEvent<'_>) {
        let event = match event {
            TapEvent::Opened(banner) => Event::Opened {
                banner: banner.to_bytes(),
            },
            TapEvent::Frame {
                direction,
                header,
                body,
            } => Event::Message {
                direction,
                header: *header,
                body: body.clone(),
            },
            TapEvent::Closed(why) => Event::Closed {
                why: why.to_string(),
            },
        };
        self.push(to_ns(time), event);
    }

    fn push(&self, time_ns: u64, event: Event) {
        let record = Record {
            time_ns,
            connection: self.connection,
            event,
        };
        match self.queue.try_send(Item::Record(record)) {
            Ok(()) => {}
            Err(TrySendError::Full(_)) => {
                self.counters.dropped.fetch_add(1, Ordering::Relaxed);
            }
            Err(TrySendError::Disconnected(_)) => {
                self.counters.failed.fetch_add(1, Ordering::Relaxed);
            }
        }
    }
}

/// The writer thread: write what comes, flush when nothing is waiting; after a write error,
/// count what still comes as failed.
fn write_loop<S: RecordSink>(mut writer: S, items: &Receiver<Item>, c: &Counters) {
    let mut broken = false;
    let fail = |e: S::Error, broken: &mut bool| {
        tracing::error!("recording stopped: {e}");
        *c.error.lock().expect("recorder error") = Some(e.to_string());
        *broken = true;
    };
    loop {
        let item = match items.try_recv() {
            Ok(item) => item,
            Err(_) => {
                if !broken && let Err(e) = writer.flush() {
                    fail(e, &mut broken);
                }
                match items.recv() {
                    Ok(item) => item,
                    Err(_) => Item::Finish,
                }
            }
        };
        let record = match item {
            Item::Record(record) => record,
            Item::Finish => break,
        };
        if broken {
            c.failed.fetch_add(1, Ordering::Relaxed);
            continue;
        }
        match writer.write(&record) {
            Ok(()) => {
                c.written.fetch_add(1, Ordering::Relaxed);
                c.bytes.store(writer.bytes(), Ordering::Relaxed);
            }
            Err(e) => {
                c.failed.fetch_add(1, Ordering::Relaxed);
                fail(e, &mut broken);
            }
        }
    }
    if !broken && let Err(e) = writer.finish() {
        fail(e, &mut broken);
    }
    // A format with an index writes it at the end.
    c.bytes.store(writer.bytes(), Ordering::Relaxed);
    // Whatever raced the finish is lost; count it.
    while let Ok(Item::Record(_)) = items.try_recv() {
        c.failed.fetch_add(1, Ordering::Relaxed);
    }
}
