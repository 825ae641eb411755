//! The MCAP mapping's promises: a recording of real Player servers goes into MCAP and comes back
//! byte for byte; a cut, damaged, lying or foreign MCAP file is a clear error after everything
//! good before it, never a panic or an allocation the file asks for.

use std::io::Cursor;
use std::path::Path;

use player_proto::capture::parse_capture;
use player_proto::recording::from_capture::records_from_capture;
use player_proto::recording::{Event, Record, RecordingReader, RecordingWriter};

use super::*;

/// Every capture of real Player 3 + Stage 4 traffic in the repository, one connection each,
/// interleaved in time as a recorder of all of them would have them.
pub(crate) fn real_records() -> Vec<Record> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures");
    let mut paths: Vec<_> = [root.clone(), root.join("nav")]
        .iter()
        .flat_map(|dir| std::fs::read_dir(dir).expect("captures/"))
        .map(|entry| entry.expect("a capture").path())
        .filter(|p| p.extension().is_some_and(|e| e == "jsonl"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 20, "{} captures", paths.len());
    let mut records = Vec::new();
    for (number, path) in paths.iter().enumerate() {
        let text = std::fs::read_to_string(path).expect("a capture");
        let chunks = parse_capture(&text).expect("a capture parses");
        let connection = u32::try_from(number).expect("few captures") * 3 + 1;
        records.extend(records_from_capture(&chunks, "localhost", 6665, connection, 0).unwrap());
    }
    records.sort_by_key(|r| r.time_ns);
    // Robot threads race to a recorder's queue: time may step back between connections.
    let last = records.len() - 1;
    records.swap(last - 1, last);
    records
}

pub(crate) fn prec(records: &[Record]) -> Vec<u8> {
    let mut writer = RecordingWriter::new(Vec::new()).unwrap();
    for r in records {
        writer.write(r).unwrap();
    }
    writer.into_inner()
}

pub(crate) fn mcap_of(prec_bytes: &[u8], chunk_size: u64) -> Vec<u8> {
    // The other fields are the `foxglove` feature's: no update without it.
    #[allow(clippy::needless_update)]
    let options = McapOptions {
        chunk_size,
        ..McapOptions::default()
    };
    let reader = RecordingReader::new(prec_bytes).unwrap();
    let (converted, out) = prec_to_mcap(reader, Cursor::new(Vec::new()), options).unwrap();
    assert!(converted.stopped.is_none(), "{:?}", converted.stopped);
    out.into_inner()
}

/// The records an MCAP file gives, and the error that stopped them if one did.
fn read_mcap(bytes: &[u8]) -> (Vec<Record>, Option<McapReadError>) {
    let mut records = Vec::new();
    for record in McapRecords::new(bytes) {
        match record {
            Ok(r) => records.push(r),
            Err(e) => return (records, Some(e)),
        }
    }
    (records, None)
}

#[test]
fn a_real_recording_comes_back_byte_for_byte() {
    let records = real_records();
    let original = prec(&records);
    let mcap = mcap_of(&original, McapOptions::default().chunk_size);
    assert_eq!(&mcap[..8], MAGIC);
    let (converted, back) = mcap_to_prec(&mcap[..], Vec::new()).unwrap();
    assert!(converted.stopped.is_none(), "{:?}", converted.stopped);
    assert_eq!(converted.records, records.len() as u64);
    assert!(
        back == original,
        "the .prec differs after a trip through MCAP"
    );
}

#[test]
fn every_record_kind_and_direction_is_there() {
    let (records, stopped) = read_mcap(&mcap_of(&prec(&real_records()), 4096));
    assert!(stopped.is_none(), "{stopped:?}");
    let count = |f: &dyn Fn(&Event) -> bool| records.iter().filter(|r| f(&r.event)).count();
    use player_proto::capture::Direction::*;
    let to_server = count(&|e| {
        matches!(
            e,
            Event::Message {
                direction: ClientToServer,
                ..
            }
        )
    });
    let to_client = count(&|e| {
        matches!(
            e,
            Event::Message {
                direction: ServerToClient,
                ..
            }
        )
    });
    let connections = count(&|e| matches!(e, Event::Connection { .. }));
    let opened = count(&|e| matches!(e, Event::Opened { .. }));
    assert!(to_server > 20 && to_client > 100, "{to_server} {to_client}");
    assert!(connections >= 20 && opened >= 20, "{connections} {opened}");
}

#[test]
fn every_cut_keeps_the_whole_chunks_before_it_and_says_where() {
    let records = real_records();
    let mcap = mcap_of(&prec(&records), 4096);
    let mut kept_some = false;
    for cut in (9..mcap.len()).step_by(mcap.len() / 97) {
        let (got, stopped) = read_mcap(&mcap[..cut]);
        assert_eq!(got[..], records[..got.len()], "a prefix, cut at {cut}");
        kept_some |= !got.is_empty();
        let error = stopped.expect("a cut file is an error").to_string();
        assert!(
            error.contains("cut short or damaged at or before byte"),
            "{error}"
        );
    }
    assert!(kept_some, "no cut kept anything");
}

/// An MCAP file of another program's: one JSON message on `/chatter`.
pub(crate) fn foreign_mcap() -> Vec<u8> {
    let mut writer = mcap::Writer::new(Cursor::new(Vec::new())).unwrap();
    let channel = writer
        .add_channel(0, "/chatter", "json", &Default::default())
        .unwrap();
    let header = mcap::records::MessageHeader {
        channel_id: channel,
        sequence: 0,
        log_time: 1,
        publish_time: 1,
    };
    writer.write_to_known_channel(&header, b"{}").unwrap();
    writer.finish().unwrap();
    writer.into_inner().into_inner()
}

#[test]
fn a_file_without_player_channels_is_named_as_such() {
    let (got, stopped) = read_mcap(&foreign_mcap());
    assert!(got.is_empty());
    let error = stopped.expect("refused").to_string();
    assert!(error.contains("not a Player recording"), "{error}");
}

/// An MCAP file with one Player channel whose single message holds `data`.
fn one_message(data: &[u8]) -> Vec<u8> {
    let mut writer = mcap::Writer::new(Cursor::new(Vec::new())).unwrap();
    let meta = layout::Stream::ToClient.metadata(3, None);
    let channel = writer
        .add_channel(0, "/player/3/to_client", "player-xdr", &meta)
        .unwrap();
    for sequence in 0..2 {
        let header = mcap::records::MessageHeader {
            channel_id: channel,
            sequence,
            log_time: 5,
            publish_time: 5,
        };
        let message = if sequence == 0 {
            &GOOD_MESSAGE[..]
        } else {
            data
        };
        writer.write_to_known_channel(&header, message).unwrap();
    }
    writer.finish().unwrap();
    writer.into_inner().into_inner()
}

/// A Player header (XDR: every field at least 4 bytes) of a position2d:0 DATA message with an
/// empty body.
const GOOD_MESSAGE: [u8; 40] = {
    let mut m = [0u8; 40];
    m[11] = 4; // interf: position2d
    m[19] = 1; // type: DATA
    m[23] = 1; // subtype: state
    m
};

#[test]
fn garbage_and_lying_sizes_in_a_message_name_the_channel_and_the_message() {
    let mut lying = GOOD_MESSAGE;
    lying[36..40].copy_from_slice(&4_000_000_000u32.to_be_bytes());
    for (data, says) in [
        (&b"\x01\x02\x03"[..], "no 40-byte Player header"),
        (&lying[..], "announces 4000000000 body bytes"),
    ] {
        let (got, stopped) = read_mcap(&one_message(data));
        assert_eq!(got.len(), 1, "the good message before is kept");
        let error = stopped.expect("refused").to_string();
        assert!(
            error.contains("message 1 of channel \"/player/3/to_client\""),
            "{error}"
        );
        assert!(error.contains(says), "{error}");
    }
}

#[test]
fn a_lying_record_length_is_refused_without_allocating_it() {
    let mcap = mcap_of(&prec(&real_records()), 4096);
    // Walk the top-level records to the first chunk (opcode 6) and make it claim 2⁶² bytes.
    let mut at = MAGIC.len();
    while mcap[at] != 0x06 {
        let length = u64::from_le_bytes(mcap[at + 1..at + 9].try_into().unwrap());
        at += 9 + usize::try_from(length).unwrap();
    }
    let mut lying = mcap.clone();
    lying[at + 1..at + 9].copy_from_slice(&(1u64 << 62).to_le_bytes());
    let (got, stopped) = read_mcap(&lying);
    assert!(got.is_empty());
    let error = stopped.expect("refused").to_string();
    assert!(error.contains("at or before byte"), "{error}");
}

/// A chunk whose opcode byte is damaged into another record's (a summary offset, which a
/// linear reader passes over) loses its records: the reading stops where they are missing,
/// naming it, instead of going on with the records after them as if they followed.
#[test]
fn a_chunk_passed_over_is_a_gap_not_a_shorter_recording() {
    let (records, mcap) = small_recording();
    let mut chunks = Vec::new();
    let mut at = MAGIC.len();
    while mcap[at] != 0x0F {
        // Up to the data section's end record.
        if mcap[at] == 0x06 {
            chunks.push(at);
        }
        let length = u64::from_le_bytes(mcap[at + 1..at + 9].try_into().unwrap());
        at += 9 + usize::try_from(length).unwrap();
    }
    assert!(chunks.len() > 4, "{}", chunks.len());
    let mut gaps = 0;
    for &chunk in &chunks {
        let mut damaged = mcap.clone();
        damaged[chunk] = 0x0E;
        let (got, stopped) = read_mcap(&damaged);
        assert_eq!(&got[..], &records[..got.len()], "chunk at {chunk}");
        // A chunk after the recording's last Player message (Foxglove's alone) loses only the
        // end, which reads as a shorter recording, as a cut does.
        let Some(error) = stopped.map(|e| e.to_string()) else {
            continue;
        };
        // Else it stopped: at the gap, or at a message whose channel the lost chunk declared.
        if error.contains("the records between are missing") {
            gaps += 1;
            assert!(
                error.contains(&format!("but {} records came", got.len())),
                "{error}"
            );
        } else {
            assert!(
                error.contains("which no channel record declared"),
                "{error}"
            );
        }
    }
    assert!(gaps > 0);
}

#[cfg(feature = "foxglove")]
#[test]
fn every_laser_scan_is_also_a_foxglove_laser_scan() {
    use player_proto::capture::Direction;
    use player_proto::wire::{Interface, MsgType};
    let records = real_records();
    let scans = records
        .iter()
        .filter(|r| {
            matches!(&r.event, Event::Message { direction: Direction::ServerToClient, header, .. }
                if header.addr.interf == Interface::LASER
                    && header.msg_type == MsgType::Data
                    && header.subtype == 1 /* scan */)
        })
        .count();
    let mcap = mcap_of(&prec(&records), McapOptions::default().chunk_size);
    let mut foxglove_scans = 0;
    let mut schemas = std::collections::BTreeSet::new();
    for message in mcap::MessageStream::new(&mcap).unwrap() {
        let message = message.unwrap();
        let schema = message
            .channel
            .schema
            .as_ref()
            .expect("every channel has a schema");
        schemas.insert(schema.name.clone());
        if schema.name == "foxglove.LaserScan" && message.channel.topic.contains("/laser/") {
            foxglove_scans += 1;
        }
    }
    assert!(scans >= 10, "{scans} scans recorded");
    assert_eq!(foxglove_scans, scans);
    for name in [
        "player.Message",
        "player.Session",
        "foxglove.LaserScan",
        "foxglove.PoseInFrame",
        "foxglove.FrameTransform",
        "foxglove.Grid",
        "foxglove.RawImage",
        "foxglove.CompressedImage",
        "foxglove.SceneUpdate",
        "foxglove.Log",
    ] {
        assert!(schemas.contains(name), "no {name} in {schemas:?}");
    }
}

#[test]
fn a_channel_claiming_to_be_a_player_channel_without_sense_is_named() {
    let mut writer = mcap::Writer::new(Cursor::new(Vec::new())).unwrap();
    let mut meta = layout::Stream::Session.metadata(1, None);
    meta.insert(layout::META_CONNECTION.into(), "first".into());
    writer
        .add_channel(0, "/player/first/session", "json", &meta)
        .unwrap();
    writer.finish().unwrap();
    let (got, stopped) = read_mcap(&writer.into_inner().into_inner());
    assert!(got.is_empty());
    let error = stopped.expect("refused").to_string();
    assert!(error.contains("\"/player/first/session\""), "{error}");
    assert!(error.contains("\"first\" is not a number"), "{error}");
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// Damage anywhere — bytes changed, the file cut — is an error or fewer records, never a
    /// panic, and what is returned is the recording's beginning.
    #[test]
    fn damaged_files_never_panic(
        changes in proptest::collection::vec((0.0..1.0f64, proptest::prelude::any::<u8>()), 1..8),
        keep in 0.5..1.0f64,
    ) {
        let (records, mcap) = small_recording();
        let mut mcap = mcap.clone();
        let len = mcap.len();
        for (at, byte) in changes {
            let at = ((at * len as f64) as usize).min(len - 1);
            mcap[at] = byte;
        }
        mcap.truncate((keep * len as f64) as usize);
        let (got, _) = read_mcap(&mcap);
        // Chunks are checked whole before their records are returned: what comes back is the
        // recording's beginning, unchanged.
        proptest::prop_assert_eq!(&got[..], &records[..got.len()]);
    }
}

/// The first records of the real recording, and their MCAP file in 512-byte chunks (many).
fn small_recording() -> &'static (Vec<Record>, Vec<u8>) {
    static SMALL: std::sync::OnceLock<(Vec<Record>, Vec<u8>)> = std::sync::OnceLock::new();
    SMALL.get_or_init(|| {
        let records: Vec<Record> = real_records().into_iter().take(60).collect();
        let mcap = mcap_of(&prec(&records), 512);
        (records, mcap)
    })
}

#[test]
fn a_length_past_its_record_stops_the_reading_before_it_is_parsed() {
    let (records, mcap) = small_recording();
    // The header record right after the magic: opcode, length, then its profile's length.
    let mut damaged = mcap.clone();
    damaged[17..21].copy_from_slice(&3_327_152_921u32.to_le_bytes());
    let (got, error) = read_mcap(&damaged);
    assert!(got.is_empty() && !records.is_empty());
    let error = error.expect("an error").to_string();
    assert!(
        error.contains("header record's field 1 claims 3327152921 bytes"),
        "{error}"
    );
}
