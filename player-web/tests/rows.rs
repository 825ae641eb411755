//! The page's rows give each device's rate in readings a second, as pv3d's status panel does:
//! Stage's rangers send each reading as two messages (ranges, then intensities, stamped
//! alike), which the rows used to count twice ("20 Hz" for a 10 Hz sensor).

mod support;

use std::time::Duration;

use futures_util::StreamExt;
use player_proto::server::Commanders;
use serde_json::Value;
use support::{Front, serve_world};
use tokio_tungstenite::tungstenite::Message;

#[test]
fn a_ranger_sending_ranges_and_intensities_reads_as_often_as_the_laser() {
    let running = serve_world("multirobot.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .unwrap();
    let rows = runtime.block_on(async {
        let url = format!("ws://127.0.0.1:{}/ws", front.web.port());
        let (mut page, _) = tokio_tungstenite::connect_async(url).await.unwrap();
        // The first rows cover the survey's first second; the fourth a steady one.
        let mut statuses = 0;
        loop {
            let next = tokio::time::timeout(Duration::from_secs(10), page.next()).await;
            let Ok(Some(Ok(Message::Text(text)))) = next else {
                panic!("the page's socket gave no status frame: {next:?}");
            };
            let value: Value = serde_json::from_str(&text).unwrap();
            if value["type"] == "status" {
                statuses += 1;
                if statuses == 4 {
                    return value["rows"].as_array().unwrap().clone();
                }
            }
        }
    });
    let rate = |row: &Value, device: &str| {
        row["devices"]
            .as_array()
            .unwrap()
            .iter()
            .find(|d| d["device"] == device)
            .map(|d| d["hz"].as_f64().unwrap())
    };
    let mut rangers = 0;
    for row in &rows {
        let (Some(laser), Some(ranger)) = (rate(row, "laser:0"), rate(row, "ranger:0")) else {
            continue;
        };
        rangers += 1;
        assert!((7.0..=13.0).contains(&laser), "laser {laser} Hz: {row}");
        assert!((7.0..=13.0).contains(&ranger), "ranger {ranger} Hz: {row}");
    }
    assert_eq!(rangers, 5, "every robot has a laser and a ranger: {rows:?}");
}
