//! The recording reader and the index a replay builds, on arbitrary bytes after a valid file
//! header (and on arbitrary bytes alone): errors, never a panic or an unbounded allocation.
#![no_main]

use libfuzzer_sys::fuzz_target;
use player_proto::recording::{RecordingIndex, RecordingReader, format};

fuzz_target!(|data: &[u8]| {
    let _ = RecordingReader::new(data).map(RecordingIndex::build);
    let mut file = format::MAGIC.to_vec();
    file.extend_from_slice(&format::VERSION.to_be_bytes());
    file.extend_from_slice(data);
    if let Ok(reader) = RecordingReader::new(&file[..]) {
        let _ = RecordingIndex::build(reader);
    }
});
