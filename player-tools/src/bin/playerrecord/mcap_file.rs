//! MCAP at the command line: `export --mcap` and `from-mcap`, both streaming through
//! `player_mcap`, both keeping what came before damage and saying where it stopped; and any
//! recording opened for reading whichever kind its file is.

use std::fs::File;
use std::io::{BufReader, BufWriter};
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use player_proto::recording::RecordStream;

/// Reads a recording whichever kind its file is: a `.prec`, or an MCAP file written from one
/// (by `export --mcap` or by recording to `*.mcap`), read directly.
pub fn open_recording(path: &Path) -> Result<Box<dyn RecordStream>> {
    let read = || player_mcap::open_recording(path)?.read();
    read().with_context(|| format!("reading {}", path.display()))
}

/// Is this file to be written as MCAP (by its extension)?
pub fn named_mcap(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(player_mcap::EXTENSION))
}

/// Writes a recording as MCAP.
pub fn export(reader: impl RecordStream, out: File, from: &Path, to: &Path) -> Result<()> {
    let (stats, out) = player_mcap::prec_to_mcap(reader, BufWriter::new(out), Default::default())
        .with_context(|| format!("writing {}", to.display()))?;
    out.into_inner()
        .map_err(|e| e.into_error())
        .and_then(|f| f.sync_all())
        .with_context(|| format!("writing {}", to.display()))?;
    eprintln!("wrote {} records to {}", stats.records, to.display());
    if let Some(stopped) = stats.stopped {
        eprintln!(
            "{} stops early; exported up to there: {stopped}",
            from.display()
        );
    }
    Ok(())
}

/// Turn an MCAP file written from a recording back into that recording, byte for byte.
#[derive(clap::Args, Debug)]
pub struct FromMcapArgs {
    file: PathBuf,

    /// The recording to write.
    #[arg(short, long)]
    out: PathBuf,
}

pub fn from_mcap(args: FromMcapArgs) -> Result<()> {
    let input =
        File::open(&args.file).with_context(|| format!("opening {}", args.file.display()))?;
    let out =
        File::create(&args.out).with_context(|| format!("creating {}", args.out.display()))?;
    let (stats, out) = player_mcap::mcap_to_prec(BufReader::new(input), BufWriter::new(out))
        .with_context(|| format!("{} to {}", args.file.display(), args.out.display()))?;
    out.into_inner()
        .map_err(|e| e.into_error())
        .and_then(|f| f.sync_all())
        .with_context(|| format!("writing {}", args.out.display()))?;
    eprintln!("wrote {} records to {}", stats.records, args.out.display());
    if let Some(stopped) = stats.stopped {
        bail!(
            "{}: converted the {} records before the damage, then stopped: {stopped}",
            args.file.display(),
            stats.records
        );
    }
    Ok(())
}
