//! `playerrecord` — record every message of Player robots losslessly, for robots without a
//! viewer; summarise a recording; turn captures into one; export to Player's own log format
//! or to MCAP, and back from MCAP.
//!
//! ```text
//! playerrecord record --out swarm.prec localhost:7000-7255 --seconds 600
//! playerrecord info swarm.prec
//! playerrecord export swarm.prec --out swarm.log
//! playerrecord from-capture captures/laser_push.jsonl --out laser.prec
//! playerrecord export swarm.prec --mcap --out swarm.mcap
//! playerrecord from-mcap swarm.mcap --out swarm.prec
//! ```

mod capture;
mod export;
mod info;
mod mcap_file;
mod record;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Record Player robots losslessly; summarise, convert and export recordings.
#[derive(Parser, Debug)]
#[command(version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    Record(record::Args),
    Info(info::Args),
    Export(export::Args),
    FromCapture(capture::Args),
    FromMcap(mcap_file::FromMcapArgs),
}

fn main() -> ExitCode {
    program_edge::logging::init("warn");
    let result = match Cli::parse().command {
        Command::Record(args) => record::run(args),
        Command::Info(args) => info::run(args),
        Command::Export(args) => export::run(args),
        Command::FromCapture(args) => capture::run(args),
        Command::FromMcap(args) => mcap_file::from_mcap(args),
    };
    program_edge::exit::exit_code("playerrecord", result)
}
