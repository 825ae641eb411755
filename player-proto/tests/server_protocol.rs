//! The server side over real TCP on 127.0.0.1, spoken to byte for byte.

mod support;

use std::sync::atomic::Ordering;
use std::time::Duration;

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player::{
    self, AddReplaceRuleReq, DataModeReq, DeviceReq, DriverInfo, Player,
};
use player_proto::interfaces::position2d::{Position2d, Position2dCmdVel};
use player_proto::message::{Body, Message};
use player_proto::wire::{DevAddr, Interface, MsgType, PlayerString};
use support::RawClient;
use support::test_server::{Fixture, fixture};

fn player_addr() -> DevAddr {
    DevAddr::local(Interface::PLAYER, 0)
}

fn subscribe(client: &mut RawClient, addr: &str, access: u8) -> Message {
    let req = DeviceReq {
        addr: addr.parse().unwrap(),
        access,
        driver_name: PlayerString::default(),
    };
    client.request(
        player_addr(),
        player::REQ_DEV,
        Body::Player(Player::Device(req)),
    )
}

fn laser_addr(f: &Fixture) -> DevAddr {
    DevAddr {
        robot: u32::from(f.server.port(0)),
        ..DevAddr::local(Interface::LASER, 0)
    }
}

fn scan(id: u32) -> Body {
    Body::Laser(Laser::Scan(LaserScan {
        ranges: vec![1.0; 4],
        id,
        ..LaserScan::default()
    }))
}

#[test]
fn device_list_driver_names_and_the_banner() {
    let f = fixture();
    let mut c = RawClient::connect(f.server.port(0));
    assert_eq!(c.banner.version, "3.1.1-dev");
    let reply = c.request(player_addr(), player::REQ_DEVLIST, Body::Empty);
    assert_eq!(reply.header.msg_type, MsgType::Ack);
    let Body::Player(Player::DevList(list)) = reply.body else {
        panic!("{reply:?}")
    };
    assert_eq!(list.devices.len(), 3, "only robot 0's devices on its port");
    assert!(
        list.devices
            .iter()
            .all(|d| d.robot == u32::from(f.server.port(0)) && d.host == 0x0100_007f)
    );

    let ask = |interf, index| DriverInfo {
        addr: DevAddr::local(interf, index),
        driver_name: PlayerString::default(),
    };
    let reply = c.request(
        player_addr(),
        player::REQ_DRIVERINFO,
        Body::Player(Player::DriverInfo(ask(Interface::LASER, 0))),
    );
    let Body::Player(Player::DriverInfo(info)) = reply.body else {
        panic!()
    };
    assert_eq!(
        info.driver_name.wire_bytes(),
        b"sicklms200\0",
        "the NUL is counted, as Player does"
    );
    let reply = c.request(
        player_addr(),
        player::REQ_DRIVERINFO,
        Body::Player(Player::DriverInfo(ask(Interface::SONAR, 0))),
    );
    assert_eq!(
        (reply.header.msg_type, reply.body),
        (MsgType::Nack, Body::Empty)
    );
}

#[test]
fn subscriptions_check_access_and_unknown_devices_get_a_nack_with_a_body() {
    let f = fixture();
    let mut c = RawClient::connect(f.server.port(0));
    let reply = subscribe(&mut c, "laser:0", player::OPEN_MODE);
    let Body::Player(Player::Device(granted)) = &reply.body else {
        panic!()
    };
    assert_eq!(
        (
            reply.header.msg_type,
            granted.access,
            granted.driver_name.as_str().as_ref()
        ),
        (MsgType::Ack, 1, "sicklms200")
    );
    assert_eq!(f.subscribers.load(Ordering::SeqCst), 1);

    let reply = subscribe(&mut c, "laser:1", player::OPEN_MODE);
    let Body::Player(Player::Device(refused)) = &reply.body else {
        panic!()
    };
    assert_eq!(
        (reply.header.msg_type, refused.access),
        (MsgType::Ack, 3),
        "a failed driver still ACKs, with access 3"
    );

    let reply = subscribe(&mut c, "sonar:0", player::OPEN_MODE);
    let Body::Player(Player::Device(unknown)) = &reply.body else {
        panic!()
    };
    assert_eq!((reply.header.msg_type, unknown.access), (MsgType::Nack, 3));

    let reply = subscribe(&mut c, "laser:0", player::CLOSE_MODE);
    let Body::Player(Player::Device(closed)) = &reply.body else {
        panic!()
    };
    assert_eq!(closed.access, 2);
    assert_eq!(f.subscribers.load(Ordering::SeqCst), 0);
}

#[test]
fn push_data_reaches_subscribers_only_and_a_closed_connection_unsubscribes() {
    let f = fixture();
    let mut subscribed = RawClient::connect(f.server.port(0));
    let mut other = RawClient::connect(f.server.port(0));
    subscribe(&mut subscribed, "laser:0", player::OPEN_MODE);
    assert_eq!(
        f.server
            .publisher()
            .publish(laser_addr(&f), 1, scan(1), 12.5),
        1
    );
    let data = subscribed.next();
    assert_eq!(
        (data.header.msg_type, data.header.timestamp),
        (MsgType::Data, 12.5)
    );
    assert_eq!(data.body, scan(1));
    other.set_timeout(Duration::from_millis(200));
    assert!(other.try_next().is_none(), "not subscribed, nothing sent");

    drop(subscribed);
    let deadline = std::time::Instant::now() + Duration::from_secs(3);
    while f.subscribers.load(Ordering::SeqCst) != 0 && std::time::Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(10));
    }
    assert_eq!(
        f.subscribers.load(Ordering::SeqCst),
        0,
        "a departed client is unsubscribed"
    );
}

#[test]
fn pull_mode_rounds_and_replace_rules() {
    let f = fixture();
    let mut c = RawClient::connect(f.server.port(0));
    let mode = DataModeReq {
        mode: player::DATAMODE_PULL,
    };
    assert_eq!(
        c.request(
            player_addr(),
            player::REQ_DATAMODE,
            Body::Player(Player::DataMode(mode))
        )
        .header
        .msg_type,
        MsgType::Ack
    );
    subscribe(&mut c, "laser:0", player::OPEN_MODE);
    let rule = AddReplaceRuleReq {
        interf: -1,
        index: -1,
        msg_type: 1,
        subtype: -1,
        replace: player::REPLACE_RULE_REPLACE,
    };
    assert_eq!(
        c.request(
            player_addr(),
            player::REQ_ADD_REPLACE_RULE,
            Body::Player(Player::AddReplaceRule(rule))
        )
        .header
        .msg_type,
        MsgType::Ack
    );
    for id in 0..5 {
        f.server
            .publisher()
            .publish(laser_addr(&f), 1, scan(id), 0.0);
    }
    c.set_timeout(Duration::from_millis(200));
    assert!(c.try_next().is_none(), "PULL holds data back");
    c.set_timeout(Duration::from_secs(3));
    c.send(&Message::new(
        player_addr(),
        MsgType::Req,
        player::REQ_DATA,
        Body::Empty,
    ));
    let round: Vec<Message> = (0..3).map(|_| c.next()).collect();
    assert_eq!(
        round
            .iter()
            .map(|m| (m.header.msg_type, m.header.subtype))
            .collect::<Vec<_>>(),
        [(MsgType::Ack, 4), (MsgType::Data, 1), (MsgType::Synch, 1)]
    );
    assert_eq!(
        round[1].body,
        scan(4),
        "only the newest scan survived the REPLACE rule"
    );
}

#[test]
fn commands_and_requests_reach_devices() {
    let f = fixture();
    let mut c = RawClient::connect(f.server.port(0));
    let base = DevAddr::local(Interface::POSITION2D, 0);
    let vel = Position2dCmdVel {
        vel: Pose2d::new(0.5, 0.0, 0.25),
        state: 1,
    };
    c.send(&Message::typed(
        base,
        MsgType::Cmd,
        Position2d::Velocity(vel),
    ));
    let geometry = Laser::REQ_GET_GEOM.subtype();
    let geom = c.request(DevAddr::local(Interface::LASER, 0), geometry, Body::Empty);
    assert_eq!(geom.header.msg_type, MsgType::Ack);
    assert_eq!(
        geom.header.addr.robot,
        u32::from(f.server.port(0)),
        "replies carry the device's address"
    );
    assert!(matches!(geom.body, Body::Laser(Laser::Geometry(_))));
    let nack = c.request(
        DevAddr::local(Interface::LASER, 0),
        Laser::REQ_POWER.subtype(),
        Body::Laser(Laser::Power(player_proto::interfaces::laser::LaserPower {
            state: 1,
        })),
    );
    assert_eq!(nack.header.msg_type, MsgType::Nack);
    // The command was handled before the request that followed it.
    let commands = f.commands.lock().unwrap();
    assert_eq!(commands.len(), 1);
    assert_eq!(
        commands[0].body,
        Body::Position2d(Position2d::Velocity(vel))
    );
}

#[test]
fn requests_to_unknown_devices_are_dropped_and_unimplemented_player_requests_nacked() {
    let f = fixture();
    let mut c = RawClient::connect(f.server.port(0));
    c.send(&Message::new(
        DevAddr::local(Interface::SONAR, 0),
        MsgType::Req,
        1,
        Body::Empty,
    ));
    let reply = c.request(player_addr(), player::REQ_AUTH, Body::Empty);
    assert_eq!(
        (reply.header.msg_type, reply.header.subtype),
        (MsgType::Nack, player::REQ_AUTH),
        "the sonar request got no reply"
    );
    let caps = c.request(DevAddr::local(Interface::LASER, 0), 255, Body::Empty);
    assert_eq!(caps.header.msg_type, MsgType::Nack);
}

#[test]
fn garbage_closes_that_connection_and_no_other() {
    let f = fixture();
    let mut good = RawClient::connect(f.server.port(0));
    subscribe(&mut good, "laser:0", player::OPEN_MODE);
    let mut bad = RawClient::connect(f.server.port(0));
    // A header with message type 99.
    let devlist = Message::new(
        player_addr(),
        MsgType::Req,
        player::REQ_DEVLIST,
        Body::Empty,
    );
    let mut garbage = devlist.to_bytes().to_vec();
    garbage[19] = 99;
    bad.send_raw(&garbage);
    assert!(
        bad.try_next().is_none(),
        "the server closed the bad connection"
    );
    let mut liar = RawClient::connect(f.server.port(0));
    let mut lying = devlist.to_bytes().to_vec();
    lying[36..40].copy_from_slice(&[0xff; 4]);
    liar.send_raw(&lying);
    assert!(
        liar.try_next().is_none(),
        "a lying size closes the connection"
    );

    f.server
        .publisher()
        .publish(laser_addr(&f), 1, scan(9), 0.0);
    assert_eq!(good.next().body, scan(9), "the good client carries on");
}

#[test]
fn robots_on_separate_ports_see_only_their_devices() {
    let f = fixture();
    let mut b = RawClient::connect(f.server.port(1));
    let reply = b.request(player_addr(), player::REQ_DEVLIST, Body::Empty);
    let Body::Player(Player::DevList(list)) = reply.body else {
        panic!()
    };
    assert_eq!(list.devices.len(), 1);
    assert_eq!(list.devices[0].robot, u32::from(f.server.port(1)));
}
