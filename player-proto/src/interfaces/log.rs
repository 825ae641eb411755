//! The `log` interface (code 45): control of a device that writes data to a log or plays a
//! log back as if the logged devices were live (Player's `writelog` and `readlog` drivers; here
//! also `player-sim --replay`).
//!
//! Requests 1–5 are Player's. Player sets the playback speed only in the driver's
//! configuration and has no way to seek, step or report where playback is, which a timeline
//! needs; those are this project's extension, numbered after Player's and laid out as Player's
//! generator lays out a struct, so a Player client that knows nothing of them never meets
//! them (it never asks, and it does not subscribe to `log` devices for data):
//!
//! | Class | Subtype | Body | Meaning |
//! |---|---|---|---|
//! | request | 6 | [`LogSetReadSpeed`] | playback speed, 1 = real time (`readlog`'s `speed` option, at run time) |
//! | request | 7 | [`LogSetReadPosition`] | seek: seconds from the log's start |
//! | request | 8 | [`LogReadStep`] | advance this many seconds of log (0: to the next message) |
//! | data | 1 | [`LogPlayback`] | where playback is, sent to subscribers while it is served |

use crate::wire::PlayerString;

/// `PLAYER_LOG_TYPE_READ`: a device that plays a log back.
pub const TYPE_READ: u8 = 1;
/// `PLAYER_LOG_TYPE_WRITE`: a device that writes a log.
pub const TYPE_WRITE: u8 = 2;

/// Request subtypes (Player's, then this project's).
pub const REQ_SET_WRITE_STATE: u8 = 1;
pub const REQ_SET_READ_STATE: u8 = 2;
pub const REQ_GET_STATE: u8 = 3;
/// Bodiless: back to the start, playing or paused as before.
pub const REQ_SET_READ_REWIND: u8 = 4;
pub const REQ_SET_FILENAME: u8 = 5;
pub const REQ_SET_READ_SPEED: u8 = 6;
pub const REQ_SET_READ_POSITION: u8 = 7;
pub const REQ_READ_STEP: u8 = 8;
/// Data subtype of [`LogPlayback`].
pub const DATA_PLAYBACK: u8 = 1;

/// Filename bytes, NUL included (`char filename[256]`).
pub const MAX_FILENAME: u32 = 256;

xdr_struct! {
    /// `player_log_set_write_state_t`: start (1) or stop (0) writing.
    #[derive(Copy)]
    pub struct LogSetWriteState {
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_log_set_read_state_t`: play (1) or pause (0).
    #[derive(Copy)]
    pub struct LogSetReadState {
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_log_get_state_t`: asked with an empty body; `kind` is `TYPE_READ` or
    /// `TYPE_WRITE` (Player's field is `type`), `state` 1 while playing or writing.
    #[derive(Copy)]
    pub struct LogState {
        pub kind: u8,
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_log_set_filename_t`: the file a write device writes next.
    pub struct LogSetFilename {
        pub filename: PlayerString [max MAX_FILENAME],
    }
}

xdr_struct! {
    /// Extension: playback speed, recorded seconds per real second (above 0).
    #[derive(Copy)]
    pub struct LogSetReadSpeed {
        pub speed: f64,
    }
}

xdr_struct! {
    /// Extension: seek to `position` seconds after the log's first message.
    #[derive(Copy)]
    pub struct LogSetReadPosition {
        pub position: f64,
    }
}

xdr_struct! {
    /// Extension: play `seconds` more of the log, then stand still (0: up to the next
    /// message).
    #[derive(Copy)]
    pub struct LogReadStep {
        pub seconds: f64,
    }
}

xdr_struct! {
    /// Extension: where playback is. `state` 1 while playing; `position` and `duration` in
    /// seconds of log, from its first message.
    #[derive(Copy)]
    pub struct LogPlayback {
        pub state: u8,
        pub speed: f64,
        pub position: f64,
        pub duration: f64,
    }
}

interface_messages! {
    /// Messages of the `log` interface.
    pub enum Log for LOG {
        Request 1 as REQ_SET_WRITE_STATE => SetWriteState(LogSetWriteState),
        Request 2 as REQ_SET_READ_STATE => SetReadState(LogSetReadState),
        Request 3 as REQ_GET_STATE => State(LogState),
        Request 5 as REQ_SET_FILENAME => SetFilename(LogSetFilename),
        Request 6 as REQ_SET_READ_SPEED => SetReadSpeed(LogSetReadSpeed),
        Request 7 as REQ_SET_READ_POSITION => SetReadPosition(LogSetReadPosition),
        Request 8 as REQ_READ_STEP => ReadStep(LogReadStep),
        Data 1 as DATA_PLAYBACK => Playback(LogPlayback),
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::message::MessageSet;
    use crate::message::{Body, Message};
    use crate::wire::{DevAddr, FrameDecoder, Interface};

    proptest! {
        #[test]
        fn every_log_message_round_trips_through_a_byte_stream(log in any::<Log>()) {
            let msg_type = log.class().default_type();
            let original = Message::typed(DevAddr::local(Interface::LOG, 0), msg_type, log);
            let bytes = original.to_bytes();
            let mut frames = FrameDecoder::default();
            frames.extend(&bytes);
            let frame = frames.next_frame().unwrap().expect("a whole frame");
            let decoded = Message::decode(frame.header, frame.body).unwrap();
            prop_assert!(matches!(decoded.body, Body::Log(_)));
            prop_assert_eq!(decoded.to_bytes(), bytes);
        }
    }

    #[test]
    fn a_playback_report_is_laid_out_as_player_lays_out_a_struct() {
        let report = LogPlayback {
            state: 1,
            speed: 2.0,
            position: 0.5,
            duration: 10.0,
        };
        let bytes = Message::typed(
            DevAddr::local(Interface::LOG, 0),
            crate::wire::MsgType::Data,
            Log::Playback(report),
        )
        .to_bytes();
        let body = &bytes[crate::wire::HEADER_LEN..];
        // state widened to 4 bytes, then three XDR doubles.
        assert_eq!(body.len(), 4 + 3 * 8);
        assert_eq!(&body[..4], &[0, 0, 0, 1]);
        assert_eq!(&body[4..12], &2.0f64.to_be_bytes());
    }
}
