//! A Player server that hangs — its socket stays open but nothing comes out of it, as with a
//! stopped process or a dead link — shows as such in the viewer within seconds, and comes
//! back by itself when the server recovers: nobody looks at a frozen robot believing it live.

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use player_proto::client::ConnectionState;
use tests::{load, run_until, serve, viewer_for};

/// Forwards TCP between the viewer and the server until frozen; frozen, it forwards nothing
/// either way (connections stay open), as a hung server looks from outside.
struct FreezableProxy {
    port: u16,
    frozen: Arc<AtomicBool>,
}

impl FreezableProxy {
    fn start(server_port: u16) -> FreezableProxy {
        let listener = TcpListener::bind("127.0.0.1:0").expect("proxy port");
        let port = listener.local_addr().unwrap().port();
        let frozen = Arc::new(AtomicBool::new(false));
        let flag = frozen.clone();
        std::thread::spawn(move || {
            for client in listener.incoming().flatten() {
                let Ok(server) = TcpStream::connect(("127.0.0.1", server_port)) else {
                    continue;
                };
                for (from, to) in [
                    (client.try_clone().unwrap(), server.try_clone().unwrap()),
                    (server, client),
                ] {
                    let flag = flag.clone();
                    std::thread::spawn(move || pump(from, to, &flag));
                }
            }
        });
        FreezableProxy { port, frozen }
    }
}

fn pump(mut from: TcpStream, mut to: TcpStream, frozen: &AtomicBool) {
    let mut buffer = [0u8; 16 * 1024];
    loop {
        while frozen.load(Ordering::Relaxed) {
            std::thread::sleep(Duration::from_millis(10));
        }
        match from.read(&mut buffer) {
            Ok(0) | Err(_) => return,
            Ok(n) => {
                while frozen.load(Ordering::Relaxed) {
                    std::thread::sleep(Duration::from_millis(10));
                }
                if to.write_all(&buffer[..n]).is_err() {
                    return;
                }
            }
        }
    }
}

fn state(viewer: &pv3d::app::Viewer) -> ConnectionState {
    let robots = viewer.robots.as_ref().expect("robots");
    let (_, _, client) = robots.clients().next().expect("one server");
    client.state()
}

#[test]
fn a_hung_server_is_noticed_and_its_return_too() {
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    let _running = serve("stage-worlds/simple.world", &mut composition, 1.0);
    let proxy = FreezableProxy::start(composition.clients[0].port);
    composition.clients[0].port = proxy.port;
    let mut viewer = viewer_for(&composition);
    assert_eq!(state(&viewer), ConnectionState::Connected);

    proxy.frozen.store(true, Ordering::Relaxed);
    run_until(
        &mut viewer,
        "the viewer to notice the hung server",
        Duration::from_secs(20),
        |v| state(v) != ConnectionState::Connected,
    );
    proxy.frozen.store(false, Ordering::Relaxed);
    run_until(
        &mut viewer,
        "the connection to come back",
        Duration::from_secs(30),
        |v| state(v) == ConnectionState::Connected,
    );
}
