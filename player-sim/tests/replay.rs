//! Record a live player-sim session over TCP, then serve the recording with `player-sim
//! --replay`: a client sees the same messages; commands are NACKed; a paused replay steps and
//! seeks; a torn recording plays up to its cut; a client that vanishes or a replay that is
//! killed leaves the others, and the recording, as they were.

mod support;

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{self, Receiver};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use bytes::Bytes;
use player_proto::capture::Direction;
use player_proto::client::{Client, ClientOptions, ConnectionState, TapEvent};
use player_proto::interfaces::log::{self, Log, LogReadStep, LogSetReadPosition, LogSetReadState};
use player_proto::message::Body;
use player_proto::recording::{self, Event, Recorder};
use player_proto::wire::{DevAddr, Header, Interface, MsgType};
use player_sim::replay::{ReplayOptions, Replaying, replay};
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::World;
use support::free_port;

const WAIT: Duration = Duration::from_secs(20);
/// DATA messages recorded from the live simulation.
const RECORDED: usize = 40;

/// A message as a client receives it: header and body bytes.
type Seen = (Header, Bytes);

/// Checks that `got` are the messages `want`, as a client sees them: same device, type,
/// subtype, timestamp and body bytes (the port and host are the serving server's).
fn assert_same(want: &[Seen], got: &[Seen]) {
    assert_eq!(want.len(), got.len());
    for (i, ((w, wb), (g, gb))) in want.iter().zip(got).enumerate() {
        assert_eq!(
            (w.addr.interf, w.addr.index, w.msg_type, w.subtype),
            (g.addr.interf, g.addr.index, g.msg_type, g.subtype),
            "message {i}"
        );
        assert_eq!(
            w.timestamp.to_bits(),
            g.timestamp.to_bits(),
            "message {i}: {w} / {g}"
        );
        assert!(wb == gb, "message {i}: the body bytes differ ({w})");
    }
}

/// A tap that hands every message from the server to a channel.
fn collecting_options() -> (ClientOptions, Receiver<Seen>) {
    let (sender, received) = mpsc::channel();
    let sender = Arc::new(Mutex::new(sender));
    let tap: player_proto::client::Tap = Arc::new(move |_host: &str, _port: u16| {
        let sender = sender.clone();
        let tap: player_proto::client::ConnectionTap = Arc::new(move |_, event| {
            if let TapEvent::Frame {
                direction: Direction::ServerToClient,
                header,
                body,
            } = event
            {
                let _ = sender.lock().unwrap().send((*header, body.clone()));
            }
        });
        tap
    });
    let options = ClientOptions {
        tap: Some(tap),
        replace_old_data: false,
        ..ClientOptions::default()
    };
    (options, received)
}

/// The next DATA message of a recorded device (not the `log` device's reports).
fn next_data(received: &Receiver<Seen>) -> Seen {
    loop {
        let seen = received.recv_timeout(WAIT).expect("a message");
        if seen.0.msg_type == MsgType::Data && seen.0.addr.interf != Interface::LOG {
            return seen;
        }
    }
}

/// Records `RECORDED` DATA messages of simple.world's robot; returns the file and what the
/// recording client received.
fn record_live(dir: &Path) -> (PathBuf, Vec<Seen>) {
    let worlds = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds");
    let world_file = worlds.join("simple.world");
    let world = World::load(&world_file).unwrap();
    let devices = from_cfg(&world_file.with_extension("cfg"), &world, &mut Vec::new()).unwrap();
    let options = ServeOptions {
        speedup: 10.0,
        free_ports: true,
        ..ServeOptions::default()
    };
    let sim = serve(Simulation::new(world), devices, options).unwrap();
    let port = sim.port(6665).unwrap();

    let path = dir.join("live.prec");
    let recorder = Recorder::create(&path).unwrap();
    let (mut options, received) = collecting_options();
    let (record_tap, collect_tap) = (recorder.tap(), options.tap.take().unwrap());
    options.tap = Some(Arc::new(move |host: &str, port: u16| {
        let (record, collect) = (record_tap(host, port), collect_tap(host, port));
        let both: player_proto::client::ConnectionTap = Arc::new(move |time, event| {
            record(time, event);
            collect(time, event);
        });
        both
    }));
    let mut client = Client::connect("127.0.0.1", port, options).unwrap();
    client.position2d(0).subscribe().unwrap();
    client.laser(0).subscribe().unwrap();
    let seen: Vec<Seen> = (0..RECORDED).map(|_| next_data(&received)).collect();
    client.close();
    drop(sim);
    let stats = recorder.finish().unwrap();
    assert_eq!(stats.lost(), 0, "{stats:?}");
    (path, seen)
}

/// The DATA messages from the server in a recording, in order.
fn data_in(path: &Path) -> Vec<Seen> {
    recording::open(path)
        .unwrap()
        .map(Result::unwrap)
        .filter_map(|r| match r.event {
            Event::Message {
                direction: Direction::ServerToClient,
                header,
                body,
            } if header.msg_type == MsgType::Data => Some((header, body)),
            _ => None,
        })
        .collect()
}

/// `player-sim --replay`, once it says it serves.
fn replay_binary(path: &Path, port: u16, extra: &[&str]) -> Child {
    let mut child = Command::new(env!("CARGO_BIN_EXE_player-sim"))
        .args([
            "--replay",
            path.to_str().unwrap(),
            "--port-base",
            &port.to_string(),
        ])
        .args(extra)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stderr = BufReader::new(child.stderr.take().unwrap());
    let mut line = String::new();
    while !line.contains("port(s)") {
        line.clear();
        assert!(stderr.read_line(&mut line).unwrap() > 0, "no serving line");
    }
    child
}

fn set_playing(client: &Client, log: DevAddr, playing: bool) {
    let body = Log::SetReadState(LogSetReadState {
        state: u8::from(playing),
    });
    client
        .request(log, log::REQ_SET_READ_STATE, Body::Log(body))
        .unwrap();
}

#[test]
fn a_recorded_session_replays_as_the_same_messages() {
    let dir = tempfile::tempdir().unwrap();
    let (path, recorded) = record_live(dir.path());
    let port = free_port();
    let mut child = replay_binary(&path, port, &["--paused", "--speed", "4"]);

    let (options, received) = collecting_options();
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    let drivers: Vec<_> = client.devices().into_iter().map(|d| d.driver).collect();
    assert!(drivers.iter().any(|d| d == "stage"), "{drivers:?}");
    client.position2d(0).subscribe().unwrap();
    client.laser(0).subscribe().unwrap();
    set_playing(&client, client.addr(Interface::LOG, 0), true);
    let replayed: Vec<Seen> = (0..RECORDED).map(|_| next_data(&received)).collect();
    child.kill().unwrap();
    let _ = child.wait();

    assert_same(&recorded, &replayed);
    assert!(
        replayed
            .iter()
            .all(|(h, _)| h.addr.robot == u32::from(port))
    );
}

fn replay_in_process(path: &Path, paused: bool) -> Replaying {
    let options = ReplayOptions {
        port_base: Some(0),
        paused,
        ..ReplayOptions::default()
    };
    replay(path, &options).unwrap()
}

#[test]
fn commands_to_a_replay_are_refused_with_a_nack() {
    let dir = tempfile::tempdir().unwrap();
    let (path, _) = record_live(dir.path());
    let replaying = replay_in_process(&path, true);
    let (options, received) = collecting_options();
    let client = Client::connect("127.0.0.1", replaying.servers[0].port, options).unwrap();
    let base = client.position2d(0);
    base.subscribe().unwrap();
    base.set_velocity(0.5, 0.0, 0.0);
    let nack = loop {
        let (header, _) = received.recv_timeout(WAIT).expect("a reply to the command");
        if header.msg_type == MsgType::Nack {
            break header;
        }
    };
    assert_eq!(nack.addr.interf, Interface::POSITION2D);
    // A request the robot was never asked during the recording is refused too.
    assert!(client.position2d(0).set_motor_power(true).is_err());
}

#[test]
fn a_paused_replay_steps_and_seeks() {
    let dir = tempfile::tempdir().unwrap();
    let (path, recorded) = record_live(dir.path());
    let replaying = replay_in_process(&path, true);
    let (options, received) = collecting_options();
    let client = Client::connect("127.0.0.1", replaying.servers[0].port, options).unwrap();
    let log_device = replaying.servers[0].log;
    client.position2d(0).subscribe().unwrap();
    client.laser(0).subscribe().unwrap();

    // A step to the next message plays exactly that one.
    let step = Body::Log(Log::ReadStep(LogReadStep { seconds: 0.0 }));
    client
        .request(log_device, log::REQ_READ_STEP, step.clone())
        .unwrap();
    assert_same(&recorded[..1], &[next_data(&received)]);
    client
        .request(log_device, log::REQ_READ_STEP, step)
        .unwrap();
    assert_same(&recorded[1..2], &[next_data(&received)]);
    assert!(!replaying.clock.is_playing());

    // Seeking to the end shows the newest message of each device there.
    let end = Body::Log(Log::SetReadPosition(LogSetReadPosition { position: 1e6 }));
    client
        .request(log_device, log::REQ_SET_READ_POSITION, end)
        .unwrap();
    let mut newest = [next_data(&received), next_data(&received)];
    newest.sort_by_key(|(h, _)| h.addr.interf);
    // The newest of each device in the file (the recorder may have kept a few after the
    // messages the test waited for).
    let in_file = data_in(&path);
    let mut want: Vec<Seen> = Vec::new();
    for interf in [Interface::POSITION2D, Interface::LASER] {
        want.extend(
            in_file
                .iter()
                .rev()
                .find(|(h, _)| h.addr.interf == interf)
                .cloned(),
        );
    }
    want.sort_by_key(|(h, _)| h.addr.interf);
    assert_same(&want, &newest);
    assert_eq!(replaying.clock.position_ns(), replaying.clock.duration_ns());
}

#[test]
fn a_torn_recording_replays_up_to_the_cut_and_says_where() {
    let dir = tempfile::tempdir().unwrap();
    let (path, recorded) = record_live(dir.path());
    let records: Vec<_> = recording::open(&path)
        .unwrap()
        .map(Result::unwrap)
        .collect();
    // Cut in the middle of the 20th DATA message's record.
    let mut reader = recording::open(&path).unwrap();
    let mut data = 0;
    let cut = loop {
        let at = reader.offset();
        let record = reader.next_record().unwrap().unwrap();
        if matches!(&record.event, Event::Message { header, direction: Direction::ServerToClient, .. } if header.msg_type == MsgType::Data)
        {
            data += 1;
            if data == 20 {
                break at + 30;
            }
        }
    };
    assert!(records.len() > 20);
    let bytes = std::fs::read(&path).unwrap();
    let torn = dir.path().join("torn.prec");
    std::fs::write(&torn, &bytes[..cut as usize]).unwrap();

    let replaying = replay_in_process(&torn, true);
    let stopped = replaying.stopped.as_ref().expect("the cut is reported");
    assert!(stopped.is_torn_tail());
    assert!(
        stopped.to_string().contains(&format!("byte {}", cut - 30)),
        "{stopped}"
    );

    let (options, received) = collecting_options();
    let client = Client::connect("127.0.0.1", replaying.servers[0].port, options).unwrap();
    let log_device = replaying.servers[0].log;
    client.position2d(0).subscribe().unwrap();
    client.laser(0).subscribe().unwrap();
    client.subscribe(log_device).unwrap();
    set_playing(&client, log_device, true);
    let played: Vec<Seen> = (0..19).map(|_| next_data(&received)).collect();
    assert_same(&recorded[..19], &played);
    // Then the log device reports it paused at the end, and nothing more was sent.
    loop {
        let (header, body) = received.recv_timeout(WAIT).expect("a playback report");
        assert!(
            header.msg_type != MsgType::Data || header.addr.interf == Interface::LOG,
            "data after the cut: {header}"
        );
        let report = player_proto::Message::decode(header, body).unwrap();
        if let Body::Log(Log::Playback(p)) = report.body
            && p.state == 0
        {
            assert_eq!(p.position, p.duration);
            break;
        }
    }
}

#[test]
fn a_vanishing_client_leaves_the_others_playing_and_a_killed_replay_is_reconnected_to() {
    let dir = tempfile::tempdir().unwrap();
    let (path, recorded) = record_live(dir.path());
    let port = free_port();
    let mut child = replay_binary(&path, port, &["--paused", "--loop"]);

    let (options, received) = collecting_options();
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    client.position2d(0).subscribe().unwrap();
    // A second client subscribes, then vanishes without unsubscribing.
    {
        let mut vanishing = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
        use std::io::Write;
        let subscribe = player_proto::message::Message::typed(
            DevAddr::local(Interface::PLAYER, 0),
            MsgType::Req,
            player_proto::interfaces::player::Player::Device(
                player_proto::interfaces::player::DeviceReq {
                    addr: DevAddr::local(Interface::LASER, 0),
                    access: player_proto::interfaces::player::OPEN_MODE,
                    driver_name: Default::default(),
                },
            ),
        );
        vanishing.write_all(&subscribe.to_bytes()).unwrap();
    }
    set_playing(&client, client.addr(Interface::LOG, 0), true);
    let played: Vec<Seen> = (0..RECORDED).map(|_| next_data(&received)).collect();
    assert_same(&recorded, &played);

    child.kill().unwrap();
    let _ = child.wait();
    let state = client.wait_for_state(WAIT, |s| *s != ConnectionState::Connected);
    assert!(
        matches!(state, Some(ConnectionState::Reconnecting { .. })),
        "{state:?}"
    );
    assert!(client.last_disconnect().is_some());

    // A replay started again on the port is found, and the subscriptions are restored.
    let mut again = replay_binary(&path, port, &["--loop"]);
    client
        .wait_for_state(WAIT, |s| *s == ConnectionState::Connected)
        .expect("reconnected");
    let (header, _) = loop {
        let seen = next_data(&received);
        if client.state() == ConnectionState::Connected
            && seen.0.timestamp == recorded[0].0.timestamp
        {
            break seen;
        }
    };
    assert_eq!(header.addr.robot, u32::from(port));
    again.kill().unwrap();
    let _ = again.wait();
}
