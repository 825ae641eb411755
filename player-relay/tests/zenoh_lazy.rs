//! `--from-zenoh` costs the robot's site what is looked at: the bridge subscribes in Zenoh to
//! a device's data only while one of its Player clients is subscribed to the device, so the
//! robot's relay (whose Zenoh front looks at what some Zenoh subscriber matches) subscribes
//! upstream to that device alone, and lets go once the client does.
//!
//! Zenoh runs in a network namespace of the test's own, never on the machine's network: the
//! test runs itself again under `unshare --net` with only loopback up. That needs root (as
//! CI has); anywhere else it says so and passes without running.

mod zenoh_support;

use std::time::{Duration, Instant};

use player_proto::wire::Interface;
use player_zenoh::{FromZenoh, FromZenohConfig, Mode};
use zenoh_support::*;

fn wait_for(what: &str, done: impl Fn() -> bool) {
    let deadline = Instant::now() + PATIENCE;
    while !done() {
        assert!(Instant::now() < deadline, "never: {what}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn from_zenoh_subscribes_to_a_device_only_while_a_client_looks_at_it() {
    if !inside_own_namespace("from_zenoh_subscribes_to_a_device_only_while_a_client_looks_at_it") {
        return;
    }
    program_edge::logging::init("warn");
    let running = serve_world("simple.world", None);
    let zport = free_port();
    let robot_side = session(Mode::Peer, Some(zport), None);
    let viewer_side = session(Mode::Peer, None, Some(zport));
    let site = Site::start(robot_side, "A", "teacher", &running);
    let bridge = FromZenoh::start(viewer_side, FromZenohConfig::new("A", "teacher"))
        .expect("the bridge starts");
    let served = bridge.wait_for_robots(1, PATIENCE);
    assert_eq!(served.len(), 1, "the robot is found through Zenoh");
    let port = served[0].1;
    let upstream = || site.relay.robots()[0].upstream_subscriptions();

    // Nobody looks: no data subscribed in Zenoh, and the relay lets go of every device once
    // its survey is over.
    assert_eq!(bridge.data_subscriptions(), 0);
    wait_for("the relay subscribed to nothing", || {
        site.front.looks() == 0 && upstream().is_empty()
    });

    // A client subscribes to the laser: the bridge to its data key alone, the relay to it.
    let client = connect(port);
    client
        .subscribe(laser_of(&client))
        .expect("subscribed through Zenoh");
    wait_for("a scan through Zenoh", || client.laser(0).scan().is_some());
    assert_eq!(bridge.data_subscriptions(), 1);
    assert_eq!(site.front.looks(), 1);
    assert_eq!(upstream(), [(Interface::LASER, 0)]);

    // The client goes: the bridge lets go, and so does the relay.
    drop(client);
    wait_for("the bridge let go", || bridge.data_subscriptions() == 0);
    wait_for("the relay let go", || {
        site.front.looks() == 0 && upstream().is_empty()
    });
}
