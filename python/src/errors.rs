//! The Python exceptions, and how each Rust error becomes one that says what failed and where.
//!
//! Python's own classes are used where they mean the same thing (`TimeoutError`, `ValueError`,
//! `KeyError`), so `except TimeoutError:` works as a student expects; what is Player's alone
//! (a refusal, a server that cannot be reached) has a class of its own.

use player_proto::client::{ConnectError, RequestError};
use pyo3::create_exception;
use pyo3::exceptions::{PyConnectionError, PyException, PyPermissionError, PyTimeoutError};
use pyo3::prelude::*;

create_exception!(
    player3,
    PlayerError,
    PyException,
    "Something went wrong talking to a Player server."
);
create_exception!(
    player3,
    ConnectionError,
    PyConnectionError,
    "The Player server cannot be reached, is not a Player server, or went away."
);
create_exception!(
    player3,
    RequestRefused,
    PlayerError,
    "The server answered a request with a refusal (a NACK, or a subscription denied)."
);

/// `what` names the device or request, `place` the server (`host:port`).
pub fn request_error(err: RequestError, what: &str, place: &str) -> PyErr {
    let text = format!("{what} on {place}: {err}");
    match err {
        RequestError::Nack(_) | RequestError::AccessDenied(_) => RequestRefused::new_err(text),
        RequestError::Timeout(_) => PyTimeoutError::new_err(text),
        RequestError::Disconnected(_) => ConnectionError::new_err(text),
        RequestError::ReadOnly(_) => PyPermissionError::new_err(text),
        RequestError::TooManyPending(_) | RequestError::Untyped(_) => PlayerError::new_err(text),
    }
}

pub fn connect_error(err: ConnectError) -> PyErr {
    ConnectionError::new_err(err.to_string())
}

/// Registers the exception classes on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("PlayerError", py.get_type::<PlayerError>())?;
    m.add("ConnectionError", py.get_type::<ConnectionError>())?;
    m.add("RequestRefused", py.get_type::<RequestRefused>())?;
    Ok(())
}
