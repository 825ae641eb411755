//! CPU time of a group of this process's threads, picked by name, from /proc/self/task.
//!
//! Per-thread accounting is what lets the server, the traffic generator and the client side
//! share one process and still be measured apart. `schedstat`'s first field (nanoseconds on
//! the CPU) is used where the kernel has it, utime + stime from `stat` (clock ticks of 1/100 s,
//! Linux's USER_HZ) otherwise.

use std::collections::HashMap;
use std::fs;

use crate::BenchError;

/// CPU seconds and context switches so far of each live thread whose name starts with a
/// prefix, by thread id. Switches count wake-ups: a thread that blocks and is woken per
/// message switches about once per message.
#[derive(Debug, Clone, Default)]
pub struct CpuSnapshot {
    seconds: HashMap<u32, f64>,
    switches: HashMap<u32, u64>,
}

impl CpuSnapshot {
    pub fn take(name_prefix: &str) -> Result<CpuSnapshot, BenchError> {
        let tasks = fs::read_dir("/proc/self/task")
            .map_err(|e| BenchError::Cpu(format!("/proc/self/task: {e}")))?;
        let mut seconds = HashMap::new();
        let mut switches = HashMap::new();
        for task in tasks.flatten() {
            let Some(tid) = task
                .file_name()
                .to_str()
                .and_then(|t| t.parse::<u32>().ok())
            else {
                continue;
            };
            // A thread may end between listing and reading: skip it.
            let Ok(comm) = fs::read_to_string(task.path().join("comm")) else {
                continue;
            };
            if !comm.trim_end_matches('\n').starts_with(name_prefix) {
                continue;
            }
            if let Some(s) = thread_seconds(&task.path()) {
                seconds.insert(tid, s);
            }
            if let Ok(status) = fs::read_to_string(task.path().join("status")) {
                switches.insert(tid, parse_switches(&status));
            }
        }
        Ok(CpuSnapshot { seconds, switches })
    }

    /// Adds another group's threads.
    pub fn absorb(&mut self, other: CpuSnapshot) {
        self.seconds.extend(other.seconds);
        self.switches.extend(other.switches);
    }

    /// Context switches (voluntary and not) between `earlier` and `self`.
    pub fn switches_since(&self, earlier: &CpuSnapshot) -> u64 {
        self.switches
            .iter()
            .map(|(tid, now)| now.saturating_sub(earlier.switches.get(tid).copied().unwrap_or(0)))
            .sum()
    }

    /// Threads matched.
    pub fn threads(&self) -> usize {
        self.seconds.len()
    }

    /// CPU seconds the matched threads used between `earlier` and `self` (threads that
    /// started in between count from zero).
    pub fn since(&self, earlier: &CpuSnapshot) -> f64 {
        self.seconds
            .iter()
            .map(|(tid, now)| now - earlier.seconds.get(tid).copied().unwrap_or(0.0))
            .sum()
    }
}

fn thread_seconds(task: &std::path::Path) -> Option<f64> {
    if let Ok(schedstat) = fs::read_to_string(task.join("schedstat"))
        && let Some(ns) = schedstat
            .split_whitespace()
            .next()
            .and_then(|f| f.parse::<u64>().ok())
    {
        return Some(ns as f64 * 1e-9);
    }
    let stat = fs::read_to_string(task.join("stat")).ok()?;
    parse_stat_ticks(&stat).map(|ticks| ticks as f64 / 100.0)
}

/// voluntary_ctxt_switches + nonvoluntary_ctxt_switches from a `status` file.
fn parse_switches(status: &str) -> u64 {
    status
        .lines()
        .filter(|l| l.contains("ctxt_switches:"))
        .filter_map(|l| l.split_whitespace().nth(1)?.parse::<u64>().ok())
        .sum()
}

/// utime + stime from a `stat` line; the command name may hold spaces and parentheses, so
/// fields are counted from the last ')'.
pub(crate) fn parse_stat_ticks(stat: &str) -> Option<u64> {
    let rest = &stat[stat.rfind(')')? + 1..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // After the name: state is field 3, utime field 14, stime field 15 (1-based, man proc).
    let utime = fields.get(11)?.parse::<u64>().ok()?;
    let stime = fields.get(12)?.parse::<u64>().ok()?;
    Some(utime + stime)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stat_ticks_are_read_after_a_name_with_spaces() {
        let line = "42 (player 127.0.0.) S 1 2 3 4 5 6 7 8 9 10 17 25 0 0 20 0";
        assert_eq!(parse_stat_ticks(line), Some(42));
        assert_eq!(parse_stat_ticks("garbage"), None);
    }

    #[test]
    fn switches_add_voluntary_and_involuntary() {
        let status = "Name:\tx\nvoluntary_ctxt_switches:\t7\nnonvoluntary_ctxt_switches:\t3\n";
        assert_eq!(parse_switches(status), 10);
    }

    #[test]
    fn a_busy_named_thread_is_measured_and_others_are_not() {
        let worker = std::thread::Builder::new()
            .name("cpu-test-spin".into())
            .spawn(|| {
                let start = std::time::Instant::now();
                let mut x = 0u64;
                while start.elapsed() < std::time::Duration::from_millis(200) {
                    x = std::hint::black_box(x.wrapping_add(1));
                }
                std::thread::sleep(std::time::Duration::from_millis(300));
            })
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(250));
        let snap = CpuSnapshot::take("cpu-test-spin").unwrap();
        assert_eq!(snap.threads(), 1);
        let used = snap.since(&CpuSnapshot::default());
        assert!(used > 0.0, "spinning thread used {used} s");
        assert_eq!(
            CpuSnapshot::take("no-such-thread-name").unwrap().threads(),
            0
        );
        worker.join().unwrap();
    }
}
