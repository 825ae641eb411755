//! Accepting viewers: one listener (a small send buffer per socket, Nagle off), the WebSocket
//! upgrade on any path with the protocol's subprotocol negotiated, one task per viewer.

use std::net::SocketAddr;
use std::sync::Arc;

use axum::Router;
use axum::extract::ws::WebSocketUpgrade;
use axum::extract::{ConnectInfo, State};
use axum::http::StatusCode;
use axum::response::{IntoResponse, Response};
use player_front::Stopping;

use super::hub::Hub;
use super::session::serve_viewer;
use super::wire::SUBPROTOCOLS;

/// The largest message a viewer may send: its requests are small JSON (a subscription is
/// some 30 bytes); anything bigger closes the connection (1009).
pub const MAX_INCOMING: usize = 1 << 20;

/// How much a viewer's socket reads at once.
const READ_BUFFER: usize = 4 * 1024;

/// Kernel send buffer per viewer: a few bursts of a few robots. A viewer that stops reading
/// fills it in a moment, and its outbox then drops its oldest messages.
pub const VIEWER_SEND_BUFFER: usize = 256 * 1024;

#[derive(Clone)]
struct Shared {
    hub: Arc<Hub>,
    session_id: String,
    stopping: Stopping,
}

/// Serves viewers on `listener` until this task is aborted (the server stops); each viewer
/// until it goes or `stopping` says the server stops.
pub async fn serve(
    listener: tokio::net::TcpListener,
    hub: Arc<Hub>,
    session_id: String,
    stopping: Stopping,
) {
    let app = Router::new()
        .fallback(upgrade)
        .with_state(Shared {
            hub,
            session_id,
            stopping,
        })
        .into_make_service_with_connect_info::<SocketAddr>();
    // Small messages (poses) go out at once rather than waiting for company.
    let listener = axum::serve::ListenerExt::tap_io(listener, |tcp| {
        if let Err(e) = tcp.set_nodelay(true) {
            tracing::debug!("a Foxglove viewer's socket keeps Nagle: {e}");
        }
    });
    if let Err(e) = axum::serve(listener, app).await {
        tracing::error!("the Foxglove WebSocket server stopped: {e}");
    }
}

async fn upgrade(
    State(shared): State<Shared>,
    ConnectInfo(from): ConnectInfo<SocketAddr>,
    upgrade: WebSocketUpgrade,
) -> Response {
    let upgrade = upgrade
        .protocols(SUBPROTOCOLS)
        .max_message_size(MAX_INCOMING)
        .max_frame_size(MAX_INCOMING)
        // tungstenite zeroes its whole read buffer (128 KiB by default) each time the socket
        // is polled for reading, which the session does whenever it wakes to write: with 200
        // viewers that memset was 44 % of the relay's CPU. Requests are small JSON; the buffer
        // still grows for a bigger one (up to MAX_INCOMING).
        .read_buffer_size(READ_BUFFER);
    if upgrade.selected_protocol().is_none() {
        let why = format!(
            "a Foxglove WebSocket client offers subprotocol {}",
            SUBPROTOCOLS.join(" or ")
        );
        return (StatusCode::BAD_REQUEST, why).into_response();
    }
    upgrade.on_upgrade(move |socket| {
        serve_viewer(socket, from, shared.hub, shared.session_id, shared.stopping)
    })
}

/// A listener whose connections start with a small kernel send buffer
/// ([`VIEWER_SEND_BUFFER`]), for hundreds of viewers connecting at once.
pub fn listen(addr: SocketAddr) -> std::io::Result<std::net::TcpListener> {
    player_front::socket::listen(addr, VIEWER_SEND_BUFFER)
}
