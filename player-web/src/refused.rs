//! Why a page's command is refused: said to the page as it is written here, and nothing is
//! sent to the robot.

use player_proto::client::RequestError;
use player_proto::wire::DevAddr;

#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Refused {
    #[error("not a command: {0}")]
    NotACommand(#[from] serde_json::Error),
    #[error("binary frames mean nothing here: send JSON text")]
    Binary,
    #[error("{0} is not a position2d device")]
    NotABase(DevAddr),
    #[error("no robot {0:?} here")]
    NoRobot(String),
    #[error("{robot} has no {device}")]
    NoDevice { robot: String, device: DevAddr },
    /// The relay's rule (in words) lets this page only watch.
    #[error("{rule}: this page only observes")]
    Observer { rule: String },
    #[error("{robot} {device}: {source}")]
    NotSent {
        robot: String,
        device: DevAddr,
        source: RequestError,
    },
}
