//! The web page in a real browser (Debian's Chromium, headless, driven by Playwright from
//! tests/web/page.mjs) against player-sim worlds through the relay: it draws the robots where
//! the simulation has them, follows them as they move, takes the controller's goals and keys
//! and nobody else's, and shows a restarted robot server reconnecting and resuming.

mod support;

use std::net::{IpAddr, Ipv4Addr};
use std::time::Duration;

use player_proto::client::{Client, ClientOptions};
use player_proto::server::Commanders;
use serde_json::Value;
use support::{
    Front, LOCALHOST, page, page_sized, robot_name, screenshot, serve_world, sim_pose, wait_for,
};

fn pose_of(seen: &Value) -> (f64, f64) {
    (
        seen["pose"][0].as_f64().unwrap(),
        seen["pose"][1].as_f64().unwrap(),
    )
}

/// A robot's colour, not the map's greys or the background's: one channel well apart from
/// another.
fn is_robot_colour(pixel: &Value) -> bool {
    let channels: Vec<i64> = (0..3).map(|i| pixel[i].as_i64().unwrap()).collect();
    channels.iter().max().unwrap() - channels.iter().min().unwrap() > 40
}

/// Whether most of the pixels sampled around a robot's centre are its colour.
fn drawn_as_robot(pixels: &Value) -> bool {
    let pixels = pixels.as_array().unwrap();
    pixels.iter().filter(|p| is_robot_colour(p)).count() * 2 > pixels.len()
}

#[test]
fn the_page_draws_every_robot_where_the_simulation_has_it_with_the_map() {
    let running = serve_world("navigation.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let seen = page(&["draw", &front.url(), &screenshot("navigation.png")]);
    let robots = seen["robots"].as_object().unwrap();
    assert_eq!(
        robots.len(),
        running.ports.len(),
        "a robot per server: {seen}"
    );
    let sim: Vec<(f64, f64, f64)> = {
        let count = running.sim.lock().unwrap().robots.len();
        (0..count).map(|i| sim_pose(&running, i)).collect()
    };
    for (name, robot) in robots {
        let (x, y) = pose_of(robot);
        assert!(
            sim.iter().any(|s| (s.0 - x).hypot(s.1 - y) < 0.3),
            "{name} drawn at ({x:.2}, {y:.2}), no simulated robot there: {sim:?}"
        );
        assert!(
            drawn_as_robot(&robot["pixels"]),
            "{name}: the pixels around its pose are {}, mostly not a robot's colour",
            robot["pixels"]
        );
    }
    assert!(
        robots.values().any(|r| r["maps"].as_u64() == Some(1)),
        "the navigation server's map reached the page: {seen}"
    );
    assert_eq!(
        seen["layout"]["rowCount"].as_u64(),
        Some(robots.len() as u64)
    );
}

#[test]
fn on_a_phone_the_rows_sit_below_the_view() {
    let running = serve_world("simple.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let seen = page_sized("390x844", &["draw", &front.url(), &screenshot("phone.png")]);
    let (view, rows) = (&seen["layout"]["view"], &seen["layout"]["rows"]);
    let view_bottom = view[1].as_f64().unwrap() + view[3].as_f64().unwrap();
    assert!(
        view[2].as_f64().unwrap() <= 390.0,
        "the view fits the width: {view}"
    );
    assert!(
        rows[1].as_f64().unwrap() >= view_bottom - 1.0,
        "rows below the view: {seen}"
    );
    assert!(drawn_as_robot(
        &seen["robots"][robot_name(&running, 6665)]["pixels"]
    ));
}

#[test]
fn the_rows_are_summed_up_and_a_robot_is_found_by_what_its_row_says() {
    let running = serve_world("multirobot.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let name = robot_name(&running, running.ports[2].0);
    let seen = page(&["find", &front.url(), &name]);
    let robots = running.ports.len();
    let listed = |when: &str| seen[when]["rows"].as_array().unwrap().len();
    let summary = |when: &str| seen[when]["summary"].as_str().unwrap().to_string();
    assert_eq!(listed("before"), robots, "every robot listed: {seen}");
    assert!(
        summary("before").starts_with(&format!("{robots} robots: {robots} connected")),
        "the summary counts the robots by link: {seen}"
    );
    assert_eq!(
        seen["after"]["rows"],
        serde_json::json!([name]),
        "Find lists the robot named: {seen}"
    );
    assert!(summary("after").ends_with("· 1 found"), "{seen}");
    assert_eq!(seen["errors"], serde_json::json!([]), "{seen}");
}

#[test]
fn a_robot_that_moves_in_the_simulation_moves_on_the_page() {
    let running = serve_world("simple.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let port = running.port(6665).unwrap();
    let driver = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    driver.position2d(0).set_velocity(0.3, 0.0, 0.0);
    let seen = page(&["follow", &front.url(), &robot_name(&running, 6665), "3"]);
    let now = sim_pose(&running, 0);
    let samples = seen["samples"].as_array().unwrap();
    let xy = |v: &Value| (v[0].as_f64().unwrap(), v[1].as_f64().unwrap());
    let (first, last) = (xy(&samples[0]), xy(samples.last().unwrap()));
    assert!(last.0 - first.0 > 0.5, "the page saw it move: {samples:?}");
    assert!(
        (now.0 - last.0).abs() < 0.4 && (now.1 - last.1).abs() < 0.1,
        "the page's last pose {last:?} is where the simulation had it, {now:?}"
    );
    driver.position2d(0).set_velocity(0.0, 0.0, 0.0);
}

#[test]
fn the_controllers_click_sends_a_goal_the_robot_reaches_and_keys_drive_it() {
    let running = serve_world("simple.world", None);
    let front = Front::start(&running, Commanders::Address(LOCALHOST));
    let name = robot_name(&running, 6665);
    let seen = page(&["command", &front.url(), &name, "0", "1.5", "0"]);
    assert_eq!(seen["controller"], Value::Bool(true), "{seen}");
    assert_eq!(seen["selected"]["robot"], Value::String(name.clone()));
    assert_eq!(seen["refused"], Value::String(String::new()));
    // A position goal ends facing its heading (the page asks for 0 rad).
    let reached = wait_for(Duration::from_secs(30), || {
        let (x, y, a) = sim_pose(&running, 0);
        x.hypot(y - 1.5) < 0.05 && a.abs() < 0.02
    });
    assert!(
        reached,
        "the robot reached the goal: it is at {:?}",
        sim_pose(&running, 0)
    );
    let heading = sim_pose(&running, 0).2;
    let seen = page(&["command", &front.url(), &name, "-", "-", "1"]);
    assert_eq!(seen["refused"], Value::String(String::new()));
    let turned = sim_pose(&running, 0).2 - heading;
    assert!(
        turned.abs() > 0.4,
        "holding ← turned the robot: {turned} rad"
    );
    let still = sim_pose(&running, 0);
    std::thread::sleep(Duration::from_millis(500));
    assert!(
        (sim_pose(&running, 0).2 - still.2).abs() < 0.05,
        "released, the robot stops"
    );
}

#[test]
fn the_controllers_goal_goes_through_the_robots_planner() {
    let running = serve_world("navigation.world", None);
    let front = Front::start(&running, Commanders::FirstToAsk);
    // The navigation server (the lowest port) serves the planner for r0, robot 0.
    let nav = running.ports.iter().map(|p| p.0).min().unwrap();
    let name = robot_name(&running, nav);
    let start = sim_pose(&running, 0);
    let goal = (start.0 + 1.5, start.1);
    let seen = page(&[
        "command",
        &front.url(),
        &name,
        &goal.0.to_string(),
        &goal.1.to_string(),
        "0",
    ]);
    assert_eq!(seen["refused"], Value::String(String::new()), "{seen}");
    let reached = wait_for(Duration::from_secs(60), || {
        let (x, y, _) = sim_pose(&running, 0);
        (x - goal.0).hypot(y - goal.1) < 0.5
    });
    assert!(
        reached,
        "the planner took r0 from {start:?} to {goal:?}: it is at {:?}",
        sim_pose(&running, 0)
    );
}

#[test]
fn an_observers_clicks_and_keys_change_nothing() {
    let running = serve_world("simple.world", None);
    let elsewhere = IpAddr::V4(Ipv4Addr::new(10, 9, 9, 9));
    let front = Front::start(&running, Commanders::Address(elsewhere));
    let before = sim_pose(&running, 0);
    let seen = page(&[
        "command",
        &front.url(),
        &robot_name(&running, 6665),
        "0",
        "1.5",
        "1",
    ]);
    assert_eq!(seen["controller"], Value::Bool(false));
    assert_eq!(seen["role"], Value::String("observing".into()));
    std::thread::sleep(Duration::from_millis(500));
    let after = sim_pose(&running, 0);
    assert!(
        (after.0 - before.0).abs() < 1e-6 && (after.2 - before.2).abs() < 1e-6,
        "the robot stayed put: {before:?} → {after:?}"
    );
}

#[test]
fn a_restarted_robot_server_shows_reconnecting_then_resumes() {
    let running = serve_world("simple.world", None);
    let ports = running.ports.clone();
    let front = Front::start(&running, Commanders::Nobody);
    let name = robot_name(&running, 6665);
    let url = front.url();
    let watcher = std::thread::spawn(move || page(&["link", &url, &name, "25"]));
    // The page settles (Chromium starts, the robot is drawn) before its server goes.
    std::thread::sleep(Duration::from_secs(6));
    drop(running);
    std::thread::sleep(Duration::from_millis(1500));
    let _restarted = serve_world("simple.world", Some(&ports));
    let seen = watcher.join().unwrap();
    let states: Vec<&str> = seen["states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["state"].as_str().unwrap())
        .collect();
    let gone = states.iter().position(|s| *s == "reconnecting");
    assert!(gone.is_some(), "the page showed the robot gone: {seen}");
    let last = seen["states"].as_array().unwrap().last().unwrap();
    assert_eq!(last["state"], "connected", "and back: {seen}");
    assert_eq!(last["posed"], Value::Bool(true), "with fresh data: {seen}");
}
