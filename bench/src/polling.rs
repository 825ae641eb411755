//! Design (b), the paper's "obvious solution": ONE thread that polls every robot's connection
//! in turn — non-blocking read, then frame and decode with player-proto's own decoders, then
//! store as newest data — and sleeps briefly when a whole round found nothing.

use std::collections::HashMap;
use std::io::{ErrorKind, Read, Write};
use std::net::TcpStream;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use player_proto::client::ReplaceRule;
use player_proto::interfaces::player::{self, DeviceReq, Player};
use player_proto::message::{Body, Message};
use player_proto::wire::{DevAddr, FrameDecoder, Interface, MsgType, PlayerString};

use crate::BenchError;
use crate::clock::{BenchClock, SharedWindow};
use crate::recorder::Recorder;
use crate::traffic::DEVICES;

/// The polling thread's name, as /proc shows it.
pub const THREAD_NAME: &str = "bench-poller";

/// How long the handshake may take per robot.
const HANDSHAKE_TIMEOUT: Duration = Duration::from_secs(10);

/// One robot's connection and its newest-data store.
struct Connection {
    port: u16,
    stream: TcpStream,
    frames: FrameDecoder,
    newest: HashMap<(Interface, u16, u8), (Message, Instant)>,
}

/// The polling thread, running.
pub struct Poller {
    stop: Arc<AtomicBool>,
    thread: JoinHandle<Result<Recorder, BenchError>>,
}

impl Poller {
    /// Connects and subscribes to every robot (blocking, one after the other), then starts the
    /// single thread. `idle_sleep` is its pause after a round that read nothing.
    pub fn start(
        ports: &[u16],
        clock: BenchClock,
        window: &SharedWindow,
        idle_sleep: Duration,
    ) -> Result<Poller, BenchError> {
        let connections = ports
            .iter()
            .map(|&port| handshake(port))
            .collect::<Result<Vec<_>, _>>()?;
        let stop = Arc::new(AtomicBool::new(false));
        let recorder = Recorder::new(window.clone());
        let thread = {
            let stop = stop.clone();
            std::thread::Builder::new()
                .name(THREAD_NAME.into())
                .spawn(move || poll_all(connections, recorder, clock, &stop, idle_sleep))
                .map_err(|e| BenchError::Thread(e.to_string()))?
        };
        Ok(Poller { stop, thread })
    }

    /// Stops the thread, closes the connections, returns what it recorded.
    pub fn finish(self) -> Result<Recorder, BenchError> {
        self.stop.store(true, Ordering::SeqCst);
        self.thread
            .join()
            .map_err(|_| BenchError::Thread("the polling thread panicked".into()))?
    }
}

/// Round-robin over all connections until stopped.
fn poll_all(
    mut connections: Vec<Connection>,
    mut recorder: Recorder,
    clock: BenchClock,
    stop: &AtomicBool,
    idle_sleep: Duration,
) -> Result<Recorder, BenchError> {
    let mut scratch = vec![0u8; 64 * 1024];
    while !stop.load(Ordering::Relaxed) {
        let mut read_any = false;
        for connection in &mut connections {
            loop {
                match connection.stream.read(&mut scratch) {
                    Ok(0) => {
                        return Err(BenchError::Protocol(format!(
                            "robot on port {} closed the connection",
                            connection.port
                        )));
                    }
                    Ok(n) => {
                        read_any = true;
                        connection.frames.extend(&scratch[..n]);
                        if n < scratch.len() {
                            break;
                        }
                    }
                    Err(e) if e.kind() == ErrorKind::WouldBlock => break,
                    Err(e) if e.kind() == ErrorKind::Interrupted => continue,
                    Err(e) => {
                        return Err(BenchError::Protocol(format!(
                            "reading robot on port {}: {e}",
                            connection.port
                        )));
                    }
                }
            }
            connection.store_frames(&mut recorder, clock)?;
        }
        if !read_any && !idle_sleep.is_zero() {
            std::thread::sleep(idle_sleep);
        }
    }
    Ok(recorder)
}

impl Connection {
    /// Decodes every whole frame buffered and stores DATA as newest per device and subtype.
    fn store_frames(
        &mut self,
        recorder: &mut Recorder,
        clock: BenchClock,
    ) -> Result<(), BenchError> {
        while let Some(frame) = self
            .frames
            .next_frame()
            .map_err(|e| BenchError::Protocol(format!("robot on port {}: {e}", self.port)))?
        {
            if frame.header.msg_type != MsgType::Data {
                continue;
            }
            let message = Message::decode(frame.header, frame.body)
                .map_err(|e| BenchError::Protocol(format!("robot on port {}: {e}", self.port)))?;
            let h = message.header;
            let received = Instant::now();
            recorder.record(h.timestamp, clock.at(received));
            self.newest.insert(
                (h.addr.interf, h.addr.index, h.subtype),
                (message, received),
            );
        }
        Ok(())
    }
}

/// Banner, the newest-data replace rule (as our client asks by default), and a subscription
/// to each device; then the socket goes non-blocking.
fn handshake(port: u16) -> Result<Connection, BenchError> {
    let fail = |what: String| BenchError::Connect(format!("robot on port {port}: {what}"));
    let mut stream =
        TcpStream::connect(("127.0.0.1", port)).map_err(|e| fail(format!("connect: {e}")))?;
    stream.set_nodelay(true).map_err(|e| fail(e.to_string()))?;
    stream
        .set_read_timeout(Some(HANDSHAKE_TIMEOUT))
        .map_err(|e| fail(e.to_string()))?;
    let mut frames = FrameDecoder::default();
    let mut scratch = vec![0u8; 64 * 1024];
    let mut read_some =
        |stream: &mut TcpStream, frames: &mut FrameDecoder| match stream.read(&mut scratch) {
            Ok(0) => Err(fail("closed during the handshake".into())),
            Ok(n) => {
                frames.extend(&scratch[..n]);
                Ok(())
            }
            Err(e) => Err(fail(format!("handshake read: {e}"))),
        };
    loop {
        match frames.take_banner() {
            Some(Ok(_)) => break,
            Some(Err(e)) => return Err(fail(format!("bad banner: {e}"))),
            None => read_some(&mut stream, &mut frames)?,
        }
    }
    let to_player = DevAddr {
        robot: u32::from(port),
        ..DevAddr::local(Interface::PLAYER, 0)
    };
    let mut requests = vec![Message::new(
        to_player,
        MsgType::Req,
        player::REQ_ADD_REPLACE_RULE,
        Body::Player(Player::AddReplaceRule(
            ReplaceRule::newest_data().to_request(),
        )),
    )];
    for interf in DEVICES {
        let open = DeviceReq {
            addr: DevAddr::local(interf, 0),
            access: player::OPEN_MODE,
            driver_name: PlayerString::default(),
        };
        requests.push(Message::new(
            to_player,
            MsgType::Req,
            player::REQ_DEV,
            Body::Player(Player::Device(open)),
        ));
    }
    for request in &requests {
        stream
            .write_all(&request.to_bytes())
            .map_err(|e| fail(format!("handshake write: {e}")))?;
    }
    let mut acks = 0;
    while acks < requests.len() {
        match frames.next_frame().map_err(|e| fail(e.to_string()))? {
            Some(frame) if frame.header.msg_type == MsgType::Ack => acks += 1,
            Some(frame) if frame.header.msg_type == MsgType::Nack => {
                return Err(fail(format!("request refused: {}", frame.header)));
            }
            Some(_) => {}
            None => read_some(&mut stream, &mut frames)?,
        }
    }
    stream
        .set_nonblocking(true)
        .map_err(|e| fail(e.to_string()))?;
    Ok(Connection {
        port,
        stream,
        frames,
        newest: HashMap::new(),
    })
}
