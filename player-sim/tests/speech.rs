//! The speech devices over TCP: `sentences` publishes its file's sentences as
//! speech-recognition data at their simulated times, `festival` logs what it is told to say
//! and speaks it into a WAV file with espeak-ng;
//! a broken sentences file is refused at its line.

mod support;

use std::time::Duration;

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::speech::{Speech, SpeechCmd};
use player_proto::interfaces::speech_recognition::SpeechRecognition;
use player_proto::message::Body;
use player_proto::wire::{Interface, PlayerString};
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::World;
use support::wait_for;

/// How long a test waits for what the server sends, in real time.
const WAIT: Duration = Duration::from_secs(20);

const CFG: &str = "driver ( name \"stage\" provides [ \"6665:position2d:0\" ] model \"r0\" )\n\
    driver ( name \"sentences\" provides [ \"6665:speech_recognition:0\" ] file \"heard.txt\" )\n\
    driver ( name \"festival\" provides [ \"6665:speech:0\" ] log \"said.txt\" wav \"said\" )\n";

#[test]
fn sentences_are_heard_in_turn_and_replies_are_logged() {
    let dir = tempfile::tempdir().unwrap();
    let robots_inc = support::worlds().join("robots.inc");
    let world = support::write(
        dir.path(),
        "talk.world",
        &format!(
            "include \"{}\"\ninterval_sim 100\nrover( name \"r0\" pose [ 0 0 0 0 ] )\n",
            robots_inc.display()
        ),
    );
    support::write(
        dir.path(),
        "heard.txt",
        "0.5 r0 go to dock\n1.5 all robots stop\n",
    );
    let cfg = support::write(dir.path(), "talk.cfg", CFG);
    let world = World::load(&world).unwrap();
    let devices = from_cfg(&cfg, &world, &mut Vec::new()).unwrap();
    let options = ServeOptions {
        speedup: 2.0,
        free_ports: true,
        ..ServeOptions::default()
    };
    let running = serve(Simulation::new(world), devices, options).unwrap();
    let port = running.port(6665).unwrap();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    let ears = client.addr(Interface::SPEECH_RECOGNITION, 0);
    let voice = client.addr(Interface::SPEECH, 0);
    assert_eq!(client.subscribe(ears).unwrap(), "sentences");
    assert_eq!(client.subscribe(voice).unwrap(), "festival");

    let subtype = SpeechRecognition::DATA_STRING.subtype();
    let text_of = |after: u64| {
        let s = client.latest(ears, subtype).filter(|s| s.seq > after)?;
        match &s.message.body {
            Body::SpeechRecognition(SpeechRecognition::Text(t)) => {
                Some((s.seq, s.server_time, t.text.as_str().to_string()))
            }
            other => panic!("not a sentence: {other:?}"),
        }
    };
    let (seq, first_at, first) = wait_for("the first sentence", WAIT, || text_of(0));
    assert_eq!(first, "r0 go to dock");
    assert!((0.5..1.5).contains(&first_at), "heard at {first_at}");
    let (_, second_at, second) = wait_for("the second sentence", WAIT, || text_of(seq));
    assert_eq!(second, "all robots stop");
    assert!(second_at >= 1.5, "heard at {second_at}");

    client.command(
        voice,
        Body::Speech(Speech::Say(SpeechCmd {
            string: PlayerString::new("r0: going to zone dock"),
        })),
    );
    let log = dir.path().join("said.txt");
    let said = wait_for("the reply logged", WAIT, || {
        std::fs::read_to_string(&log).ok()
    });
    assert_eq!(said, "r0: going to zone dock\n");

    // Spoken out loud too: espeak-ng (installed by scripts/setup.sh) wrote a whole WAV file.
    let wav = dir.path().join("said-1.wav");
    let bytes = wait_for("the spoken WAV file, complete", WAIT, || {
        let bytes = std::fs::read(&wav).ok()?;
        let riff = u32::from_le_bytes(bytes.get(4..8)?.try_into().ok()?) as usize;
        (riff + 8 == bytes.len()).then_some(bytes)
    });
    assert_eq!(&bytes[0..4], b"RIFF");
    assert_eq!(&bytes[8..12], b"WAVE");
    // 16-bit mono at 22 050 Hz: a sentence of a second or more is tens of kilobytes.
    assert!(bytes.len() > 20_000, "{} bytes", bytes.len());
}

#[test]
fn a_broken_sentences_file_is_refused_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let world = support::write(dir.path(), "w.world", "interval_sim 100\n");
    support::write(dir.path(), "heard.txt", "0.5 hello\nlater r0 stop\n");
    let cfg = support::write(
        dir.path(),
        "w.cfg",
        "driver ( name \"sentences\" provides [ \"speech_recognition:0\" ] file \"heard.txt\" )\n",
    );
    let world = World::load(&world).unwrap();
    let e = from_cfg(&cfg, &world, &mut Vec::new())
        .unwrap_err()
        .to_string();
    assert!(
        e.ends_with("heard.txt:2:1: \"later\" is not a number of seconds"),
        "{e}"
    );
    std::fs::remove_file(dir.path().join("heard.txt")).unwrap();
    let e = from_cfg(&cfg, &world, &mut Vec::new())
        .unwrap_err()
        .to_string();
    assert!(e.contains("heard.txt:1:1: cannot read"), "{e}");
}
