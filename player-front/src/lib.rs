//! # player-front: what every front of the relay shares
//!
//! The relay carries robots to fronts that are not Player clients: the web page
//! (`player-web`), Foxglove (`player-foxglove`'s `live`), Zenoh (`player-zenoh`). The two
//! that serve viewers over WebSockets serve them alike, from here:
//!
//! * [`socket`] — listening (a small kernel send buffer per viewer, hundreds connecting at
//!   once), sending a burst within [`socket::STALLED_AFTER`] (the one rule for a viewer that
//!   stops reading: closed, and nobody else waits for it), and closing with a typed
//!   [`socket::CloseCode`] and a reason cut to what a close frame holds;
//! * [`outbox`] — a viewer's bounded newest-wins queue: data past its bounds in number or
//!   bytes drops the oldest, control messages are kept (Foxglove's viewers; the page's
//!   broadcast keeps its own newest-of-everything snapshot for a page that lags).
//!
//! Every front, WebSockets or not, is a [`Front`] ([`front`]): the relay tells it each robot
//! that arrives, its messages, its leaving, and when to stop. A new front is a crate that
//! implements it (and, over WebSockets, starts from [`socket`] and [`outbox`]).
//!
//! A front runs on a [`FrontRuntime`] ([`runtime`]): its own, or one it is handed (the
//! relay hands one to all its fronts; pv3d and Python may hand theirs); stopping a front on a
//! handed runtime ends its tasks and closes its listener, and leaves the runtime running.
//!
//! A front costs what is watched ([`watch`]): it holds a [`Look`] at each device a viewer
//! looks at, and the relay subscribes upstream only to what some front or observer looks at.

pub mod front;
pub mod outbox;
pub mod runtime;
pub mod socket;
pub mod watch;

pub use front::Front;
pub use runtime::{FrontRuntime, Stopping, shared_runtime};
pub use socket::{CloseCode, STALLED_AFTER, SendError};
pub use watch::{Device, Look, Upstream, Watch, Watching};
