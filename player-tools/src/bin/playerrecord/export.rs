//! `playerrecord export`: a recording in the text format of Player's `writelog` driver.

use std::path::PathBuf;

use anyhow::{Result, bail};

/// Write a recording as a Player text log, for `readlog` (position2d, laser, sonar, ranger).
#[derive(clap::Args, Debug)]
pub struct Args {
    file: PathBuf,

    /// The Player log to write.
    #[arg(short, long)]
    out: PathBuf,
}

pub fn run(args: Args) -> Result<()> {
    bail!(
        "export of {} to {} is not written yet",
        args.file.display(),
        args.out.display()
    )
}
