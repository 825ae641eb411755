//! Lockstep over real TCP: a step waits for the client driving the robot, and a deterministic
//! program gives the same recording, byte for byte, on an idle machine and a loaded one.

mod support;

use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions};
use player_proto::recording::Recorder;
use player_sim::serve::{LockstepOptions, Running, ServeOptions, serve};
use player_sim::served::{DEFAULT_PORT, default_devices};
use player_sim::sim::Simulation;
use player_sim::sim_record::SimRecording;
use player_sim::world::World;
use support::{wait_for, worlds};

fn serve_lockstep(patience: Duration, record: Option<SimRecording>) -> Running {
    let world = World::load(&worlds().join("simple.world")).unwrap();
    let devices = default_devices(&world, DEFAULT_PORT);
    let options = ServeOptions {
        speedup: 0.0,
        free_ports: true,
        lockstep: Some(LockstepOptions {
            patience: Some(patience),
        }),
        record,
        ..ServeOptions::default()
    };
    let mut sim = Simulation::new(world);
    sim.noise.seed = 3;
    sim.noise.range_sd = 0.01;
    serve(sim, devices, options).unwrap()
}

fn connect(running: &Running) -> Client {
    let port = running.port(DEFAULT_PORT).unwrap();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    client.position2d(0).subscribe().unwrap();
    client.laser(0).subscribe().unwrap();
    client
}

/// Waits until the position and the scan of simulated time `time` have both arrived.
fn data_of_time(client: &Client, time: f64) {
    let at = |t: f64| (t - time).abs() < 1e-6;
    wait_for(
        &format!("the data of t = {time}"),
        Duration::from_secs(20),
        || {
            let (_, pose) = client.position2d(0).state()?;
            let (_, scan) = client.laser(0).scan()?;
            (at(pose.server_time) && at(scan.server_time)).then_some(())
        },
    );
}

#[test]
fn each_step_waits_for_the_driving_clients_command() {
    let running = serve_lockstep(Duration::from_secs(60), None);
    let lockstep = running.lockstep.clone().unwrap();
    let client = connect(&running);
    let interval = running.sim.lock().unwrap().world.interval;
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(lockstep.steps(), 0, "nobody commanded: no step");
    for step in 1..=20u64 {
        client.position2d(0).set_velocity(0.3, 0.0, 0.1);
        data_of_time(&client, step as f64 * interval);
    }
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(
        lockstep.steps(),
        20,
        "one step per command, none while it thinks"
    );
    let time = running.sim.lock().unwrap().time;
    assert!((time - 20.0 * interval).abs() < 1e-9, "{time}");
}

#[test]
fn a_client_that_stops_answering_is_not_waited_for_past_the_patience() {
    let running = serve_lockstep(Duration::from_millis(200), None);
    let lockstep = running.lockstep.clone().unwrap();
    let client = connect(&running);
    client.position2d(0).set_velocity(0.1, 0.0, 0.0);
    wait_for(
        "steps without the silent driver",
        Duration::from_secs(20),
        || (lockstep.steps() > 50).then_some(()),
    );
}

/// A small deterministic program: forward, turning away when the scan ahead is short.
fn drive(running: &Running, steps: u64) {
    let client = connect(running);
    let interval = running.sim.lock().unwrap().world.interval;
    for step in 0..steps {
        // Step 0's data is what a lockstep simulation greets a new subscriber with.
        data_of_time(&client, step as f64 * interval);
        let ahead = client.laser(0).scan().map_or(f32::INFINITY, |(scan, _)| {
            let n = scan.ranges.len();
            scan.ranges[n / 3..2 * n / 3]
                .iter()
                .copied()
                .fold(f32::INFINITY, f32::min)
        });
        let (vx, va) = if ahead < 1.0 { (0.0, 0.8) } else { (0.5, 0.0) };
        client.position2d(0).set_velocity(vx, 0.0, va);
    }
    data_of_time(&client, steps as f64 * interval);
}

/// One run of the program, recorded by the simulation; the recording's bytes.
fn recorded_run(dir: &Path, name: &str) -> Vec<u8> {
    let path = dir.join(name);
    let recorder = Recorder::create(&path).unwrap();
    {
        let running = serve_lockstep(Duration::from_secs(60), Some(SimRecording::to(&recorder)));
        drive(&running, 120);
    }
    let stats = recorder.finish().unwrap();
    assert_eq!(stats.lost(), 0, "{stats:?}");
    std::fs::read(&path).unwrap()
}

/// Busy threads on every core until dropped.
struct Load(Arc<AtomicBool>, Vec<std::thread::JoinHandle<()>>);

impl Load {
    fn heavy() -> Load {
        let stop = Arc::new(AtomicBool::new(false));
        let threads = (0..4)
            .map(|_| {
                let stop = stop.clone();
                std::thread::spawn(move || {
                    let mut x = 1u64;
                    while !stop.load(Ordering::Relaxed) {
                        x = x.wrapping_mul(6364136223846793005).wrapping_add(1);
                        std::hint::black_box(x);
                    }
                })
            })
            .collect();
        Load(stop, threads)
    }
}

impl Drop for Load {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
        for t in self.1.drain(..) {
            let _ = t.join();
        }
    }
}

#[test]
fn a_program_gives_the_same_recording_idle_and_under_load() {
    let dir = tempfile::tempdir().unwrap();
    let idle = recorded_run(dir.path(), "idle.prec");
    let loaded = {
        let _load = Load::heavy();
        let started = Instant::now();
        let runs = [
            recorded_run(dir.path(), "loaded-1.prec"),
            recorded_run(dir.path(), "loaded-2.prec"),
        ];
        eprintln!("two runs under load: {:?}", started.elapsed());
        runs
    };
    assert!(idle.len() > 100_000, "a whole run: {} bytes", idle.len());
    for run in &loaded {
        assert_eq!(run.len(), idle.len(), "same length");
        assert!(run == &idle, "the same bytes");
    }
}
