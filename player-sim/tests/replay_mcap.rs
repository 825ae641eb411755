//! A recording of a real Player 3 + Stage 4 server (`captures/laser_push.jsonl`), exported to
//! MCAP, is served by `player-sim --replay` as the `.prec` is: a client receives the same
//! messages, byte for byte, from both. A live session recorded straight into MCAP replays as
//! it was received.

use std::io::{BufReader, Cursor};
use std::path::Path;
use std::sync::mpsc::{self, Receiver};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use bytes::Bytes;
use player_proto::capture::{Direction, parse_capture};
use player_proto::client::{Client, ClientOptions, TapEvent};
use player_proto::interfaces::log::{self, Log, LogReadStep, LogSetReadPosition, LogSetReadState};
use player_proto::message::Body;
use player_proto::recording::from_capture::records_from_capture;
use player_proto::recording::{Event, RecordingReader, RecordingWriter};
use player_proto::wire::{Header, Interface, MsgType};
use player_sim::replay::{ReplayOptions, replay};

const WAIT: Duration = Duration::from_secs(20);

type Seen = (Header, Bytes);

/// The capture as a `.prec`, and the laser DATA its server sent.
fn real_recording(dir: &Path) -> (std::path::PathBuf, Vec<Seen>) {
    let capture = Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures/laser_push.jsonl");
    let chunks = parse_capture(&std::fs::read_to_string(capture).unwrap()).unwrap();
    let records = records_from_capture(&chunks, "localhost", 6665, 0, 0).unwrap();
    let path = dir.join("laser.prec");
    let mut writer = RecordingWriter::new(std::fs::File::create(&path).unwrap()).unwrap();
    let mut sent = Vec::new();
    for record in &records {
        writer.write(record).unwrap();
        if let Event::Message {
            direction: Direction::ServerToClient,
            header,
            body,
        } = &record.event
            && header.msg_type == MsgType::Data
            && header.addr.interf == Interface::LASER
        {
            sent.push((*header, body.clone()));
        }
    }
    writer.flush().unwrap();
    assert!(sent.len() >= 10, "{} scans in the capture", sent.len());
    (path, sent)
}

fn to_mcap(prec: &Path) -> std::path::PathBuf {
    let reader = RecordingReader::new(BufReader::new(std::fs::File::open(prec).unwrap())).unwrap();
    let (converted, out) = player_mcap::prec_to_mcap(
        reader,
        Cursor::new(Vec::new()),
        player_mcap::McapOptions::default(),
    )
    .unwrap();
    assert!(converted.stopped.is_none());
    let path = prec.with_extension("mcap");
    std::fs::write(&path, out.into_inner()).unwrap();
    path
}

/// Replays `path` paused, subscribes a real client to its laser, plays, and returns the first
/// `count` laser DATA messages the client received.
fn laser_from_replay(path: &Path, count: usize) -> Vec<Seen> {
    let options = ReplayOptions {
        port_base: Some(0),
        paused: true,
        speed: 8.0,
        ..ReplayOptions::default()
    };
    let replaying = replay(path, &options).unwrap();
    let port = replaying.servers[0].port;
    let (options, received) = collecting();
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    let play = Log::SetReadState(LogSetReadState { state: 1 });
    client
        .request(
            client.addr(Interface::LOG, replaying.servers[0].log.index),
            log::REQ_SET_READ_STATE,
            Body::Log(play),
        )
        .unwrap();
    let mut seen = Vec::new();
    while seen.len() < count {
        let (header, body) = received.recv_timeout(WAIT).expect("a laser scan");
        if header.msg_type == MsgType::Data && header.addr.interf == Interface::LASER {
            seen.push((header, body));
        }
    }
    seen
}

fn collecting() -> (ClientOptions, Receiver<Seen>) {
    let (sender, received) = mpsc::channel();
    let sender = Arc::new(Mutex::new(sender));
    let tap: player_proto::client::Tap = Arc::new(move |_: &str, _: u16| {
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

/// Same device, subtype, timestamp and body bytes (the port is the replay's).
fn same(a: &[Seen], b: &[Seen]) {
    assert_eq!(a.len(), b.len());
    for (i, ((ha, ba), (hb, bb))) in a.iter().zip(b).enumerate() {
        let key = |h: &Header| {
            (
                h.addr.interf,
                h.addr.index,
                h.subtype,
                h.timestamp.to_bits(),
            )
        };
        assert_eq!(key(ha), key(hb), "message {i}");
        assert!(ba == bb, "message {i}: the body bytes differ");
    }
}

#[test]
fn an_mcap_export_of_a_real_server_replays_as_its_prec_does() {
    let dir = tempfile::tempdir().unwrap();
    let (prec, sent) = real_recording(dir.path());
    let mcap = to_mcap(&prec);
    let from_prec = laser_from_replay(&prec, sent.len());
    let from_mcap = laser_from_replay(&mcap, sent.len());
    same(&sent, &from_prec);
    same(&from_prec, &from_mcap);
}

#[test]
fn a_live_session_recorded_straight_into_mcap_replays_as_it_was_received() {
    use player_sim::serve::{ServeOptions, serve};
    let dir = tempfile::tempdir().unwrap();
    let world_file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/simple.world");
    let world = player_sim::world::World::load(&world_file).unwrap();
    let devices =
        player_sim::served::from_cfg(&world_file.with_extension("cfg"), &world, &mut Vec::new())
            .unwrap();
    let options = ServeOptions {
        speedup: 10.0,
        free_ports: true,
        ..ServeOptions::default()
    };
    let sim = serve(player_sim::sim::Simulation::new(world), devices, options).unwrap();
    let port = sim.port(6665).unwrap();

    let path = dir.path().join("live.mcap");
    let recorder = player_mcap::recorder(&path).unwrap();
    let (mut options, received) = collecting();
    let (record, collect) = (recorder.tap(), options.tap.take().unwrap());
    options.tap = Some(Arc::new(move |host: &str, port: u16| {
        let (record, collect) = (record(host, port), collect(host, port));
        let both: player_proto::client::ConnectionTap = Arc::new(move |time, event| {
            record(time, event);
            collect(time, event);
        });
        both
    }));
    let mut client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    let mut live = Vec::new();
    while live.len() < 20 {
        let (header, body) = received.recv_timeout(WAIT).expect("a laser scan");
        if header.msg_type == MsgType::Data && header.addr.interf == Interface::LASER {
            live.push((header, body));
        }
    }
    client.close();
    drop(sim);
    let stats = recorder.finish().unwrap();
    assert_eq!(stats.lost(), 0, "{stats:?}");
    assert_eq!(stats.bytes, std::fs::metadata(&path).unwrap().len());

    let replayed = laser_from_replay(&path, live.len());
    same(&live, &replayed);
}

#[test]
fn a_file_that_is_mcap_but_no_recording_is_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("other.mcap");
    let mut writer = mcap::Writer::new(Cursor::new(Vec::new())).unwrap();
    writer
        .add_channel(0, "/chatter", "json", &Default::default())
        .unwrap();
    writer.finish().unwrap();
    std::fs::write(&path, writer.into_inner().into_inner()).unwrap();
    let error = replay(&path, &ReplayOptions::default())
        .err()
        .expect("refused");
    let text = error.to_string();
    assert!(text.contains("other.mcap"), "{text}");
    assert!(text.contains("not a Player recording"), "{text}");
}

/// Seeks a paused replay of `path` to the middle and steps once: the newest scan before the
/// middle (what a seek shows) and the one after it. Scans stamped `first` are left out: a
/// paused replay still publishes the messages at its very start when its playback begins,
/// which a client subscribed by then receives before the seek's.
fn seek_and_step(path: &Path, first: f64) -> Vec<Seen> {
    let options = ReplayOptions {
        port_base: Some(0),
        paused: true,
        ..ReplayOptions::default()
    };
    let replaying = replay(path, &options).unwrap();
    let log_device = replaying.servers[0].log;
    let (options, received) = collecting();
    let client = Client::connect("127.0.0.1", replaying.servers[0].port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    let middle = replaying.clock.duration_ns() as f64 / 2e9;
    let seek = Log::SetReadPosition(LogSetReadPosition { position: middle });
    client
        .request(log_device, log::REQ_SET_READ_POSITION, Body::Log(seek))
        .unwrap();
    let laser = || loop {
        let seen = next_laser(&received);
        if seen.0.timestamp != first {
            return seen;
        }
    };
    let mut seen = vec![laser()];
    let step = Log::ReadStep(LogReadStep { seconds: 0.0 });
    client
        .request(log_device, log::REQ_READ_STEP, Body::Log(step))
        .unwrap();
    seen.push(laser());
    seen
}

fn next_laser(received: &Receiver<Seen>) -> Seen {
    loop {
        let (header, body) = received.recv_timeout(WAIT).expect("a laser scan");
        if header.msg_type == MsgType::Data && header.addr.interf == Interface::LASER {
            return (header, body);
        }
    }
}

#[test]
fn seeking_an_mcap_replay_reads_from_its_chunk_index_as_the_prec_is_read() {
    let dir = tempfile::tempdir().unwrap();
    let (prec, sent) = real_recording(dir.path());
    let mcap = to_mcap(&prec);
    assert!(player_mcap::McapFile::open(&mcap).unwrap().indexed());
    let first = sent[0].0.timestamp;
    let from_prec = seek_and_step(&prec, first);
    let from_mcap = seek_and_step(&mcap, first);
    same(&from_prec, &from_mcap);
    // Scans come in pairs with one timestamp: the seek shows the newest before the middle,
    // and the step plays the one after it in the file.
    let is = |seen: &Seen, s: &Seen| s.0.timestamp == seen.0.timestamp && s.1 == seen.1;
    let shown = sent.iter().rposition(|s| is(&from_mcap[0], s)).unwrap();
    let after = sent[shown + 1..].iter().position(|s| is(&from_mcap[1], s));
    let next = shown + 1 + after.unwrap();
    assert_eq!(
        next,
        shown + 1,
        "the step plays the scan after the one shown"
    );
    assert!(
        shown > 0 && next < sent.len() - 1,
        "the middle of {} scans",
        sent.len()
    );
}
