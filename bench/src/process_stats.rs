//! What another process costs, from /proc: CPU time, resident memory, open TCP connections.
//! The relay benchmark runs the robots and the relay as child processes, so that each one's
//! cost is its own and not mixed with the observers'.

use std::fs;

use crate::BenchError;
use crate::cpu::parse_stat_ticks;

/// Linux's USER_HZ: the unit of utime and stime in /proc/PID/stat.
const TICKS_PER_SECOND: f64 = 100.0;

/// One look at a process.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ProcessSample {
    /// User + system CPU seconds since the process started (all its threads, dead ones too).
    pub cpu_seconds: f64,
    pub rss_bytes: u64,
    /// Open sockets (listening ones included).
    pub sockets: usize,
}

impl ProcessSample {
    pub fn take(pid: u32) -> Result<ProcessSample, BenchError> {
        let read = |file: &str| {
            fs::read_to_string(format!("/proc/{pid}/{file}"))
                .map_err(|e| BenchError::Cpu(format!("/proc/{pid}/{file}: {e}")))
        };
        let ticks = parse_stat_ticks(&read("stat")?)
            .ok_or_else(|| BenchError::Cpu(format!("/proc/{pid}/stat: no utime/stime")))?;
        let rss_bytes = parse_rss_bytes(&read("status")?)
            .ok_or_else(|| BenchError::Cpu(format!("/proc/{pid}/status: no VmRSS")))?;
        let sockets = fs::read_dir(format!("/proc/{pid}/fd"))
            .map_err(|e| BenchError::Cpu(format!("/proc/{pid}/fd: {e}")))?
            .flatten()
            .filter(|fd| {
                fs::read_link(fd.path())
                    .is_ok_and(|target| target.to_string_lossy().starts_with("socket:"))
            })
            .count();
        Ok(ProcessSample {
            cpu_seconds: ticks as f64 / TICKS_PER_SECOND,
            rss_bytes,
            sockets,
        })
    }
}

/// VmRSS from a `status` file, in bytes.
fn parse_rss_bytes(status: &str) -> Option<u64> {
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rss_is_read_in_bytes() {
        let status = "Name:\tx\nVmRSS:\t    2048 kB\nThreads:\t3\n";
        assert_eq!(parse_rss_bytes(status), Some(2 * 1024 * 1024));
        assert_eq!(parse_rss_bytes("Name:\tx\n"), None);
    }

    #[test]
    fn this_process_can_be_sampled() {
        let me = ProcessSample::take(std::process::id()).unwrap();
        assert!(me.rss_bytes > 0);
    }
}
