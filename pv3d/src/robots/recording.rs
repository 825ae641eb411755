//! `pv3d --record FILE`: every message of every server written to a recording while the
//! viewer runs (MCAP when FILE is named `*.mcap`, else a `.prec`), finished — and what it
//! wrote reported — when the viewer ends.

use std::path::{Path, PathBuf};

use player_mcap::RecordError;
use player_proto::client::Tap;
use player_proto::recording::Recorder;

/// A recording in progress; finished when dropped (after the robots, which hold its tap).
pub struct Recording {
    recorder: Option<Recorder>,
    path: PathBuf,
}

impl Recording {
    pub fn start(path: &Path) -> Result<Recording, RecordError> {
        tracing::info!("recording every message to {}", path.display());
        Ok(Recording {
            recorder: Some(player_mcap::recorder(path)?),
            path: path.to_path_buf(),
        })
    }

    /// The tap to give the robots' clients.
    pub fn tap(&self) -> Tap {
        self.recorder.as_ref().expect("recording").tap()
    }
}

impl Drop for Recording {
    fn drop(&mut self) {
        let Some(recorder) = self.recorder.take() else {
            return;
        };
        match recorder.finish() {
            Ok(stats) => {
                let lost = stats.lost();
                eprintln!(
                    "recorded {} records ({} bytes) to {}; {lost} lost{}",
                    stats.written,
                    stats.bytes,
                    self.path.display(),
                    stats.error.map(|e| format!(": {e}")).unwrap_or_default()
                );
            }
            Err(e) => eprintln!("recording to {} failed: {e}", self.path.display()),
        }
    }
}
