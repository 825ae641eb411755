//! A few threads that carry many robots' connections.
//!
//! By default a client runs its connection on a thread of its own, so that no robot ever
//! waits for another. That costs a thread wake-up per message burst: a thousand robots
//! publishing every 0.1 s wake a thousand threads ten times a second, and each wake-up
//! crosses threads (in a virtual machine, through the hypervisor). A program that opens
//! hundreds of robots — a viewer of a swarm — gives them one [`SharedIo`] instead
//! ([`super::ClientOptions::shared_io`]): each connection is then a task on its few threads,
//! which take the messages of every socket that is ready at each wake-up. Nothing a
//! connection does blocks (it reads, decodes and stores), so no robot holds up another.

use std::cell::Cell;
use std::fmt;
use std::future::Future;
use std::sync::Arc;

use tokio::runtime::{Builder, Handle, Runtime};

thread_local! {
    /// Set on the threads of every [`SharedIo`]: a client closed there must not wait for its
    /// own task, which may need this very thread to finish.
    static ON_SHARED_IO: Cell<bool> = const { Cell::new(false) };
}

/// Threads shared by many clients' connections; cheap to clone (clones share the threads).
/// The threads end when the last clone — and with it the last client using it — is gone.
#[derive(Clone)]
pub struct SharedIo {
    handle: Handle,
    _runtime: Arc<Owned>,
}

/// The runtime, shut down without blocking when the last clone goes: that may happen on one
/// of its own threads, or inside another runtime, where a blocking shutdown would panic.
struct Owned(Option<Runtime>);

impl Drop for Owned {
    fn drop(&mut self) {
        if let Some(runtime) = self.0.take() {
            runtime.shutdown_background();
        }
    }
}

impl SharedIo {
    /// Starts `threads` threads (at least one), named `player io`.
    pub fn new(threads: usize) -> std::io::Result<SharedIo> {
        let runtime = Builder::new_multi_thread()
            .worker_threads(threads.max(1))
            .thread_name("player io")
            .on_thread_start(|| ON_SHARED_IO.with(|on| on.set(true)))
            .enable_all()
            .build()?;
        Ok(SharedIo {
            handle: runtime.handle().clone(),
            _runtime: Arc::new(Owned(Some(runtime))),
        })
    }

    /// Runs `connection` on these threads.
    pub(super) fn spawn(&self, connection: impl Future<Output = ()> + Send + 'static) {
        self.handle.spawn(connection);
    }

    /// Whether the calling thread is one of any [`SharedIo`]'s threads.
    pub(super) fn on_its_threads() -> bool {
        ON_SHARED_IO.with(Cell::get)
    }
}

impl fmt::Debug for SharedIo {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let workers = self.handle.metrics().num_workers();
        write!(f, "SharedIo({workers} threads)")
    }
}
