//! Turning a capture (the JSON-lines `recv()` chunks of `captures/`) into recording records,
//! so real Player traffic can be replayed and exported like a recording.
//!
//! A capture has no wall-clock time: record times are the capture's seconds since the
//! connection was accepted, plus `start_ns`. A message is timed by the chunk that completed it.

use super::format::{Event, Record};
use crate::capture::{Chunk, Direction};
use crate::wire::{BANNER_LEN, FrameDecoder, FrameError};

const NS_PER_S: f64 = 1e9;

/// Why a capture cannot be turned into records.
#[derive(Debug, thiserror::Error)]
pub enum FromCaptureError {
    #[error("the {direction} stream of the capture is broken: {source}")]
    Frame {
        direction: Direction,
        source: FrameError,
    },
    #[error("the capture ends before the server's banner")]
    NoBanner,
}

/// The records of one captured connection, numbered `connection`; the port is the one the
/// server wrote into its messages' addresses (`fallback_port` if it wrote none).
pub fn records_from_capture(
    chunks: &[Chunk],
    host: &str,
    fallback_port: u16,
    connection: u32,
    start_ns: u64,
) -> Result<Vec<Record>, FromCaptureError> {
    let at = |t: f64| start_ns.saturating_add((t.max(0.0) * NS_PER_S) as u64);
    let record = |time_ns, event| Record {
        time_ns,
        connection,
        event,
    };
    let mut from_server = FrameDecoder::default();
    let mut to_server = FrameDecoder::default();
    let mut banner_seen = false;
    let mut records = Vec::new();
    for chunk in chunks {
        let decoder = match chunk.dir {
            Direction::ServerToClient => &mut from_server,
            Direction::ClientToServer => &mut to_server,
        };
        decoder.extend(&chunk.bytes);
        if chunk.dir == Direction::ServerToClient && !banner_seen {
            if decoder.buffered() < BANNER_LEN {
                continue;
            }
            let banner = decoder.take_banner().expect("32 bytes are there");
            let banner = banner.map_err(|e| FromCaptureError::Frame {
                direction: chunk.dir,
                source: e.into(),
            })?;
            banner_seen = true;
            records.push(record(
                at(chunk.t),
                Event::Opened {
                    banner: banner.to_bytes(),
                },
            ));
        }
        while let Some(frame) = decoder
            .next_frame()
            .map_err(|source| FromCaptureError::Frame {
                direction: chunk.dir,
                source,
            })?
        {
            records.push(record(
                at(chunk.t),
                Event::Message {
                    direction: chunk.dir,
                    header: frame.header,
                    body: frame.body,
                },
            ));
        }
    }
    if !banner_seen {
        return Err(FromCaptureError::NoBanner);
    }
    let port = records
        .iter()
        .find_map(|r| match &r.event {
            Event::Message {
                direction: Direction::ServerToClient,
                header,
                ..
            } if header.addr.robot != 0 => u16::try_from(header.addr.robot).ok(),
            _ => None,
        })
        .unwrap_or(fallback_port);
    let opened_at = records.first().map_or(start_ns, |r| r.time_ns);
    records.insert(
        0,
        record(
            opened_at,
            Event::Connection {
                host: host.to_string(),
                port,
            },
        ),
    );
    let closed_at = records.last().map_or(start_ns, |r| r.time_ns);
    records.push(record(
        closed_at,
        Event::Closed {
            why: "end of the capture".into(),
        },
    ));
    Ok(records)
}
