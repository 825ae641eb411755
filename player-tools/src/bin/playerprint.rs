//! `playerprint` — subscribe to Player devices and print their data as it arrives, like
//! Player's own playerprint. `playerprint --list` prints the device list with driver names.

use std::collections::HashMap;
use std::io::Write;
use std::process::ExitCode;
use std::sync::Arc;
use std::sync::mpsc::{RecvTimeoutError, sync_channel};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use clap::Parser;
use player_proto::client::{Client, ClientOptions, DataMode};
use player_proto::interfaces::kind::MessageKind;
use player_proto::summary::summarize;
use player_proto::wire::{DevAddr, Interface};

/// Print the data of Player devices as it arrives.
#[derive(Parser, Debug)]
#[command(version, disable_help_flag = true)]
struct Cli {
    /// Devices to print, e.g. `laser:0 position2d:1`.
    devices: Vec<String>,

    /// The Player server's host.
    #[arg(short = 'h', long, default_value = "localhost")]
    host: String,

    /// The Player server's port.
    #[arg(short, long, default_value_t = 6665)]
    port: u16,

    /// Ask for data (PULL mode) instead of having it pushed.
    #[arg(long)]
    pull: bool,

    /// Print the device list with driver names, then exit.
    #[arg(short, long)]
    list: bool,

    /// Stop after this many messages.
    #[arg(short = 'n', long)]
    count: Option<u64>,

    /// Stop after this many seconds.
    #[arg(short = 't', long)]
    seconds: Option<f64>,

    /// Print help.
    #[arg(long, action = clap::ArgAction::Help)]
    help: Option<bool>,
}

fn main() -> ExitCode {
    program_edge::logging::init("warn");
    program_edge::exit::exit_code("playerprint", run(Cli::parse()))
}

fn run(cli: Cli) -> Result<()> {
    let (wake, woken) = sync_channel::<()>(1);
    let options = ClientOptions {
        data_mode: if cli.pull {
            DataMode::Pull
        } else {
            DataMode::Push
        },
        notifier: Some(Arc::new(move || {
            let _ = wake.try_send(());
        })),
        ..ClientOptions::default()
    };
    let client = Client::connect(&cli.host, cli.port, options)?;
    if let Some(banner) = client.banner() {
        eprintln!("connected to {}:{} ({banner})", cli.host, cli.port);
    }
    let mut out = std::io::stdout().lock();
    if cli.list {
        for device in client.devices() {
            writeln!(
                out,
                "{:<16} {}",
                format!("{}:{}", device.addr.interf, device.addr.index),
                device.driver
            )?;
        }
        return Ok(());
    }
    if cli.devices.is_empty() {
        bail!("name at least one device, e.g. `playerprint laser:0`, or use --list");
    }
    let mut devices = Vec::new();
    for text in &cli.devices {
        let addr: DevAddr = text.parse().with_context(|| format!("device {text:?}"))?;
        let driver = client
            .subscribe(addr)
            .with_context(|| format!("subscribing to {text}"))?;
        eprintln!("subscribed {}:{} ({driver})", addr.interf, addr.index);
        devices.push(addr);
    }

    let deadline = cli
        .seconds
        .map(|s| Instant::now() + Duration::from_secs_f64(s));
    let mut printed = 0u64;
    let mut seen: HashMap<(DevAddr, u8), u64> = HashMap::new();
    loop {
        if cli.pull {
            if let Err(e) = client.pull() {
                eprintln!("no data: {e}");
            }
        } else {
            match woken.recv_timeout(Duration::from_millis(500)) {
                Ok(()) | Err(RecvTimeoutError::Timeout) => {}
                Err(RecvTimeoutError::Disconnected) => break,
            }
        }
        for &addr in &devices {
            for subtype in data_subtypes(addr.interf) {
                let Some(stamped) = client.latest(addr, subtype) else {
                    continue;
                };
                if seen.insert((addr, subtype), stamped.seq) == Some(stamped.seq) {
                    continue;
                }
                writeln!(
                    out,
                    "{:>12.3}  {}:{} {}  {}",
                    stamped.server_time,
                    addr.interf,
                    addr.index,
                    subtype,
                    summarize(&stamped.message)
                )?;
                printed += 1;
            }
        }
        if cli.count.is_some_and(|n| printed >= n) || deadline.is_some_and(|d| Instant::now() >= d)
        {
            break;
        }
        if cli.pull {
            std::thread::sleep(Duration::from_millis(100));
        }
    }
    Ok(())
}

/// The DATA subtypes to look for on a device: its interface table's, or every subtype for an
/// interface this crate has no table for (its bodies are printed undecoded).
fn data_subtypes(interf: Interface) -> Vec<u8> {
    let known: Vec<u8> = MessageKind::data_of(interf).map(|k| k.subtype).collect();
    if known.is_empty() && MessageKind::all_of(interf).is_empty() {
        (0..=u8::MAX).collect()
    } else {
        known
    }
}
