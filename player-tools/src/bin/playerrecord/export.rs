//! `playerrecord export`: a recording in the text format of Player's `writelog` driver, which
//! real Player's `readlog` plays back.

use std::path::PathBuf;

use anyhow::{Context, Result};
use player_proto::recording::{self, playerlog};

/// Write a recording as a Player log for `readlog` (position2d, laser, sonar, ranger).
#[derive(clap::Args, Debug)]
pub struct Args {
    file: PathBuf,

    /// The Player log to write.
    #[arg(short, long)]
    out: PathBuf,
}

pub fn run(args: Args) -> Result<()> {
    let reader = recording::open(&args.file)?;
    let out = std::fs::File::create(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
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
