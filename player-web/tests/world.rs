//! The page shows a simulated world as `player-relay --world` serves it: each robot by its
//! model's name (in the rows and beside its body) and the world's walls under the robots,
//! in a real browser (Debian's Chromium through tests/web/page.mjs).

mod support;

use player_proto::server::Commanders;
use serde_json::Value;
use support::{Front, page, screenshot, serve_world};

/// The walls' grey (app.js's `drawWalls`), give or take what is drawn over it.
fn is_wall_grey(pixel: &Value) -> bool {
    let wall = [0x55, 0x59, 0x5f];
    (0..3).all(|i| (pixel[i].as_i64().unwrap() - wall[i]).abs() <= 12)
}

#[test]
fn the_page_names_the_worlds_robots_and_draws_its_walls() {
    let running = serve_world("multirobot.world", None);
    let front = Front::start_as_world(&running, "multirobot.world", Commanders::Nobody);
    let seen = page(&["draw", &front.url(), &screenshot("multirobot-world.png")]);
    let names = ["r0", "r1", "r2", "r3", "r4"];
    let robots: Vec<&str> = seen["robots"]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(robots, names, "the page's robots: {seen}");
    let mut labels: Vec<&str> = seen["labels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect();
    labels.sort();
    assert_eq!(labels, names, "each name written beside its robot");
    let walls = &seen["walls"];
    assert!(
        walls["rects"].as_u64().unwrap_or(0) >= 4,
        "at least the arena's four walls: {walls}"
    );
    let pixels = walls["pixels"].as_array().unwrap();
    let grey = pixels.iter().filter(|p| is_wall_grey(p)).count();
    assert!(
        grey * 2 > pixels.len(),
        "the largest walls' middles are drawn wall-grey: {pixels:?}"
    );
}

#[test]
fn without_a_world_the_page_draws_no_walls_and_names_robots_by_server() {
    let running = serve_world("simple.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let seen = page(&["draw", &front.url(), &screenshot("simple-no-world.png")]);
    assert_eq!(seen["walls"], Value::Null);
    let name = format!("127.0.0.1:{}", running.ports[0].1);
    assert_eq!(seen["labels"], serde_json::json!([name]));
}
