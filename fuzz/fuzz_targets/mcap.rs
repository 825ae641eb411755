//! MCAP recordings, damaged: any bytes read as a file from its start and from a seek point
//! through its chunk index, and a real recording with a byte changed and its end cut off —
//! an error or fewer records, never a panic or an unbounded allocation; and what the damaged
//! recording gives from its start is its beginning, unchanged. (One byte: every chunk's CRC
//! catches any one changed byte, where several chosen together could forge it, as a fuzzer
//! that reads comparisons will.)
#![no_main]

use std::io::Cursor;
use std::path::PathBuf;
use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use player_mcap::{McapFile, McapOptions, McapRecordWriter, McapRecords};
use player_proto::capture::parse_capture;
use player_proto::recording::from_capture::records_from_capture;
use player_proto::recording::index::SeekPoint;
use player_proto::recording::{Record, RecordSource};

/// The first records of a real laser and position session, and their MCAP file in 512-byte
/// chunks (many chunks, each with its index).
fn recording() -> &'static (Vec<Record>, Vec<u8>) {
    static RECORDING: OnceLock<(Vec<Record>, Vec<u8>)> = OnceLock::new();
    RECORDING.get_or_init(|| {
        let capture = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../captures/pull_position2d_laser.jsonl"
        );
        let text = std::fs::read_to_string(capture).expect("the capture");
        let chunks = parse_capture(&text).expect("a capture");
        let records: Vec<Record> = records_from_capture(&chunks, "localhost", 6665, 1, 0)
            .expect("records")
            .into_iter()
            .take(40)
            .collect();
        let options = McapOptions {
            chunk_size: 512,
            ..McapOptions::default()
        };
        let mut writer = McapRecordWriter::new(Cursor::new(Vec::new()), options).expect("a writer");
        for record in &records {
            writer.write(record).expect("written");
        }
        let file = writer.finish().expect("finished").into_inner();
        (records, file)
    })
}

/// The records read from the start, up to the first error.
fn from_start(bytes: &[u8]) -> Vec<Record> {
    McapRecords::new(bytes).map_while(Result::ok).collect()
}

/// The file read as a [`RecordSource`]: opened (its summary read), from its start, and from a
/// seek point at `time_ns` through its chunk index.
fn as_source(bytes: &[u8], time_ns: u64) {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    let path = PATH.get_or_init(|| {
        std::env::temp_dir().join(format!("mcap-fuzz-{}.mcap", std::process::id()))
    });
    std::fs::write(path, bytes).expect("a scratch file");
    let Ok(file) = McapFile::open(path) else {
        return;
    };
    let point = SeekPoint {
        time_ns,
        offset: 0,
        records: 0,
    };
    for mut stream in [file.read(), file.read_from(point)].into_iter().flatten() {
        while let Ok(Some(_)) = stream.next_record() {}
    }
}

fuzz_target!(|data: &[u8]| {
    let (records, original) = recording();
    // Any bytes as a file.
    let _ = from_start(data);
    // The real recording damaged: the input's first two bytes say where a byte is changed,
    // the third to what, the next two how much of its end is cut off.
    let mut file = original.clone();
    let number = |b: &[u8]| usize::from(u16::from_le_bytes([b[0], b[1]]));
    if let [a, b, value, ..] = *data {
        let at = number(&[a, b]) % file.len();
        file[at] = value;
    }
    if let [_, _, _, a, b, ..] = *data {
        file.truncate(file.len() - number(&[a, b]) % (file.len() / 2));
    }
    let got = from_start(&file);
    assert!(
        got.len() <= records.len() && got[..] == records[..got.len()],
        "a damaged recording gave records it does not hold: {} of {}",
        got.len(),
        records.len()
    );
    // Through its index, from a seek point in its middle.
    let middle = records[records.len() / 2].time_ns;
    as_source(&file, middle);
    as_source(data, middle);
});
