//! Many clients in one process, as lightweight async tasks rather than threads: a thousand
//! threads on two cores would measure the scheduler, not the servers. Each member connects,
//! says when it is ready, then records the latency of what it receives inside the shared
//! window until told to stop. The crowds built on it (Player observers, web pages, Foxglove
//! clients: the `observers`, `pages` and `foxglove_clients` modules) know this one; this one
//! knows none of them.

use std::future::Future;
use std::time::{Duration, Instant};

use tokio::sync::{mpsc, watch};
use tokio::task::JoinHandle;

use crate::BenchError;
use crate::clock::SharedWindow;

/// Threads the crowd's runtime runs on.
const CROWD_THREADS: usize = 2;

/// What one member saw inside the window: seconds from send to receipt, or why it failed.
pub type Seen = Result<Vec<f64>, String>;

/// What a member is given: its number, the window, a stop signal and a ready signal.
pub struct Member {
    pub index: usize,
    pub window: SharedWindow,
    pub stop: watch::Receiver<bool>,
    pub ready: mpsc::Sender<()>,
}

/// A crowd of clients; stop them with [`Crowd::finish`].
pub struct Crowd {
    runtime: tokio::runtime::Runtime,
    stop: watch::Sender<bool>,
    tasks: Vec<JoinHandle<Seen>>,
}

/// What the crowd saw.
#[derive(Debug, Clone, Default)]
pub struct CrowdReport {
    /// Seconds from send to receipt, every message sent inside the window.
    pub latencies: Vec<f64>,
    /// Members that lost their connection or never became ready.
    pub failed: usize,
}

impl Crowd {
    /// Starts `count` members made by `member` and waits (at most `timeout`) until every one
    /// is ready; `what` names them in errors.
    pub fn start<F, Fut>(
        what: &str,
        count: usize,
        window: SharedWindow,
        timeout: Duration,
        member: F,
    ) -> Result<Crowd, BenchError>
    where
        F: Fn(Member) -> Fut,
        Fut: Future<Output = Seen> + Send + 'static,
    {
        if count == 0 {
            return Err(BenchError::Config(format!("no {what}")));
        }
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(CROWD_THREADS)
            .thread_name("bench-crowd")
            .enable_all()
            .build()
            .map_err(|e| BenchError::Thread(e.to_string()))?;
        let (stop, stopped) = watch::channel(false);
        let (ready, mut readies) = mpsc::channel(count);
        let tasks = (0..count)
            .map(|index| {
                runtime.spawn(member(Member {
                    index,
                    window: window.clone(),
                    stop: stopped.clone(),
                    ready: ready.clone(),
                }))
            })
            .collect();
        let deadline = Instant::now() + timeout;
        let started = runtime.block_on(async {
            let mut n = 0;
            while n < count {
                let left = deadline.saturating_duration_since(Instant::now());
                match tokio::time::timeout(left, readies.recv()).await {
                    Ok(Some(())) => n += 1,
                    _ => break,
                }
            }
            n
        });
        let crowd = Crowd {
            runtime,
            stop,
            tasks,
        };
        if started < count {
            let report = crowd.finish();
            return Err(BenchError::Connect(format!(
                "{started} of {count} {what} ready within {timeout:?} ({} failed)",
                report.failed
            )));
        }
        Ok(crowd)
    }

    /// Every member goes at once, mid-stream, as when a viewer's process dies.
    pub fn vanish(self) {
        self.runtime.shutdown_background();
    }

    /// Stops every member and gathers what they saw.
    pub fn finish(self) -> CrowdReport {
        let _ = self.stop.send(true);
        let mut report = CrowdReport::default();
        let outcomes = self.runtime.block_on(async {
            let mut outcomes = Vec::with_capacity(self.tasks.len());
            for task in self.tasks {
                outcomes.push(task.await);
            }
            outcomes
        });
        for outcome in outcomes {
            match outcome {
                Ok(Ok(latencies)) => report.latencies.extend(latencies),
                Ok(Err(why)) => {
                    tracing::warn!("a crowd member failed: {why}");
                    report.failed += 1;
                }
                Err(_) => report.failed += 1,
            }
        }
        report
    }
}
