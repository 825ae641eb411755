//! The scale sweep: `cargo run --release -p bench --bin scale -- --out bench/results`
//! (add `--lidar` for 1081 beams at 40 Hz). Prints the table and writes it, with a PNG plot,
//! into the output folder.

use std::path::PathBuf;
use std::time::Duration;

use anyhow::Context;
use bench::{Design, PointConfig, TrafficConfig, plot, report, run_point};
use clap::Parser;

#[derive(Parser)]
#[command(about = "One client thread per robot vs one polling thread, N robots")]
struct Args {
    /// Robot counts to measure.
    #[arg(long, value_delimiter = ',', default_values_t = [3usize, 16, 64, 256])]
    robots: Vec<usize>,
    /// Laser beams per scan.
    #[arg(long, default_value_t = 361)]
    beams: usize,
    /// Messages per second per device.
    #[arg(long, default_value_t = 10.0)]
    rate_hz: f64,
    /// A modern lidar: 1081 beams at 40 Hz (overrides --beams and --rate-hz).
    #[arg(long)]
    lidar: bool,
    /// Measurement window per point and design, seconds.
    #[arg(long, default_value_t = 5.0)]
    seconds: f64,
    /// Receiving before the window opens, seconds.
    #[arg(long, default_value_t = 1.0)]
    warmup: f64,
    /// The single poller's pause after a round that read nothing, microseconds.
    #[arg(long, default_value_t = 1000)]
    idle_sleep_us: u64,
    /// Which designs, in this order.
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Design::ThreadPerRobot, Design::SinglePoller])]
    designs: Vec<Design>,
    /// Folder for scale-<beams>x<rate>.md and .png; nothing is written without it.
    #[arg(long)]
    out: Option<PathBuf>,
}

fn main() -> anyhow::Result<()> {
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| "error,bench=info".into()),
        )
        .with_writer(std::io::stderr)
        .init();
    let args = Args::parse();
    let (beams, rate_hz) = if args.lidar {
        (1081, 40.0)
    } else {
        (args.beams, args.rate_hz)
    };
    anyhow::ensure!(
        args.seconds > 0.0 && args.warmup >= 0.0,
        "--seconds must be positive and --warmup not negative"
    );
    let window = Duration::try_from_secs_f64(args.seconds).context("--seconds")?;
    let warmup = Duration::try_from_secs_f64(args.warmup).context("--warmup")?;
    let mut results = Vec::new();
    for &robots in &args.robots {
        let config = PointConfig {
            traffic: TrafficConfig {
                robots,
                beams,
                rate_hz,
            },
            designs: args.designs.clone(),
            warmup,
            window,
            drain: Duration::from_millis(500),
            idle_sleep: Duration::from_micros(args.idle_sleep_us),
        };
        let point = run_point(&config).with_context(|| format!("{robots} robots"))?;
        for m in &point {
            eprintln!(
                "{}",
                report::table(std::slice::from_ref(m))
                    .lines()
                    .last()
                    .unwrap_or("")
            );
        }
        results.extend(point);
    }
    let title = format!("{beams}-beam laser + position2d at {rate_hz} Hz per robot");
    let text = format!(
        "{title}; {} s window per point\n\n{}\n{}",
        args.seconds,
        report::table(&results),
        report::ratios(&results)
    );
    println!("{text}");
    if let Some(out) = args.out {
        std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
        let stem = format!("scale-{beams}x{rate_hz}");
        let md = out.join(format!("{stem}.md"));
        std::fs::write(&md, &text).with_context(|| format!("writing {}", md.display()))?;
        plot::draw(&out.join(format!("{stem}.png")), &title, &results)?;
        eprintln!("wrote {} and {stem}.png", md.display());
    }
    Ok(())
}
