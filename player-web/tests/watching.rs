//! Watching drives subscribing: the relay subscribes to a robot's devices upstream only while
//! a page shows them — nothing with no page open, every pose and the sensors of the robots
//! in view while one is, nothing again once it closes. Through real TCP: a real Chromium
//! page (tests/web/page.mjs) and a plain WebSocket client that says what it shows.

mod support;

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::time::Duration;

use futures_util::SinkExt;
use player_proto::server::Commanders;
use player_proto::wire::Interface;
use support::{Front, repo_root, serve_world, wait_for};
use tokio_tungstenite::tungstenite::Message;

const PATIENCE: Duration = Duration::from_secs(30);

/// The devices every robot of the relay is subscribed to upstream, over all robots.
fn subscribed(front: &Front) -> Vec<(Interface, u16)> {
    let mut all: Vec<_> = front
        .relay
        .robots()
        .iter()
        .flat_map(|r| r.upstream_subscriptions())
        .collect();
    all.sort();
    all
}

/// Once the survey has let go of every device (nobody looks yet).
fn nothing_subscribed(front: &Front) -> bool {
    wait_for(PATIENCE, || subscribed(front).is_empty())
}

#[test]
fn a_chromium_page_subscribes_the_robots_while_it_is_open() {
    let running = serve_world("multirobot.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let robots = front.relay.robots().len();
    assert!(
        nothing_subscribed(&front),
        "nobody looks: {:?}",
        subscribed(&front)
    );

    let web = repo_root().join("tests/web");
    let mut page = Command::new("node")
        .args(["page.mjs", "watch", &front.url(), "4"])
        .current_dir(&web)
        .stdout(Stdio::piped())
        .spawn()
        .expect("node runs (scripts/setup.sh installs it)");
    let mut lines = BufReader::new(page.stdout.take().expect("stdout")).lines();
    let first = lines.next().and_then(Result::ok);
    assert_eq!(
        first.as_deref(),
        Some("WATCHING"),
        "the page showed the robots"
    );
    let looked = subscribed(&front);
    let bases = looked
        .iter()
        .filter(|d| d.0 == Interface::POSITION2D)
        .count();
    let lasers = looked.iter().filter(|d| d.0 == Interface::LASER).count();
    assert_eq!(bases, robots, "every robot's pose: {looked:?}");
    assert_eq!(lasers, robots, "and, all in view, every laser: {looked:?}");
    assert!(
        !looked.iter().any(|d| d.0 == Interface::CAMERA),
        "nothing the page does not draw: {looked:?}"
    );
    let seen: serde_json::Value =
        serde_json::from_str(&lines.next().and_then(Result::ok).expect("the page's JSON"))
            .expect("JSON");
    assert_eq!(seen["errors"], serde_json::json!([]));
    assert_eq!(seen["scans"], robots, "every robot's scan drawn: {seen}");
    assert!(page.wait().expect("node ends").success());

    assert!(
        nothing_subscribed(&front),
        "let go once the page closed: {:?}",
        subscribed(&front)
    );
}

#[test]
fn a_page_that_shows_no_robot_in_view_gets_poses_alone() {
    let running = serve_world("multirobot.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let robots = front.relay.robots().len();
    assert!(
        nothing_subscribed(&front),
        "nobody looks: {:?}",
        subscribed(&front)
    );
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .expect("a runtime");
    let url = format!("ws://127.0.0.1:{}/ws", front.web.port());
    let (mut page, _) = runtime
        .block_on(tokio_tungstenite::connect_async(url))
        .expect("the page's socket opens");
    // Until it says, a page is sent the first robots' sensors (all five here).
    assert!(wait_for(PATIENCE, || subscribed(&front).len() >= 2 * robots));
    let show = r#"{"type":"show","robots":[]}"#;
    runtime
        .block_on(page.send(Message::text(show)))
        .expect("sent");
    let poses_alone = || {
        let looked = subscribed(&front);
        looked.len() == robots && looked.iter().all(|d| d.0 == Interface::POSITION2D)
    };
    assert!(
        wait_for(PATIENCE, poses_alone),
        "poses alone: {:?}",
        subscribed(&front)
    );
    runtime
        .block_on(page.close(None))
        .expect("the page's socket closes");
    assert!(
        nothing_subscribed(&front),
        "let go once the page closed: {:?}",
        subscribed(&front)
    );
}
