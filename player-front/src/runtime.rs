//! Where a front's tasks run: a runtime of its own, or one it was handed.
//!
//! The relay runs three or four fronts, and pv3d and the Python package embed them: a runtime
//! (and its worker threads) per front is waste where the program already has one. A front
//! starts on a [`FrontRuntime`], which either owns its runtime ([`FrontRuntime::own`], shut
//! down with the front, as before) or runs on a handed [`Handle`] ([`FrontRuntime::on`]),
//! which outlives the front. On a handed runtime nothing shuts the front's tasks down for it,
//! so they are tracked: stopping or dropping the front aborts every task it spawned (its
//! listener is closed with its accept loop), and tasks it could not spawn itself (a viewer's
//! session, spawned by the WebSocket upgrade) end on [`FrontRuntime::stopping`].

use std::future::Future;
use std::sync::Mutex;

use tokio::runtime::{Handle, Runtime};
use tokio::sync::watch;
use tokio::task::AbortHandle;

/// A front's runtime: owned, or a handed one's handle; its spawned tasks tracked.
pub struct FrontRuntime {
    handle: Handle,
    owned: Option<Runtime>,
    tasks: Mutex<Vec<AbortHandle>>,
    stop: watch::Sender<bool>,
}

impl FrontRuntime {
    /// A multi-threaded runtime of the front's own with `workers` threads named `name`; shut
    /// down when the front is dropped.
    pub fn own(name: &str, workers: usize) -> std::io::Result<FrontRuntime> {
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(workers.max(1))
            .thread_name(name)
            .enable_all()
            .build()?;
        let mut front = FrontRuntime::on(runtime.handle().clone());
        front.owned = Some(runtime);
        Ok(front)
    }

    /// The front runs on `handle`'s runtime (which must have IO and time enabled), and leaves
    /// it running when stopped.
    pub fn on(handle: Handle) -> FrontRuntime {
        FrontRuntime {
            handle,
            owned: None,
            tasks: Mutex::new(Vec::new()),
            stop: watch::channel(false).0,
        }
    }

    /// Whether the runtime is the front's own.
    pub fn is_owned(&self) -> bool {
        self.owned.is_some()
    }

    pub fn handle(&self) -> &Handle {
        &self.handle
    }

    /// Runs `task` until it ends or the front stops.
    pub fn spawn<F>(&self, task: F)
    where
        F: Future<Output = ()> + Send + 'static,
    {
        let handle = self.handle.spawn(task).abort_handle();
        let mut tasks = self.tasks.lock().unwrap_or_else(|e| e.into_inner());
        tasks.retain(|t| !t.is_finished());
        tasks.push(handle);
    }

    /// Tasks spawned and not finished yet.
    pub fn tasks(&self) -> usize {
        let mut tasks = self.tasks.lock().unwrap_or_else(|e| e.into_inner());
        tasks.retain(|t| !t.is_finished());
        tasks.len()
    }

    /// Resolves once the front stops: for the tasks it does not spawn itself.
    pub fn stopping(&self) -> Stopping {
        Stopping(self.stop.subscribe())
    }

    /// Stops the front's tasks: those spawned are aborted, the others told through
    /// [`FrontRuntime::stopping`]. The runtime itself runs on until dropped (if owned).
    pub fn stop(&self) {
        self.stop.send_replace(true);
        let tasks = std::mem::take(&mut *self.tasks.lock().unwrap_or_else(|e| e.into_inner()));
        for task in tasks {
            task.abort();
        }
    }
}

/// A runtime for a program's fronts to share (`start_on` each with its handle): a few
/// workers, since the conversions run on the robots' threads and the workers only move bytes
/// to the viewers' sockets; its threads named `fronts`, as `top -H` shows them.
pub fn shared_runtime() -> std::io::Result<Runtime> {
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get().clamp(2, 4));
    tokio::runtime::Builder::new_multi_thread()
        .worker_threads(workers)
        .thread_name("fronts")
        .enable_all()
        .build()
}

impl Drop for FrontRuntime {
    fn drop(&mut self) {
        self.stop();
        if let Some(runtime) = self.owned.take() {
            runtime.shutdown_background();
        }
    }
}

impl std::fmt::Debug for FrontRuntime {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FrontRuntime")
            .field("owned", &self.is_owned())
            .field("tasks", &self.tasks())
            .finish()
    }
}

/// The front's stop, for a task to end on; cheap to clone.
#[derive(Debug, Clone)]
pub struct Stopping(watch::Receiver<bool>);

impl Stopping {
    /// Resolves once the front stops (at once if it has).
    pub async fn wait(&mut self) {
        // An error is the front gone altogether: stopped too.
        let _ = self.0.wait_for(|stopped| *stopped).await;
    }

    pub fn is_stopped(&self) -> bool {
        *self.0.borrow()
    }
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use super::*;

    fn handed() -> Runtime {
        tokio::runtime::Builder::new_multi_thread()
            .worker_threads(1)
            .enable_all()
            .build()
            .unwrap()
    }

    /// Sends when dropped: tells the test that a task's future is gone.
    struct Gone(Option<std::sync::mpsc::Sender<()>>);

    impl Drop for Gone {
        fn drop(&mut self) {
            let _ = self.0.take().map(|s| s.send(()));
        }
    }

    #[test]
    fn stopping_a_front_on_a_handed_runtime_ends_its_tasks_and_not_the_runtime() {
        let handed = handed();
        let front = FrontRuntime::on(handed.handle().clone());
        assert!(!front.is_owned());
        let (gone, went) = std::sync::mpsc::channel();
        // Made outside the task: aborted before its first poll, the task still drops it.
        let gone = Gone(Some(gone));
        front.spawn(async move {
            let _gone = gone;
            std::future::pending::<()>().await;
        });
        let mut stopping = front.stopping();
        let (told, heard) = std::sync::mpsc::channel();
        // A task the front did not spawn, ending on its stop.
        handed.spawn(async move {
            stopping.wait().await;
            let _ = told.send(());
        });
        assert_eq!(front.tasks(), 1);
        drop(front);
        went.recv_timeout(Duration::from_secs(5))
            .expect("the spawned task is aborted");
        heard
            .recv_timeout(Duration::from_secs(5))
            .expect("the other task heard the stop");
        // The handed runtime runs on.
        assert_eq!(handed.block_on(async { 7 }), 7);
        let (ran, done) = std::sync::mpsc::channel();
        handed.spawn(async move { ran.send(()).unwrap() });
        done.recv_timeout(Duration::from_secs(5)).unwrap();
    }

    #[test]
    fn an_owned_runtime_is_shut_down_with_the_front() {
        let front = FrontRuntime::own("front-test", 1).unwrap();
        assert!(front.is_owned());
        let (gone, went) = std::sync::mpsc::channel();
        let gone = Gone(Some(gone));
        front.spawn(async move {
            let _gone = gone;
            tokio::time::sleep(Duration::from_secs(3600)).await;
        });
        drop(front);
        went.recv_timeout(Duration::from_secs(5)).unwrap();
    }
}
