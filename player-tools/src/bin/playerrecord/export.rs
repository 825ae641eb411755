//! `playerrecord export`: a recording in the text format of Player's `writelog` driver, which
//! real Player's `readlog` plays back, as an MCAP file (`--mcap`, or an output named
//! `*.mcap`) that holds every record losslessly, or as a rosbag2 folder (`--rosbag2`) for ROS 2.

use std::path::PathBuf;

use anyhow::{Context, Result};
use player_proto::recording::playerlog;

/// Write a recording (`.prec` or MCAP) as a Player log for `readlog` (position2d, laser,
/// sonar, ranger), or as MCAP.
#[derive(clap::Args, Debug)]
pub struct Args {
    file: PathBuf,

    /// The file to write.
    #[arg(short, long)]
    out: PathBuf,

    /// Write MCAP (the default when the output's name ends in `.mcap`): every message
    /// losslessly, for MCAP readers and `player-sim --replay`.
    #[arg(long, conflicts_with = "rosbag2")]
    mcap: bool,

    /// Write a rosbag2 folder (metadata.yaml and an MCAP file of CDR messages with their
    /// ros2msg schemas) for `ros2 bag play`, rosbags and Foxglove: OUT is the folder.
    #[arg(long)]
    rosbag2: bool,

    /// A robot's name, for its ROS 2 namespace: HOST:PORT=NAME (else HOST_PORT). Repeat it.
    #[arg(long = "name", value_name = "HOST:PORT=NAME", requires = "rosbag2")]
    names: Vec<player_proto::RobotId>,
}

pub fn run(args: Args) -> Result<()> {
    let reader = crate::mcap_file::open_recording(&args.file)?;
    if args.rosbag2 {
        return rosbag2(reader, &args);
    }
    let out = std::fs::File::create(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    if args.mcap || crate::mcap_file::named_mcap(&args.out) {
        return crate::mcap_file::export(reader, out, &args.file, &args.out);
    }
    let stats = playerlog::export(reader, out)
        .with_context(|| format!("exporting {}", args.file.display()))?;
    eprintln!("wrote {} lines to {}", stats.lines, args.out.display());
    for ((interf, msg_type, subtype), count) in &stats.skipped {
        eprintln!(
            "  left out {count} {interf} type {msg_type} subtype {subtype} (no Player log layout)"
        );
    }
    if let Some(stopped) = &stats.stopped {
        eprintln!("the recording stops early; exported up to there: {stopped}");
    }
    Ok(())
}

/// The recording as a rosbag2 folder at `args.out`.
fn rosbag2(mut reader: impl player_proto::recording::RecordStream, args: &Args) -> Result<()> {
    let mut bag = player_ros2::bag::BagWriter::create(&args.out, &args.names)?;
    let mut stopped = None;
    loop {
        match reader.next_record() {
            Ok(Some(record)) => bag.write(&record)?,
            Ok(None) => break,
            Err(e) => {
                stopped = Some(e);
                break;
            }
        }
    }
    let stats = bag.finish()?;
    let total: u64 = stats.topics.values().sum();
    eprintln!("wrote {total} ROS 2 messages to {}", args.out.display());
    for (topic, n) in &stats.topics {
        eprintln!("  {topic}: {n}");
    }
    if stats.unmapped > 0 {
        eprintln!(
            "  left out {} Player messages with no ROS 2 counterpart yet",
            stats.unmapped
        );
    }
    if let Some(stopped) = stopped {
        eprintln!("the recording stops early; exported up to there: {stopped}");
    }
    Ok(())
}
