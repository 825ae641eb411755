//! `trim_capture` — shrink a JSON-lines capture to its first few DATA messages per direction,
//! cutting only between messages, so the result still frames and decodes. This is how the
//! repository's `captures/` keeps a camera session as a few frames.
//!
//! ```text
//! cargo run -p player-tools --example trim_capture -- --keep-data 2 IN.jsonl OUT.jsonl
//! ```

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::Parser;
use player_proto::capture::trim::keep_first_data;
use player_proto::capture::{parse_capture, write_capture};

/// Keep the banner, every request, reply and command, and the first DATA messages of each
/// direction; write one message per line.
#[derive(Parser, Debug)]
struct Cli {
    /// How many DATA messages of each direction to keep.
    #[arg(long)]
    keep_data: usize,
    /// The recorded capture.
    input: PathBuf,
    /// Where to write the trimmed capture.
    output: PathBuf,
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    let text = std::fs::read_to_string(&cli.input)
        .with_context(|| format!("reading {}", cli.input.display()))?;
    let chunks = parse_capture(&text).with_context(|| cli.input.display().to_string())?;
    let trimmed =
        keep_first_data(&chunks, cli.keep_data).with_context(|| cli.input.display().to_string())?;
    let written = write_capture(&trimmed);
    std::fs::write(&cli.output, &written)
        .with_context(|| format!("writing {}", cli.output.display()))?;
    println!(
        "{}: {} bytes in {} chunks -> {}: {} bytes in {} messages",
        cli.input.display(),
        text.len(),
        chunks.len(),
        cli.output.display(),
        written.len(),
        trimmed.len()
    );
    Ok(())
}
