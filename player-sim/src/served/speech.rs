//! The speech drivers of a .cfg: `sentences` provides a `speech_recognition` device hearing
//! the sentences of `file` (relative to the .cfg; `"-"` reads standard input), and `festival`
//! (Player's text-to-speech driver) a `speech` device that appends what it says to `log` and
//! speaks it into `wav`-N.wav files when espeak-ng is installed.

use player_proto::wire::Interface;

use super::drivers::at;
use super::{DriverBlock, Source};
use crate::speech::{SpeechInput, SpeechOutput};
use crate::worldfile::WorldFileError;

/// The file name that means standard input.
const STDIN: &str = "-";

/// The source of a device a speech block provides, or `None` for another interface
/// (reported in `ignored`).
pub(super) fn source(
    driver: &DriverBlock,
    interf: Interface,
    ignored: &mut Vec<String>,
) -> Result<Option<Source>, WorldFileError> {
    let name = driver.name.as_str();
    match (name, interf) {
        ("sentences", Interface::SPEECH_RECOGNITION) => {
            let file = driver
                .block
                .get("file")
                .ok_or_else(|| driver.error("sentences needs a file (\"-\" for standard input)"))?;
            let path = file
                .value
                .as_str()
                .ok_or_else(|| at(file, "file must be a \"string\""))?;
            let input = if path == STDIN {
                SpeechInput::from_stdin()
            } else {
                SpeechInput::from_file(&driver.folder.join(path))?
            };
            Ok(Some(Source::SpeechRecognition(input)))
        }
        ("festival", Interface::SPEECH) => {
            let path = |option: &str| -> Result<_, WorldFileError> {
                driver
                    .block
                    .get(option)
                    .map(|p| {
                        p.value
                            .as_str()
                            .map(|s| driver.folder.join(s))
                            .ok_or_else(|| at(p, format!("{option} must be a \"string\"")))
                    })
                    .transpose()
            };
            Ok(Some(Source::Speech(SpeechOutput::new(
                path("log")?,
                path("wav")?,
            ))))
        }
        (_, other) => {
            let note = driver.ignored(&format!("{other} of driver {name:?}"));
            if !ignored.contains(&note) {
                ignored.push(note);
            }
            Ok(None)
        }
    }
}
