//! The format's promises: what is written reads back identically; a torn tail, damage or a
//! failing disk is a clear error at the right offset, never a panic.

use std::io::{self, Write};
use std::sync::{Arc, Mutex};

use bytes::Bytes;
use proptest::prelude::*;

use super::format::{Event, FILE_HEADER_LEN, Record};
use super::{ReadError, Recorder, RecordingReader, RecordingWriter};
use crate::capture::Direction;
use crate::interfaces::laser::{Laser, LaserScan};
use crate::message::Message;
use crate::wire::{Banner, DevAddr, Interface, MsgType};

fn laser_message(n: usize) -> Message {
    let scan = LaserScan {
        ranges: vec![1.5; n],
        ..LaserScan::default()
    };
    Message::typed(
        DevAddr::local(Interface::LASER, 0),
        MsgType::Data,
        Laser::Scan(scan),
    )
    .at(1_700_000_000.25)
}

fn sample_records() -> Vec<Record> {
    let message = laser_message(361);
    let encoded = message.to_bytes();
    vec![
        Record {
            time_ns: 1,
            connection: 0,
            event: Event::Connection {
                host: "localhost".into(),
                port: 6665,
            },
        },
        Record {
            time_ns: 2,
            connection: 0,
            event: Event::Opened {
                banner: Banner::new("3.1.1-dev").unwrap().to_bytes(),
            },
        },
        Record {
            time_ns: 3,
            connection: 0,
            event: Event::Message {
                direction: Direction::ServerToClient,
                header: message.header,
                body: encoded.slice(crate::wire::HEADER_LEN..),
            },
        },
        Record {
            time_ns: 4,
            connection: 0,
            event: Event::Message {
                direction: Direction::ClientToServer,
                header: Message::new(
                    DevAddr::local(Interface::LASER, 0),
                    MsgType::Req,
                    1,
                    crate::message::Body::Empty,
                )
                .header,
                body: Bytes::new(),
            },
        },
        Record {
            time_ns: 5,
            connection: 0,
            event: Event::Closed {
                why: "the server closed the connection".into(),
            },
        },
    ]
}

fn written(records: &[Record]) -> Vec<u8> {
    let mut writer = RecordingWriter::new(Vec::new()).unwrap();
    for r in records {
        writer.write(r).unwrap();
    }
    writer.into_inner()
}

fn read_all(bytes: &[u8]) -> (Vec<Record>, Option<ReadError>) {
    let mut reader = match RecordingReader::new(bytes) {
        Ok(r) => r,
        Err(e) => return (Vec::new(), Some(e)),
    };
    let mut records = Vec::new();
    loop {
        match reader.next_record() {
            Ok(Some(r)) => records.push(r),
            Ok(None) => return (records, None),
            Err(e) => return (records, Some(e)),
        }
    }
}

#[test]
fn what_is_written_reads_back_identically() {
    let records = sample_records();
    let (read, error) = read_all(&written(&records));
    assert!(error.is_none(), "{error:?}");
    assert_eq!(read, records);
}

#[test]
fn a_message_record_holds_the_wire_bytes() {
    let wire = laser_message(361).to_bytes();
    let bytes = written(&sample_records()[2..3]);
    // The file header, the length, the 16-byte fixed part, then the message exactly as on the
    // wire, then the checksum.
    let start = FILE_HEADER_LEN + 4 + 16;
    assert_eq!(&bytes[start..start + wire.len()], &wire[..]);
    assert_eq!(bytes.len(), start + wire.len() + 4);
}

#[test]
fn every_cut_of_the_tail_reads_up_to_the_cut_and_says_where() {
    let records = sample_records();
    let bytes = written(&records);
    let mut boundaries = vec![FILE_HEADER_LEN];
    let mut writer = RecordingWriter::new(Vec::new()).unwrap();
    for r in &records {
        writer.write(r).unwrap();
        boundaries.push(writer.bytes() as usize);
    }
    for cut in FILE_HEADER_LEN..bytes.len() {
        let (read, error) = read_all(&bytes[..cut]);
        let whole = boundaries.iter().filter(|&&b| b <= cut).count() - 1;
        assert_eq!(read, records[..whole], "cut at {cut}");
        let at_boundary = boundaries.contains(&cut);
        match error {
            None => assert!(at_boundary, "cut at {cut} went unnoticed"),
            Some(ReadError::Truncated {
                offset, records: n, ..
            }) => {
                assert_eq!(offset as usize, boundaries[whole], "cut at {cut}");
                assert_eq!(n as usize, whole);
            }
            Some(other) => panic!("cut at {cut}: {other}"),
        }
    }
}

#[test]
fn a_flipped_bit_is_a_checksum_error_at_its_record() {
    let records = sample_records();
    let mut bytes = written(&records);
    let second_record = FILE_HEADER_LEN + 4 + records[0].payload_len() + 4;
    bytes[second_record + 10] ^= 0x40;
    let (read, error) = read_all(&bytes);
    assert_eq!(read.len(), 1);
    match error {
        Some(ReadError::Checksum { offset, records }) => {
            assert_eq!(offset as usize, second_record);
            assert_eq!(records, 1);
        }
        other => panic!("expected a checksum error, got {other:?}"),
    }
}

#[test]
fn other_files_are_refused_by_name() {
    let err = RecordingReader::new(&b"{\"t\": 0.1, \"dir\": \"s2c\"}"[..]).unwrap_err();
    assert!(err.to_string().contains("not a recording"), "{err}");
    let mut bytes = written(&[]);
    bytes[11] = 9;
    let err = RecordingReader::new(&bytes[..]).unwrap_err();
    assert!(
        matches!(err, ReadError::UnsupportedVersion { found: 9 }),
        "{err}"
    );
}

#[test]
fn a_lying_length_is_refused_before_allocating() {
    let mut bytes = written(&[]);
    bytes.extend_from_slice(&u32::MAX.to_be_bytes());
    let (_, error) = read_all(&bytes);
    assert!(
        matches!(error, Some(ReadError::TooLarge { .. })),
        "{error:?}"
    );
}

/// A disk that fills up after `room` bytes.
#[derive(Clone)]
struct FillingDisk {
    kept: Arc<Mutex<Vec<u8>>>,
    room: usize,
}

impl Write for FillingDisk {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let mut kept = self.kept.lock().unwrap();
        let left = self.room.saturating_sub(kept.len());
        if left == 0 {
            return Err(io::Error::new(
                io::ErrorKind::StorageFull,
                "No space left on device",
            ));
        }
        let n = left.min(buf.len());
        kept.extend_from_slice(&buf[..n]);
        Ok(n)
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

#[test]
fn a_full_disk_stops_the_recording_with_an_error_and_keeps_what_was_written() {
    let disk = FillingDisk {
        kept: Arc::default(),
        room: 20_000,
    };
    let recorder = Recorder::to_writer(disk.clone()).unwrap();
    let tap = (recorder.tap())("localhost", 6665);
    let message = laser_message(361).to_bytes();
    let header = crate::wire::Header::decode_slice(&message)
        .unwrap()
        .unwrap();
    let body = message.slice(crate::wire::HEADER_LEN..);
    let sent = 40;
    for _ in 0..sent {
        let event = crate::client::TapEvent::Frame {
            direction: Direction::ServerToClient,
            header: &header,
            body: &body,
        };
        tap(std::time::SystemTime::now(), event);
    }
    drop(tap);
    let stats = recorder.finish().unwrap();
    let error = stats.error.clone().expect("the full disk is reported");
    assert!(error.contains("No space left on device"), "{error}");
    // The connection record and every message are either written or counted as lost.
    assert_eq!(stats.written + stats.lost(), sent + 1, "{stats:?}");
    assert!(stats.failed > 0);

    let kept = disk.kept.lock().unwrap().clone();
    assert_eq!(kept.len(), 20_000);
    let (read, error) = read_all(&kept);
    assert!(
        read.len() >= 2,
        "the records before the disk filled are kept"
    );
    assert!(error.is_some_and(|e| e.is_torn_tail()));
    for r in &read[1..] {
        assert!(matches!(&r.event, Event::Message { body: b, .. } if *b == body));
    }
}

proptest! {
    #[test]
    fn damaged_files_never_panic(
        cut in 0usize..4000,
        flips in proptest::collection::vec((0usize..4000, any::<u8>()), 0..4),
    ) {
        let mut bytes = written(&sample_records());
        for (at, value) in flips {
            if let Some(b) = bytes.get_mut(at) {
                *b = value;
            }
        }
        bytes.truncate(cut);
        let _ = read_all(&bytes);
    }

    #[test]
    fn arbitrary_bytes_after_the_header_never_panic(
        tail in proptest::collection::vec(any::<u8>(), 0..512),
    ) {
        let mut bytes = written(&[]);
        bytes.extend_from_slice(&tail);
        let _ = read_all(&bytes);
    }
}
