//! `playerrecord info`: what a recording holds, per connection and device, and where it stops
//! if it was cut short.

use std::io::Write;
use std::path::PathBuf;

use anyhow::{Result, bail};
use player_proto::recording::RecordingIndex;

/// Summarise a recording (`.prec` or MCAP): its connections, devices, message counts and
/// time span.
#[derive(clap::Args, Debug)]
pub struct Args {
    file: PathBuf,
}

pub fn run(args: Args) -> Result<()> {
    let reader = crate::mcap_file::open_recording(&args.file)?;
    let index = RecordingIndex::build(reader);
    let mut out = std::io::stdout().lock();
    writeln!(
        out,
        "{}: {} records, {} messages, {:.3} s, {} connections",
        args.file.display(),
        index.records,
        index.messages,
        index.duration_s(),
        index.connections.len()
    )?;
    for (number, c) in &index.connections {
        let version = c.version().unwrap_or_else(|| "no banner".into());
        writeln!(out, "  #{number} {}:{} (Player {version})", c.host, c.port)?;
        for (&(interf, index), driver) in &c.devices {
            let data = c.data.get(&(interf, index)).copied().unwrap_or(0);
            writeln!(
                out,
                "    {:<16} {driver:<16} {data} data",
                format!("{interf}:{index}")
            )?;
        }
    }
    match index.stopped {
        None => Ok(()),
        Some(e) if e.is_torn_tail() => {
            writeln!(out, "stops early (everything before is above): {e}")?;
            Ok(())
        }
        Some(e) => bail!("{}: read up to the damage only: {e}", args.file.display()),
    }
}
