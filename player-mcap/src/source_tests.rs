//! An MCAP file read as a recording source: indexed from its start as its `.prec` is, and read
//! again from any seek point through its chunk index, or linearly when it was cut short.

use player_proto::recording::{PrecFile, Record, RecordSource, RecordStream, RecordingIndex};

use crate::tests::{foreign_mcap, mcap_of, prec, real_records};
use crate::{McapFile, open_recording};

fn all(mut stream: impl RecordStream) -> Vec<Record> {
    let mut records = Vec::new();
    while let Some(record) = stream.next_record().expect("no error") {
        records.push(record);
    }
    records
}

/// The real captures as a `.prec` and as an MCAP file of many chunks, in `dir`.
fn files(dir: &std::path::Path) -> (Vec<Record>, std::path::PathBuf, std::path::PathBuf) {
    let records = real_records();
    let prec_bytes = prec(&records);
    let mcap = dir.join("real.mcap");
    std::fs::write(&mcap, mcap_of(&prec_bytes, 4096)).unwrap();
    let prec_path = dir.join("real.prec");
    std::fs::write(&prec_path, prec_bytes).unwrap();
    (records, prec_path, mcap)
}

#[test]
fn an_mcap_file_indexes_as_its_prec_does() {
    let dir = tempfile::tempdir().unwrap();
    let (records, prec_path, mcap_path) = files(dir.path());
    let mcap = McapFile::open(&mcap_path).unwrap();
    assert!(mcap.indexed(), "a whole file has a chunk index");
    let from_mcap = RecordingIndex::read(&mcap).unwrap();
    let from_prec = RecordingIndex::read(&PrecFile::open(&prec_path).unwrap()).unwrap();
    assert!(from_mcap.stopped.is_none(), "{:?}", from_mcap.stopped);
    assert_eq!(from_mcap.records, records.len() as u64);
    assert_eq!(
        (from_mcap.first_ns, from_mcap.last_ns, from_mcap.messages),
        (from_prec.first_ns, from_prec.last_ns, from_prec.messages)
    );
    let times = |i: &RecordingIndex| i.seek_points.iter().map(|p| p.time_ns).collect::<Vec<_>>();
    assert_eq!(times(&from_mcap), times(&from_prec));
    assert!(from_mcap.seek_points.len() > 3, "a few seconds of captures");
    for (number, c) in &from_prec.connections {
        let m = &from_mcap.connections[number];
        assert_eq!(
            (&m.host, m.port, &m.devices, &m.data),
            (&c.host, c.port, &c.devices, &c.data)
        );
    }
}

#[test]
fn reading_from_a_seek_point_gives_every_record_from_its_time_on() {
    let dir = tempfile::tempdir().unwrap();
    let (records, _, mcap_path) = files(dir.path());
    let mcap = open_recording(&mcap_path).unwrap();
    let index = RecordingIndex::read(&*mcap).unwrap();
    for point in &index.seek_points {
        let got = all(mcap.read_from(*point).unwrap());
        let want: Vec<_> = records
            .iter()
            .filter(|r| r.time_ns >= point.time_ns)
            .cloned()
            .collect();
        assert_eq!(got.len(), want.len(), "from {}", point.time_ns);
        assert!(got == want, "from {}: other records", point.time_ns);
        assert_eq!(
            got[0], records[point.records as usize],
            "starts at the point"
        );
    }
}

#[test]
fn a_file_cut_short_is_read_to_the_cut_and_seeks_without_an_index() {
    let dir = tempfile::tempdir().unwrap();
    let (records, _, mcap_path) = files(dir.path());
    let whole = std::fs::read(&mcap_path).unwrap();
    let cut = dir.path().join("cut.mcap");
    std::fs::write(&cut, &whole[..whole.len() * 2 / 3]).unwrap();
    let mcap = McapFile::open(&cut).unwrap();
    assert!(!mcap.indexed(), "a cut file has no summary");
    let index = RecordingIndex::read(&mcap).unwrap();
    let stopped = index.stopped.as_ref().expect("the cut is said");
    assert!(stopped.is_torn_tail(), "a cut is a torn tail: {stopped}");
    let kept = index.records as usize;
    assert!(kept > records.len() / 3, "{kept} records kept");
    let point = index.seek_points[index.seek_points.len() / 2];
    let mut stream = mcap.read_from(point).unwrap();
    let first = stream.next_record().unwrap().expect("a record");
    assert_eq!(first, records[point.records as usize]);
}

#[test]
fn a_foreign_mcap_file_is_refused_when_opened() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("foreign.mcap");
    std::fs::write(&path, foreign_mcap()).unwrap();
    let error = McapFile::open(&path).err().expect("refused").to_string();
    assert!(error.contains("not a Player recording"), "{error}");
}

/// The byte where the first record of opcode `opcode` in the summary section of `file` starts.
fn summary_record(file: &[u8], opcode: u8) -> usize {
    let footer = file.len() - 8 - 29;
    let word = |at: usize| u64::from_le_bytes(file[at..at + 8].try_into().unwrap()) as usize;
    let mut at = word(footer + 9);
    while file[at] != opcode {
        at += 9 + word(at + 1);
    }
    at
}

#[test]
fn a_summary_length_past_its_record_leaves_the_file_read_without_its_index() {
    let dir = tempfile::tempdir().unwrap();
    let (records, _, mcap_path) = files(dir.path());
    let mut bytes = std::fs::read(&mcap_path).unwrap();
    // A summary channel record's topic claims 3 GB (the body: id, schema id, topic length).
    let channel = summary_record(&bytes, 0x04);
    bytes[channel + 13..channel + 17].copy_from_slice(&3_327_152_921u32.to_le_bytes());
    let damaged = dir.path().join("damaged.mcap");
    std::fs::write(&damaged, &bytes).unwrap();
    let mcap = McapFile::open(&damaged).unwrap();
    assert!(!mcap.indexed(), "the damaged summary is not used");
    // Every record comes back; the damage is named where the reading meets it, after them.
    let mut stream = mcap.read().unwrap();
    let mut got = Vec::new();
    let error = loop {
        match stream.next_record() {
            Ok(Some(record)) => got.push(record),
            Ok(None) => panic!("the damage went unnoticed"),
            Err(e) => break e.to_string(),
        }
    };
    assert_eq!(got, records, "the data section is whole");
    assert!(
        error.contains("channel record's field 3 claims 3327152921 bytes"),
        "{error}"
    );
}

/// The fuzzer's file (45 bytes): the opening magic, a footer whose `summary_start` (16)
/// points into the footer itself, where byte 16 reads as a Header record's opcode, and the
/// closing magic. The summary reader parsed the footer's bytes as that record, whose
/// strings claimed 4 GB.
#[test]
fn a_summary_starting_past_the_footer_is_damage() {
    let mut bytes = crate::MAGIC.to_vec();
    bytes.extend([0x02, 0x7f, 0, 0, 0, 0, 0, 0, 0x01]);
    bytes.extend(16u64.to_le_bytes());
    bytes.extend([0xa1, 0x4a, 0, 0, 0, 0, 0, 0, 0x6b, 0x7d, 0xb8, 0xf0]);
    bytes.extend(crate::MAGIC);
    assert_eq!(bytes.len(), 45);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("past.mcap");
    std::fs::write(&path, &bytes).unwrap();
    let mut file = std::fs::File::open(&path).unwrap();
    let error = format!(
        "{:?}",
        crate::source::read_summary(&mut file).expect_err("damaged")
    );
    assert!(error.contains("past the footer at byte 8"), "{error}");
    // Opened all the same, without an index.
    assert!(!McapFile::open(&path).unwrap().indexed());
}
