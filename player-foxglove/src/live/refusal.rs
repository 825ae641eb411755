//! Why a viewer's request is refused: the text of the error `status` it is answered with
//! (the protocol's own wording, as Foxglove's servers word it), the connection kept.

use super::ids::{ChannelId, SubscriptionId};

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum Refusal {
    /// Not a request this protocol knows, or one missing its fields: what the JSON reader
    /// said.
    #[error("Invalid message: {0}")]
    Invalid(String),
    /// A request that needs a capability this server does not advertise.
    #[error("Unsupported operation {0:?}: this server advertises no capabilities")]
    Unsupported(String),
    #[error("Unknown channel ID {0}")]
    UnknownChannel(ChannelId),
    #[error("Subscription ID {0} is already in use")]
    SubscriptionInUse(SubscriptionId),
    #[error("Already subscribed to channel ID {0}")]
    AlreadySubscribed(ChannelId),
    #[error("Unknown subscription ID {0}")]
    UnknownSubscription(SubscriptionId),
}
