//! Making a recorded session smaller without breaking it, so that a long stream (a camera
//! sending 57 600-byte frames) can live in the repository as a few frames.
//!
//! A cut through a message would leave a stream that no longer frames, so trimming works on
//! whole messages: both directions are framed, the DATA messages past the first few of each
//! direction are dropped, and everything else (the banner, requests, replies, commands, SYNCHs)
//! is kept, so the session's handshake and its ending stay as they were recorded.

use std::ops::Range;

use crate::wire::{BANNER_LEN, FrameDecoder, FrameError, HEADER_LEN, MsgType};

use super::{Chunk, Direction};

/// Why a capture cannot be trimmed: one of its streams does not frame.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TrimError {
    #[error("{dir} stream: {source}")]
    Framing { dir: Direction, source: FrameError },
    #[error("{dir} stream ends inside a message (at stream byte {at})")]
    Truncated { dir: Direction, at: u64 },
}

/// One whole message (or the banner) of one direction.
struct Piece {
    /// The recorded chunk that completed it: its time is when the message had fully arrived.
    completed_in: usize,
    /// Its bytes within the direction's stream.
    range: Range<usize>,
    is_data: bool,
}

/// Cuts one direction's stream into its banner and messages.
fn pieces(chunks: &[Chunk], dir: Direction) -> Result<(Vec<u8>, Vec<Piece>), TrimError> {
    let mut stream = Vec::new();
    // (stream length after the chunk, the chunk's index), in stream order.
    let mut chunk_ends = Vec::new();
    for (index, chunk) in chunks.iter().enumerate().filter(|(_, c)| c.dir == dir) {
        stream.extend_from_slice(&chunk.bytes);
        chunk_ends.push((stream.len(), index));
    }
    let completed_in = |end: usize| chunk_ends[chunk_ends.partition_point(|(e, _)| *e < end)].1;
    let framing = |source| TrimError::Framing { dir, source };

    let mut frames = FrameDecoder::default();
    frames.extend(&stream);
    let mut pieces = Vec::new();
    if dir == Direction::ServerToClient && !stream.is_empty() {
        match frames.take_banner() {
            Some(banner) => banner.map_err(|e| framing(FrameError::Banner(e)))?,
            None => return Err(TrimError::Truncated { dir, at: 0 }),
        };
        pieces.push(Piece {
            completed_in: completed_in(BANNER_LEN),
            range: 0..BANNER_LEN,
            is_data: false,
        });
    }
    while let Some(frame) = frames.next_frame().map_err(framing)? {
        let start = usize::try_from(frame.offset).expect("the stream is in memory");
        let end = start + HEADER_LEN + frame.body.len();
        pieces.push(Piece {
            completed_in: completed_in(end),
            range: start..end,
            is_data: frame.header.msg_type == MsgType::Data,
        });
    }
    if frames.buffered() > 0 {
        return Err(TrimError::Truncated {
            dir,
            at: frames.offset(),
        });
    }
    Ok((stream, pieces))
}

/// The session with only the first `keep` DATA messages of each direction; every other
/// message stays. Each kept message becomes one chunk of its own, timed by the recorded chunk
/// that completed it, and chunks stay in recorded order.
pub fn keep_first_data(chunks: &[Chunk], keep: usize) -> Result<Vec<Chunk>, TrimError> {
    let mut kept = Vec::new();
    for dir in [Direction::ServerToClient, Direction::ClientToServer] {
        let (stream, pieces) = pieces(chunks, dir)?;
        let mut data_seen = 0;
        for piece in pieces {
            if piece.is_data {
                data_seen += 1;
                if data_seen > keep {
                    continue;
                }
            }
            let chunk = Chunk {
                t: chunks[piece.completed_in].t,
                dir,
                bytes: stream[piece.range.clone()].to_vec(),
            };
            kept.push(((piece.completed_in, piece.range.start), chunk));
        }
    }
    // Pieces completed by one recorded chunk share its direction, so this is recorded order.
    kept.sort_by_key(|(order, _)| *order);
    Ok(kept.into_iter().map(|(_, chunk)| chunk).collect())
}

#[cfg(test)]
mod tests {
    use bytes::Bytes;

    use super::*;
    use crate::capture::stream;
    use crate::message::{Body, Message};
    use crate::wire::{Banner, DevAddr, Interface};

    const SUBTYPE: u8 = 1;

    fn message(msg_type: MsgType, body: &[u8]) -> Vec<u8> {
        let addr = DevAddr::local(Interface::LASER, 0);
        let body = Body::Unknown(Bytes::copy_from_slice(body));
        Message::new(addr, msg_type, SUBTYPE, body)
            .to_bytes()
            .to_vec()
    }

    fn chunk(t: f64, dir: Direction, bytes: &[u8]) -> Chunk {
        Chunk {
            t,
            dir,
            bytes: bytes.to_vec(),
        }
    }

    /// A subscription ACK, three DATA messages and a closing ACK from the server, recorded in
    /// chunks that cut through messages; a request and a command from the client.
    fn session() -> (Vec<Chunk>, Vec<Vec<u8>>) {
        use Direction::{ClientToServer as C2s, ServerToClient as S2c};
        let banner = Banner::new("3.1.1-dev").unwrap().to_bytes().to_vec();
        let s2c = [
            banner,
            message(MsgType::Ack, &[]),
            message(MsgType::Data, &[1; 8]),
            message(MsgType::Data, &[2; 8]),
            message(MsgType::Data, &[3; 8]),
            message(MsgType::Ack, &[4; 4]),
        ];
        let all: Vec<u8> = s2c.concat();
        let request = message(MsgType::Req, &[]);
        let command = message(MsgType::Cmd, &[5; 4]);
        let half = HEADER_LEN / 2;
        let chunks = vec![
            chunk(0.1, S2c, &all[..BANNER_LEN + 10]),
            chunk(0.2, C2s, &request[..half]),
            chunk(0.3, C2s, &[&request[half..], &command[..]].concat()),
            chunk(0.4, S2c, &all[BANNER_LEN + 10..all.len() - 3]),
            chunk(0.5, S2c, &all[all.len() - 3..]),
        ];
        (chunks, s2c.to_vec())
    }

    #[test]
    fn only_data_past_the_first_few_is_dropped_and_the_rest_frames() {
        let (chunks, s2c) = session();
        let trimmed = keep_first_data(&chunks, 1).unwrap();
        let want: Vec<u8> = [&s2c[0][..], &s2c[1], &s2c[2], &s2c[5]].concat();
        assert_eq!(stream(&trimmed, Direction::ServerToClient), want);
        assert_eq!(
            stream(&trimmed, Direction::ClientToServer),
            stream(&chunks, Direction::ClientToServer)
        );
        // Trimming what is already trimmed changes nothing.
        assert_eq!(keep_first_data(&trimmed, 1).unwrap(), trimmed);
    }

    #[test]
    fn each_message_is_a_chunk_timed_when_it_had_arrived() {
        let (chunks, _) = session();
        let trimmed = keep_first_data(&chunks, usize::MAX).unwrap();
        let times: Vec<(f64, Direction)> = trimmed.iter().map(|c| (c.t, c.dir)).collect();
        use Direction::{ClientToServer as C2s, ServerToClient as S2c};
        assert_eq!(
            times,
            [
                (0.1, S2c), // the banner
                (0.3, C2s), // the request, completed by the second client chunk
                (0.3, C2s), // the command
                (0.4, S2c), // the ACK, cut by the first server chunk
                (0.4, S2c),
                (0.4, S2c),
                (0.4, S2c),
                (0.5, S2c), // the closing ACK's last bytes came last
            ]
        );
        for dir in [S2c, C2s] {
            assert_eq!(stream(&trimmed, dir), stream(&chunks, dir), "{dir}");
        }
    }

    #[test]
    fn a_stream_that_ends_inside_a_message_is_refused() {
        let (mut chunks, _) = session();
        chunks.pop();
        assert_eq!(
            keep_first_data(&chunks, 1),
            Err(TrimError::Truncated {
                dir: Direction::ServerToClient,
                at: u64::try_from(BANNER_LEN + 4 * HEADER_LEN + 3 * 8).unwrap(),
            })
        );
    }
}
