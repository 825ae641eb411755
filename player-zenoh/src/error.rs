//! What can go wrong between Player and Zenoh.

/// Why a Zenoh front or bridge could not start or carry on.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ZenohError {
    /// Zenoh refused the configuration, or a session, key, subscriber or queryable.
    #[error("zenoh: {0}")]
    Zenoh(#[from] zenoh::Error),
    #[error("bad Zenoh option: {0}")]
    Option(String),
    #[error("cannot start a thread or runtime: {0}")]
    Thread(#[from] std::io::Error),
    /// The robot's `devices` queryable did not answer with a device list.
    #[error("{0} did not say which devices it has")]
    NotDescribed(String),
    #[error("cannot serve a robot found in Zenoh: {0}")]
    Serve(#[from] player_proto::server::ServerError),
}
