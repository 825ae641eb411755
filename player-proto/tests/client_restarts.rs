//! The client against a server that dies and comes back, over real TCP: subscriptions,
//! data modes and replace rules restored, what was asked while it was away, and a quiet
//! server not taken for a stalled one.

mod support;

use std::sync::Arc;
use std::time::Duration;

use player_proto::client::{
    Client, ClientOptions, ConnectionState, DataMode, ReplaceAction, ReplaceRule, RequestError,
};
use player_proto::wire::Interface;

use support::served_robots::*;

#[test]
fn a_restarted_server_gets_its_subscriptions_back() {
    let s = server(0, Arc::default());
    let port = s.port(0);
    let client = Client::connect("127.0.0.1", port, quick()).unwrap();
    client.laser(0).subscribe().unwrap();
    let feed = Feeder::start(s.publisher(), addr(&s, "laser:0"));
    wait_for("data", Duration::from_secs(3), || {
        client.laser(0).scan().is_some()
    });
    drop(feed);
    drop(s);
    wait_for_state(
        &client,
        "the client to notice",
        Duration::from_secs(3),
        |s| *s != ConnectionState::Connected,
    );
    let seq_before = client.laser(0).scan().unwrap().1.seq;

    let s = server(port, Arc::default());
    wait_for_state(&client, "reconnection", Duration::from_secs(5), |s| {
        *s == ConnectionState::Connected
    });
    let _feed = Feeder::start(s.publisher(), addr(&s, "laser:0"));
    wait_for(
        "data again, on the restored subscription",
        Duration::from_secs(3),
        || {
            client
                .laser(0)
                .scan()
                .is_some_and(|(_, st)| st.seq > seq_before)
        },
    );
}

#[test]
fn runtime_data_mode_and_replace_rules_survive_a_server_restart() {
    let s = server(0, Arc::default());
    let port = s.port(0);
    // Connect in PUSH mode with no replace rule; switch both at run time.
    let options = ClientOptions {
        replace_old_data: false,
        ..quick()
    };
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    client.set_data_mode(DataMode::Pull).unwrap();
    let rule = ReplaceRule::device_data(Interface::LASER, 0, ReplaceAction::Replace);
    client.add_replace_rule(rule).unwrap();
    assert_eq!(client.data_mode(), DataMode::Pull);
    assert_eq!(client.replace_rules(), vec![rule]);

    drop(s);
    wait_for_state(
        &client,
        "the client to notice",
        Duration::from_secs(3),
        |s| *s != ConnectionState::Connected,
    );
    let s = server(port, Arc::default());
    wait_for_state(&client, "reconnection", Duration::from_secs(5), |s| {
        *s == ConnectionState::Connected
    });
    for id in 0..20 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
    }
    std::thread::sleep(Duration::from_millis(100));
    assert!(
        client.laser(0).scan().is_none(),
        "PULL restored: nothing arrives until asked"
    );
    assert_eq!(
        client.pull().unwrap(),
        1,
        "the restored replace rule left only the newest of 20 scans"
    );
    assert_eq!(client.laser(0).scan().unwrap().0.id, 19);

    // And back to PUSH at run time: data flows unasked.
    client.set_data_mode(DataMode::Push).unwrap();
    s.publisher().publish(addr(&s, "laser:0"), 1, scan(20), 0.0);
    wait_for("pushed data", Duration::from_secs(3), || {
        client
            .laser(0)
            .scan()
            .is_some_and(|(scan, _)| scan.id == 20)
    });
}

#[test]
fn what_is_asked_while_the_server_is_away_holds_once_it_comes() {
    let port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let client = Client::spawn("127.0.0.1", port, quick()).unwrap();
    assert_eq!(client.replace_rules(), vec![ReplaceRule::newest_data()]);
    let laser = client.addr(Interface::LASER, 0);
    assert!(matches!(
        client.subscribe_async(laser).wait(Duration::from_secs(5)),
        Err(RequestError::Disconnected(_))
    ));
    assert!(matches!(
        client.set_data_mode(DataMode::Pull),
        Err(RequestError::Disconnected(_))
    ));
    assert_eq!(
        client.data_mode(),
        DataMode::Pull,
        "remembered all the same"
    );

    let s = server(port, Arc::default());
    wait_for_state(&client, "the server", Duration::from_secs(5), |s| {
        *s == ConnectionState::Connected
    });
    for id in 0..5 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
    }
    assert_eq!(client.pull().unwrap(), 1, "PULL, newest only, subscribed");
    assert_eq!(client.laser(0).scan().unwrap().0.id, 4);
}

#[test]
fn a_quiet_server_is_not_taken_for_a_stalled_one() {
    let s = server(0, Arc::default());
    let options = ClientOptions {
        stall_timeout: Some(Duration::from_millis(100)),
        ..quick()
    };
    let client = Client::connect("127.0.0.1", s.port(0), options).unwrap();
    client.laser(0).subscribe().unwrap();
    // Subscribed, but nothing is published: the server answers the liveness probes only.
    std::thread::sleep(Duration::from_millis(800));
    assert_eq!(client.state(), ConnectionState::Connected);
    assert_eq!(client.last_disconnect(), None);
    assert_eq!(
        client.rejected(),
        0,
        "probe replies are not replies to nothing"
    );
}
