//! The protocol's ids, apart from the messages that carry them ([`super::wire`]) so that a
//! refusal naming an id ([`super::refusal`]) need not depend on the messages, which carry
//! refusals.

/// A client's subscription id (chosen by the client) and a server's channel id.
pub type SubscriptionId = u32;
pub type ChannelId = u64;
