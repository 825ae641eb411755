//! MCAP at the command line: `export --mcap` and `from-mcap`, both streaming through
//! `player_mcap`, both keeping what came before damage and saying where it stopped; and any
//! recording opened for reading whichever kind its file is.

use std::fs::File;
use std::io::{BufReader, BufWriter};
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use player_mcap::as_prec::ConvertedRecording;
use player_proto::recording::{self, RecordingReader};

/// A recording opened for reading, and the `.prec` an MCAP file was converted to for it
/// (removed when this is dropped, so keep it while reading).
pub type Opened = (RecordingReader<BufReader<File>>, Option<ConvertedRecording>);

/// Opens a recording whichever kind its file is: a `.prec` as it is, an MCAP file written from
/// one (by `export --mcap` or by recording to `*.mcap`) through the `.prec` it holds.
pub fn open_recording(path: &Path) -> Result<Opened> {
    if !player_mcap::is_mcap(path) {
        let reader =
            recording::open(path).with_context(|| format!("reading {}", path.display()))?;
        return Ok((reader, None));
    }
    let converted = player_mcap::as_prec::convert(path)?;
    let reader = recording::open(&converted.path)
        .with_context(|| format!("reading what {} holds", path.display()))?;
    Ok((reader, Some(converted)))
}

/// Is this file to be written as MCAP (by its extension)?
pub fn named_mcap(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(player_mcap::EXTENSION))
}

/// Writes a recording as MCAP.
pub fn export(
    reader: RecordingReader<BufReader<File>>,
    out: File,
    from: &Path,
    to: &Path,
) -> Result<()> {
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
