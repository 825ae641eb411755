//! The results as a Markdown table, and the ratios of ours to the single-thread baseline.

use std::fmt::Write;

use crate::run::{Design, Measurement};

fn ms(seconds: Option<f64>) -> String {
    seconds.map_or("–".into(), |s| format!("{:.2}", s * 1e3))
}

/// One row per N and design.
pub fn table(results: &[Measurement]) -> String {
    let mut out = String::from(
        "| N | design | published/s | handled msg/s | lost | client CPU (cores) | client ctx switches/s | server+generator CPU | p50 ms | p99 ms | max ms |\n\
         |---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for m in results {
        let _ = writeln!(
            out,
            "| {} | {} | {:.0} | {:.0} | {} ({:.1}%) | {:.3} | {:.0} | {:.3} | {} | {} | {} |",
            m.robots,
            m.design.label(),
            m.published as f64 / m.window_s,
            m.handled_per_s(),
            m.lost(),
            100.0 * m.lost() as f64 / (m.published.max(1)) as f64,
            m.client_cpu,
            m.client_switches_per_s,
            m.server_cpu,
            ms(m.latency.map(|l| l.p50)),
            ms(m.latency.map(|l| l.p99)),
            ms(m.latency.map(|l| l.max)),
        );
    }
    out
}

/// Ours ÷ baseline per N, for CPU and p99 (below 1 = ours better).
pub fn ratios(results: &[Measurement]) -> String {
    let mut out = String::from(
        "| N | CPU ours/baseline | p99 ours/baseline | handled ours/baseline |\n|---:|---:|---:|---:|\n",
    );
    let mut ns: Vec<usize> = results.iter().map(|m| m.robots).collect();
    ns.dedup();
    for n in ns {
        let find = |d: Design| results.iter().find(|m| m.robots == n && m.design == d);
        let (Some(ours), Some(base)) = (find(Design::ThreadPerRobot), find(Design::SinglePoller))
        else {
            continue;
        };
        let ratio = |a: f64, b: f64| {
            if b > 0.0 {
                format!("{:.2}", a / b)
            } else {
                "–".into()
            }
        };
        let p99 = |m: &Measurement| m.latency.map_or(0.0, |l| l.p99);
        let _ = writeln!(
            out,
            "| {n} | {} | {} | {} |",
            ratio(ours.client_cpu, base.client_cpu),
            ratio(p99(ours), p99(base)),
            ratio(ours.handled_per_s(), base.handled_per_s()),
        );
    }
    out
}
