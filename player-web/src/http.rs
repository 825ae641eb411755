//! The page's HTTP side: the page and its assets, compiled into the binary (a classroom
//! may have no internet, so nothing comes from a CDN), and the WebSocket upgrade.

use std::net::SocketAddr;
use std::sync::Arc;

use axum::Router;
use axum::extract::ws::WebSocketUpgrade;
use axum::extract::{ConnectInfo, State};
use axum::http::header;
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use player_front::Stopping;

use crate::control::Control;
use crate::hub::Hub;
use crate::socket::serve_page;

/// The largest frame a page may send: a command is a few hundred bytes.
pub const MAX_FROM_PAGE: usize = 16 * 1024;

/// What a page's socket gathers before writing, and the most it may hold (a burst after a
/// page fell behind is the newest of everything: a few hundred kilobytes with a map).
const WRITE_BUFFER: usize = 32 * 1024;
const MAX_WRITE_BUFFER: usize = 2 * 1024 * 1024;

const HTML: &str = "text/html; charset=utf-8";
const SCRIPT: &str = "text/javascript; charset=utf-8";
const CSS: &str = "text/css; charset=utf-8";

/// The page and its files, each served as compiled in: its path, its type and its text. The
/// scripts are classic ones, loaded in the order the page names them (`app.js` last).
const ASSETS: [(&str, &str, &str); 7] = [
    ("/", HTML, include_str!("../assets/index.html")),
    ("/app.js", SCRIPT, include_str!("../assets/app.js")),
    ("/world.js", SCRIPT, include_str!("../assets/world.js")),
    (
        "/robot_draw.js",
        SCRIPT,
        include_str!("../assets/robot_draw.js"),
    ),
    ("/rows.js", SCRIPT, include_str!("../assets/rows.js")),
    ("/in_view.js", SCRIPT, include_str!("../assets/in_view.js")),
    ("/style.css", CSS, include_str!("../assets/style.css")),
];

#[derive(Clone)]
struct Shared {
    hub: Arc<Hub>,
    control: Arc<Control>,
    stopping: Stopping,
}

/// The routes: the page and its files ([`ASSETS`]), `/ws` (the live socket); the sockets end on
/// `stopping` (the front stopped).
pub fn router(hub: Arc<Hub>, control: Arc<Control>, stopping: Stopping) -> Router {
    ASSETS
        .iter()
        .fold(Router::new(), |router, &(path, kind, text)| {
            router.route(path, get(move || async move { asset(kind, text) }))
        })
        .route("/ws", get(upgrade))
        // Browsers ask; there is none, and saying so quietly keeps their consoles clean.
        .route(
            "/favicon.ico",
            get(|| async { axum::http::StatusCode::NO_CONTENT }),
        )
        .with_state(Shared {
            hub,
            control,
            stopping,
        })
}

fn asset(kind: &'static str, text: &'static str) -> Response {
    (
        [
            (header::CONTENT_TYPE, kind),
            (header::CACHE_CONTROL, "no-cache"),
        ],
        text,
    )
        .into_response()
}

async fn upgrade(
    socket: WebSocketUpgrade,
    ConnectInfo(from): ConnectInfo<SocketAddr>,
    State(shared): State<Shared>,
) -> Response {
    socket
        .max_message_size(MAX_FROM_PAGE)
        .max_frame_size(MAX_FROM_PAGE)
        // Commands are small, and frames out are written a burst at a time: a page's socket
        // needs kilobytes, not tungstenite's default 128 KiB each way (500 pages: 125 MB).
        .read_buffer_size(4 * 1024)
        .write_buffer_size(WRITE_BUFFER)
        .max_write_buffer_size(MAX_WRITE_BUFFER)
        .on_upgrade(move |socket| {
            serve_page(socket, from, shared.hub, shared.control, shared.stopping)
        })
}
