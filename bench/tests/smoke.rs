//! The measurement end to end at N = 3 for about a second: both designs receive data over real
//! TCP and every figure is finite. No timing assertions: this machine is shared and noisy.

use std::time::Duration;

use bench::{Design, PointConfig, TrafficConfig, run_point};

#[test]
fn both_designs_receive_data_at_three_robots() {
    let config = PointConfig {
        traffic: TrafficConfig {
            robots: 3,
            beams: 361,
            rate_hz: 10.0,
        },
        designs: vec![Design::ThreadPerRobot, Design::SinglePoller],
        warmup: Duration::from_millis(200),
        window: Duration::from_millis(1000),
        drain: Duration::from_millis(300),
        idle_sleep: Duration::from_millis(1),
    };
    let results = run_point(&config).expect("the point runs");
    assert_eq!(results.len(), 2);
    for (m, design) in results.iter().zip(&config.designs) {
        assert_eq!(m.design, *design);
        assert_eq!(m.robots, 3);
        assert!(m.published > 0, "{m:?}: nothing published in the window");
        assert!(m.stored > 0, "{m:?}: nothing stored");
        assert!(m.stored <= m.published, "{m:?}: stored more than was sent");
        let latency = m.latency.expect("latencies were sampled");
        for v in [latency.p50, latency.p99, latency.max] {
            assert!(v.is_finite() && v >= 0.0, "{m:?}: latency {v}");
        }
        assert!(latency.p50 <= latency.p99 && latency.p99 <= latency.max);
        assert!(m.client_cpu.is_finite() && m.client_cpu >= 0.0, "{m:?}");
        assert!(m.client_threads >= 1, "{m:?}: no client thread measured");
    }
    assert_eq!(results[0].client_threads, 3, "one thread per robot");
    assert_eq!(results[1].client_threads, 1, "one polling thread");
}
