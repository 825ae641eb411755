//! An MCAP file written from a recording, read as the `.prec` it holds: converted once,
//! streaming, into a temporary file, which whatever reads recordings (a replay that seeks and
//! loops, `playerrecord info` and `export`) then reads exactly as it reads a `.prec`. The file
//! goes when the [`ConvertedRecording`] does.

use std::fs::File;
use std::io::{BufReader, BufWriter};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

/// Why an MCAP file cannot be read as a recording.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum FromMcapError {
    #[error("cannot open {path}: {source}")]
    Open {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("cannot write the recording {path} was converted to: {source}")]
    Temporary {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: {source}")]
    Convert {
        path: PathBuf,
        source: crate::ConvertError,
    },
}

/// A recording converted from an MCAP file, removed when dropped.
#[derive(Debug)]
pub struct ConvertedRecording {
    pub path: PathBuf,
}

impl Drop for ConvertedRecording {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// Converts `mcap` into a temporary `.prec`. Damage part way is logged and what came before
/// it is kept; damage before any record is the error.
pub fn convert(mcap: &Path) -> Result<ConvertedRecording, FromMcapError> {
    static COUNT: AtomicU32 = AtomicU32::new(0);
    let input = File::open(mcap).map_err(|source| FromMcapError::Open {
        path: mcap.to_path_buf(),
        source,
    })?;
    let name = format!(
        "player-mcap-{}-{}.prec",
        std::process::id(),
        COUNT.fetch_add(1, Ordering::Relaxed)
    );
    let converted = ConvertedRecording {
        path: std::env::temp_dir().join(name),
    };
    let temporary = |source| FromMcapError::Temporary {
        path: mcap.to_path_buf(),
        source,
    };
    let out = File::create(&converted.path).map_err(temporary)?;
    let (stats, out) =
        crate::mcap_to_prec(BufReader::new(input), BufWriter::new(out)).map_err(|source| {
            FromMcapError::Convert {
                path: mcap.to_path_buf(),
                source,
            }
        })?;
    out.into_inner()
        .map_err(|e| temporary(e.into_error()))?
        .sync_all()
        .map_err(temporary)?;
    if let Some(stopped) = stats.stopped {
        if stats.records == 0 {
            return Err(FromMcapError::Convert {
                path: mcap.to_path_buf(),
                source: stopped,
            });
        }
        tracing::warn!("{}: read up to the damage: {stopped}", mcap.display());
    }
    tracing::debug!("{}: {} records", mcap.display(), stats.records);
    Ok(converted)
}
