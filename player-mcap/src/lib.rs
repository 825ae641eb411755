//! Recordings (`player_proto::recording`) as MCAP files, and back.
//!
//! An MCAP file written here holds every record of the recording — each Player message's
//! exact wire bytes, both directions, with its receive time and its connection — so it converts
//! back to the very same `.prec` bytes and `player-sim --replay` serves it as it serves the
//! `.prec`. `docs/RECORDING-FORMAT.md` ("MCAP") describes the layout; [`layout`] implements it.
//!
//! * [`McapRecordWriter`] — records into an MCAP file, with what Foxglove shows of them
//!   (`foxglove_channels`, through `player_foxglove`: the `foxglove` feature, on by default;
//!   reading needs no Foxglove schemas).
//! * [`McapRecords`] — records out of one, trusting nothing.
//! * [`prec_to_mcap`] / [`mcap_to_prec`] — whole files, streaming, in bounded memory.
//! * [`recorder`] — a recorder writing MCAP directly when the file is named `*.mcap`.
//! * [`McapFile`] — an MCAP file as a recording source, read from its start or from a seek
//!   point through its chunk index, by a replay or a summary: no conversion first.

#[cfg(feature = "foxglove")]
pub mod foxglove_channels;
pub mod layout;
pub mod reader;
pub mod record_lengths;
pub mod sink;
pub mod source;
pub mod writer;

use std::io::{Read, Seek, Write};

use player_proto::recording::{RecordStream, RecordingWriter, WriteError};

pub use reader::{McapReadError, McapRecords};
pub use sink::{RecordError, recorder, reproducible_recorder};
pub use source::{IndexedReadError, McapFile, open_recording};
pub use writer::{McapOptions, McapRecordWriter, McapWriteError};

/// The conventional file extension of an MCAP file.
pub const EXTENSION: &str = "mcap";
/// The first bytes of every MCAP file.
pub const MAGIC: &[u8] = b"\x89MCAP0\r\n";

/// Does this file start as an MCAP file does? (`false` if it cannot be read.)
pub fn is_mcap(path: &std::path::Path) -> bool {
    let mut start = [0u8; 8];
    std::fs::File::open(path)
        .and_then(|mut f| f.read_exact(&mut start))
        .is_ok_and(|()| start == MAGIC)
}

/// A conversion that failed, or stopped at damage after converting what came before it.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ConvertError {
    /// Reading the recording (a `.prec`, or any other source) stopped.
    #[error(transparent)]
    Read(#[from] player_proto::recording::SourceError),
    #[error(transparent)]
    ReadMcap(#[from] McapReadError),
    #[error(transparent)]
    WritePrec(#[from] WriteError),
    #[error(transparent)]
    WriteMcap(#[from] McapWriteError),
}

/// What a conversion did.
#[derive(Debug, Default)]
pub struct Converted {
    pub records: u64,
    /// Foxglove messages written beside the records (MCAP exports).
    pub foxglove: u64,
    /// Why reading stopped before the input's end, if it did: everything before is written.
    pub stopped: Option<ConvertError>,
}

/// Writes every record of a recording into an MCAP file, up to a torn or damaged tail (kept in
/// [`Converted::stopped`]).
pub fn prec_to_mcap<W: Write + Seek>(
    mut input: impl RecordStream,
    out: W,
    options: McapOptions,
) -> Result<(Converted, W), ConvertError> {
    let mut writer = McapRecordWriter::new(out, options)?;
    let mut converted = Converted::default();
    loop {
        match input.next_record() {
            Ok(Some(record)) => writer.write(&record)?,
            Ok(None) => break,
            Err(e) => {
                converted.stopped = Some(e.into());
                break;
            }
        }
    }
    converted.records = writer.records();
    converted.foxglove = writer.foxglove_messages();
    Ok((converted, writer.finish()?))
}

/// Writes the recording an MCAP file holds as a `.prec`, up to the first damage (kept in
/// [`Converted::stopped`]).
pub fn mcap_to_prec<R: Read, W: Write>(input: R, out: W) -> Result<(Converted, W), ConvertError> {
    let mut writer = RecordingWriter::new(out)?;
    let mut converted = Converted::default();
    for record in McapRecords::new(input) {
        match record {
            Ok(record) => writer.write(&record)?,
            Err(e) => {
                converted.stopped = Some(e.into());
                break;
            }
        }
    }
    writer.flush()?;
    converted.records = writer.records();
    Ok((converted, writer.into_inner()))
}

#[cfg(test)]
mod source_tests;
#[cfg(test)]
mod tests;
