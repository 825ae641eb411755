//! What the tests and the `message_body` fuzz target report when viewing a body in place
//! (`wire::xdr_view`) and decoding it do not agree: both outcomes, as the checker saw them
//! (the encoding of the value read, or the error and its byte), so that a failing seed says
//! what differs without a debugger.

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("decoded {decoded}, viewed {viewed}")]
pub struct ViewDisagreement {
    pub decoded: String,
    pub viewed: String,
}
