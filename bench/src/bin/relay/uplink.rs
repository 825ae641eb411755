//! The robot site's uplink, counted: a TCP forwarder between the site's Zenoh session and the
//! router, adding up the bytes each way. Whatever Zenoh does (framing, batching, its own
//! keep-alives), this is what would cross the site's link to the world.

use std::io::{Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use anyhow::Result;

/// A running forwarder; its threads end with the process.
pub struct Uplink {
    port: u16,
    /// Bytes from the site to the router.
    up: Arc<AtomicU64>,
}

impl Uplink {
    /// Forwards every connection made to [`Uplink::port`] to `target` on loopback.
    pub fn start(target: u16) -> Result<Uplink> {
        let listener = TcpListener::bind("127.0.0.1:0")?;
        let port = listener.local_addr()?.port();
        let up = Arc::new(AtomicU64::new(0));
        let counted = up.clone();
        std::thread::Builder::new()
            .name("uplink".into())
            .spawn(move || {
                for site in listener.incoming().flatten() {
                    let Ok(router) = TcpStream::connect(("127.0.0.1", target)) else {
                        continue;
                    };
                    let _ = site.set_nodelay(true);
                    let _ = router.set_nodelay(true);
                    if let (Ok(site2), Ok(router2)) = (site.try_clone(), router.try_clone()) {
                        forward(site, router, Some(counted.clone()));
                        forward(router2, site2, None);
                    }
                }
            })?;
        Ok(Uplink { port, up })
    }

    pub fn port(&self) -> u16 {
        self.port
    }

    /// Bytes sent from the site to the router so far.
    pub fn bytes_up(&self) -> u64 {
        self.up.load(Ordering::Relaxed)
    }
}

fn forward(mut from: TcpStream, mut to: TcpStream, count: Option<Arc<AtomicU64>>) {
    let _ = std::thread::Builder::new()
        .name("uplink-copy".into())
        .spawn(move || {
            let mut buffer = vec![0u8; 64 * 1024];
            while let Ok(n) = from.read(&mut buffer) {
                if n == 0 || to.write_all(&buffer[..n]).is_err() {
                    break;
                }
                if let Some(count) = &count {
                    count.fetch_add(n as u64, Ordering::Relaxed);
                }
            }
            let _ = to.shutdown(Shutdown::Write);
        });
}
