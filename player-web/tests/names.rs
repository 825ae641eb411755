//! The page names a robot as the relay was told to (`HOST:PORT=NAME`, a world's model), and
//! its commands reach the robot by that name.

mod support;

use std::time::Duration;

use futures_util::{SinkExt, StreamExt};
use player_proto::RobotId;
use player_proto::server::Commanders;
use player_relay::{Relay, RelayConfig, Route};
use player_web::WebFront;
use serde_json::{Value, json};
use support::{LOCALHOST, serve_world};
use tokio_tungstenite::tungstenite::Message;

#[test]
fn rows_and_commands_use_the_robots_names() {
    let running = serve_world("simple.world", None);
    let web = WebFront::start(LOCALHOST, 0, Commanders::Everyone).expect("the page is served");
    let web = std::sync::Arc::new(web);
    let port = running.ports[0].1;
    let robot = RobotId::new("127.0.0.1", port).named("scout").unwrap();
    let relay = Relay::start(RelayConfig {
        routes: vec![Route {
            robot: robot.clone(),
            listen_port: 0,
        }],
        commanders: Commanders::Everyone,
        fronts: vec![web.clone() as _],
        ..RelayConfig::default()
    })
    .expect("the relay starts");
    // Commands are checked against the robot's devices: wait until the relay knows them.
    assert_eq!(relay.wait_serving(Duration::from_secs(10)), 1);
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .unwrap();
    let (rows, refusals) = runtime.block_on(async {
        let url = format!("ws://127.0.0.1:{}/ws", web.port());
        let (mut page, _) = tokio_tungstenite::connect_async(url).await.unwrap();
        let stop = |robot: &str| {
            let command = json!({"type": "velocity", "robot": robot, "device": "position2d:0",
                "command": {"vel": {"px": 0, "py": 0, "pa": 0}, "state": 1}});
            Message::Text(command.to_string().into())
        };
        // One command by the name, one by the server, in that order: the page answers in
        // order, so the first refusal says which was refused. Then the rows.
        page.send(stop("scout")).await.unwrap();
        page.send(stop(&robot.server())).await.unwrap();
        let (mut refusals, mut rows) = (Vec::new(), None);
        let deadline = std::time::Instant::now() + Duration::from_secs(30);
        while refusals.is_empty() || rows.is_none() {
            assert!(
                std::time::Instant::now() < deadline,
                "{refusals:?} {rows:?}"
            );
            let next = tokio::time::timeout(Duration::from_secs(10), page.next()).await;
            let Ok(Some(Ok(Message::Text(text)))) = next else {
                panic!("the page's socket gave no refusal or status frame: {next:?}");
            };
            let value: Value = serde_json::from_str(&text).unwrap();
            match value["type"].as_str() {
                Some("refused") => refusals.push(value["why"].to_string()),
                Some("status") => rows = Some(value["rows"].clone()),
                _ => {}
            }
        }
        (rows.unwrap_or_default(), refusals)
    });
    let names: Vec<&str> = rows
        .as_array()
        .unwrap()
        .iter()
        .map(|row| row["robot"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["scout"]);
    assert!(
        refusals[0].contains(&robot.server()),
        "a robot is no longer known by its server: {refusals:?}"
    );
}
