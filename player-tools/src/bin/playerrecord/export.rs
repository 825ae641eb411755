//! `playerrecord export`: a recording in the text format of Player's `writelog` driver, which
//! real Player's `readlog` plays back, or as an MCAP file (`--mcap`, or an output named
//! `*.mcap`) that holds every record losslessly.

use std::path::PathBuf;

use anyhow::{Context, Result};
use player_proto::recording::playerlog;

/// Write a recording (`.prec` or MCAP) as a Player log for `readlog` (position2d, laser,
/// sonar, ranger), or as MCAP.
#[derive(clap::Args, Debug)]
pub struct Args {
    file: PathBuf,

    /// The file to write.
    #[arg(short, long)]
    out: PathBuf,

    /// Write MCAP (the default when the output's name ends in `.mcap`): every message
    /// losslessly, for MCAP readers and `player-sim --replay`.
    #[arg(long)]
    mcap: bool,
}

pub fn run(args: Args) -> Result<()> {
    let (reader, _converted) = crate::mcap_file::open_recording(&args.file)?;
    let out = std::fs::File::create(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    if args.mcap || crate::mcap_file::named_mcap(&args.out) {
        return crate::mcap_file::export(reader, out, &args.file, &args.out);
    }
    let stats = playerlog::export(reader, out)?;
    eprintln!("wrote {} lines to {}", stats.lines, args.out.display());
    for ((interf, msg_type, subtype), count) in &stats.skipped {
        eprintln!(
            "  left out {count} {interf} type {msg_type} subtype {subtype} (no Player log layout)"
        );
    }
    if let Some(stopped) = &stats.stopped {
        eprintln!("the recording stops early; exported up to there: {stopped}");
    }
    Ok(())
}
