//! `playerrecord from-capture`: captures of real Player traffic (`captures/*.jsonl`, one file
//! per connection) as one recording, to replay or export them.

use std::path::PathBuf;

use anyhow::{Context, Result};
use player_proto::capture::parse_capture;
use player_proto::recording::RecordingWriter;
use player_proto::recording::from_capture::records_from_capture;

/// Player's default port, for a capture whose messages name none.
const DEFAULT_PORT: u16 = 6665;

/// Turn JSON-lines captures (one per connection) into one recording.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(required = true)]
    captures: Vec<PathBuf>,

    /// The recording to write.
    #[arg(short, long)]
    out: PathBuf,

    /// The host the connections are recorded as.
    #[arg(long, default_value = "localhost")]
    host: String,
}

pub fn run(args: Args) -> Result<()> {
    let mut records = Vec::new();
    for (number, path) in args.captures.iter().enumerate() {
        let text =
            std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
        let chunks = parse_capture(&text).with_context(|| format!("in {}", path.display()))?;
        let connection = u32::try_from(number)?;
        records.extend(
            records_from_capture(&chunks, &args.host, DEFAULT_PORT, connection, 0)
                .with_context(|| format!("in {}", path.display()))?,
        );
    }
    // Connections interleave in time, as a recorder of all of them at once would have them.
    records.sort_by_key(|r| r.time_ns);
    let file = std::fs::File::create(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    let mut writer = RecordingWriter::new(std::io::BufWriter::new(file))?;
    for record in &records {
        writer.write(record)?;
    }
    writer.flush()?;
    eprintln!("wrote {} records to {}", records.len(), args.out.display());
    Ok(())
}
