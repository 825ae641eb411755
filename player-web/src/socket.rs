//! One page's WebSocket: the newest of everything first, then every new frame as it comes;
//! the page's commands checked and carried out. A page that falls behind is sent the newest
//! of everything again rather than a backlog; one that stops reading altogether is closed
//! after [`player_front::STALLED_AFTER`] (every front's rule, `player_front::socket`), and
//! nobody else waits for it.

use std::net::SocketAddr;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use axum::extract::ws::{Message, WebSocket};
use futures_util::StreamExt;
use player_front::Stopping;
use player_front::socket::{CloseCode, Out, SendError, close, send_within};
use tokio::sync::broadcast::error::{RecvError, TryRecvError};

use crate::control::{Control, DEAD_MAN, Driven, peer};
use crate::hub::{Hub, to_json};
use crate::page::{FromPage, ToPage};
use crate::refused::Refused;

/// The most frames written at once.
const BATCH: usize = 64;

static NEXT_PAGE: AtomicU64 = AtomicU64::new(1);

/// Serves one page until it or the server goes.
pub async fn serve_page(
    socket: WebSocket,
    from: SocketAddr,
    hub: Arc<Hub>,
    control: Arc<Control>,
    mut stopping: Stopping,
) {
    let page = peer(NEXT_PAGE.fetch_add(1, Ordering::Relaxed), from.ip());
    // From now until the page goes, by whatever way, the relay subscribes to what it shows.
    let _open = Open::new(&hub, page.id);
    let (mut out, mut incoming) = socket.split();
    // Subscribed before the snapshot is taken: nothing falls between the two.
    let mut live = hub.subscribe();
    let (controller, rule) = control.standing(page);
    let mut first = vec![to_json(&ToPage::Hello { controller, rule })];
    first.extend(hub.snapshot());
    let mut driven = Driven::default();
    let mut dead_man = tokio::time::interval(DEAD_MAN / 2);
    let why = 'serve: {
        if let Err(why) = send_all(&mut out, first).await {
            break 'serve why.to_string();
        }
        loop {
            tokio::select! {
                frame = live.recv() => {
                    let mut frames = match frame {
                        Ok(frame) => vec![frame],
                        Err(RecvError::Lagged(_)) => hub.snapshot(),
                        Err(RecvError::Closed) => break 'serve "the server stops".to_string(),
                    };
                    // Whatever else is already waiting goes in the same write: one system
                    // call for a burst rather than one per frame.
                    while frames.len() < BATCH {
                        match live.try_recv() {
                            Ok(frame) => frames.push(frame),
                            Err(TryRecvError::Lagged(_)) => frames.extend(hub.snapshot()),
                            Err(_) => break,
                        }
                    }
                    if let Err(why) = send_all(&mut out, frames).await {
                        break 'serve why.to_string();
                    }
                }
                message = incoming.next() => {
                    let text = match message {
                        Some(Ok(Message::Text(text))) => text,
                        Some(Ok(Message::Binary(_))) => {
                            refuse(&mut out, &Refused::Binary).await;
                            continue;
                        }
                        Some(Ok(Message::Ping(_) | Message::Pong(_))) => continue,
                        Some(Ok(Message::Close(_))) | None => break 'serve "the page closed".to_string(),
                        Some(Err(e)) => {
                            let why = format!("the socket failed: {e}");
                            close(&mut out, CloseCode::of_error(&e), &why).await;
                            break 'serve why;
                        }
                    };
                    let outcome = serde_json::from_str::<FromPage>(&text)
                        .map_err(Refused::from)
                        .and_then(|command| match command {
                            FromPage::Show { robots } => {
                                hub.page_shows(page.id, &robots);
                                Ok(())
                            }
                            command => control.execute(page, command, &mut driven),
                        });
                    if let Err(why) = outcome {
                        refuse(&mut out, &why).await;
                    }
                }
                _ = dead_man.tick() => {
                    control.stop_stale(page, &mut driven, false);
                }
                // The front stopped; on a handed runtime nothing else would end this task.
                _ = stopping.wait() => {
                    close(&mut out, CloseCode::GoingAway, "the server stops").await;
                    break 'serve "the server stops".to_string();
                }
            }
        }
    };
    tracing::debug!(page = page.id, %from, "page gone: {why}");
    control.stop_stale(page, &mut driven, true);
    control.left(page);
}

/// An open page, as the hub's views count it: closed when dropped (the page went, or the
/// server stops and its task with it).
struct Open {
    hub: Arc<Hub>,
    page: u64,
}

impl Open {
    fn new(hub: &Arc<Hub>, page: u64) -> Open {
        hub.page_opened(page);
        Open {
            hub: hub.clone(),
            page,
        }
    }
}

impl Drop for Open {
    fn drop(&mut self) {
        self.hub.page_closed(self.page);
    }
}

async fn send(out: &mut Out, frame: crate::hub::Frame) -> Result<(), SendError> {
    send_all(out, vec![frame]).await
}

/// Writes `frames` and flushes them, all within [`player_front::STALLED_AFTER`]; a page that
/// takes longer is not reading, and is closed.
async fn send_all(out: &mut Out, frames: Vec<crate::hub::Frame>) -> Result<(), SendError> {
    send_within(out, frames.into_iter().map(Message::Text)).await
}

async fn refuse(out: &mut Out, why: &Refused) {
    let frame = to_json(&ToPage::Refused {
        why: why.to_string(),
    });
    if let Err(e) = send(out, frame).await {
        tracing::debug!("refusal not sent: {e}");
    }
}
