//! `playerdump` — decode a recorded Player byte stream, one line per message.
//!
//! Reads a raw server-to-client stream (the 32-byte banner, then messages) or, with
//! `--capture`, one direction of a JSON-lines capture. Stops at the first message that does
//! not decode, names its offset, and exits non-zero.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::{Parser, ValueEnum};
use player_proto::capture::{Direction, parse_capture, stream};
use player_proto::message::Message;
use player_proto::summary::summarize;
use player_proto::wire::{DEFAULT_MAX_BODY, FrameDecoder};

#[derive(Debug, Clone, Copy, ValueEnum)]
enum Dir {
    S2c,
    C2s,
}

/// Decode a recorded Player byte stream, one line per message.
#[derive(Parser, Debug)]
#[command(version)]
struct Cli {
    /// The raw stream (server to client: banner first), or a JSON-lines capture with --capture.
    file: PathBuf,

    /// The file is a JSON-lines capture (`{"t":…, "dir":"s2c", "hex":"…"}` per line).
    #[arg(long)]
    capture: bool,

    /// Which direction of a capture to decode (a client-to-server stream has no banner).
    #[arg(long, value_enum, default_value = "s2c")]
    dir: Dir,

    /// Largest message body accepted, bytes.
    #[arg(long, default_value_t = DEFAULT_MAX_BODY)]
    max_body: usize,
}

fn main() -> ExitCode {
    program_edge::exit::exit_code("playerdump", run(&Cli::parse()))
}

fn run(cli: &Cli) -> Result<()> {
    let raw =
        std::fs::read(&cli.file).with_context(|| format!("reading {}", cli.file.display()))?;
    let (bytes, has_banner) = if cli.capture {
        let text = String::from_utf8(raw).context("a capture is text")?;
        let chunks = parse_capture(&text)?;
        match cli.dir {
            Dir::S2c => (stream(&chunks, Direction::ServerToClient), true),
            Dir::C2s => (stream(&chunks, Direction::ClientToServer), false),
        }
    } else {
        (raw, true)
    };

    let mut out = std::io::stdout().lock();
    let mut frames = FrameDecoder::new(cli.max_body);
    frames.extend(&bytes);
    if has_banner {
        let banner = frames
            .take_banner()
            .context("stream shorter than the 32-byte banner")?
            .context("at stream byte 0")?;
        writeln!(out, "banner: {banner}")?;
    }
    let mut count = 0usize;
    while let Some(frame) = frames.next_frame()? {
        let offset = frame.offset;
        let message = Message::decode(frame.header, frame.body)
            .with_context(|| format!("message {} at stream byte {offset}", count + 1))?;
        let h = &message.header;
        writeln!(
            out,
            "{:>12.3}  {:<22} {:<5} {:>3}  {}",
            h.timestamp,
            h.addr.to_string(),
            h.msg_type.to_string(),
            h.subtype,
            summarize(&message)
        )?;
        count += 1;
    }
    if frames.buffered() > 0 {
        anyhow::bail!(
            "stream ends in the middle of a message: {} bytes at stream byte {}",
            frames.buffered(),
            frames.offset()
        );
    }
    eprintln!("{count} messages");
    Ok(())
}
