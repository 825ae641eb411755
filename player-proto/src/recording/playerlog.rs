//! Export to Player's own log format: the text files its `writelog` driver writes and its
//! `readlog` driver plays back, so a recording can be served by real Player.
//!
//! Facts of that format (from Player's `server/drivers/shell/writelog.cc` and `readlog.cc`;
//! the code is ours): one message per line; lines starting `#` are comments, and a `##` line
//! of four words sets the format version (the last such line wins, so the file version comes
//! after the Player version); every line starts with the message header — timestamp (3
//! decimals), device host and robot (port) as unsigned integers, the interface's name, index,
//! message type and subtype — then the payload as numbers in a per-message layout. `readlog`
//! plays a line on the device it provides whose address matches (host 0 and 127.0.0.1 count as
//! the same), so the recorded host and port are kept.
//!
//! Covered here, as `writelog` writes them: position2d state and geometry, laser scans and
//! geometry, sonar ranges and geometry, ranger ranges, intensities and geometry. Anything else
//! is counted as skipped.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::{self, Write};

use super::format::Event;
use super::source::{RecordStream, SourceError};
use crate::capture::Direction;
use crate::interfaces::common::{BBox3d, Pose3d};
use crate::interfaces::laser::Laser;
use crate::interfaces::position2d::Position2d;
use crate::interfaces::ranger::{Ranger, RangerGeometry};
use crate::interfaces::sonar::{Sonar, SonarGeometry};
use crate::message::{Body, Message};
use crate::wire::{BANNER_LEN, Banner, Header, Interface, MsgType};

/// The file format version `writelog` declares and `readlog` expects.
pub const FILE_VERSION: &str = "0.3.0";

/// Why an export failed.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error("writing the Player log: {0}")]
    Write(#[from] io::Error),
    #[error(transparent)]
    Read(#[from] SourceError),
}

/// What an export wrote and left out.
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct ExportStats {
    pub lines: u64,
    /// Device messages from the server the format has no layout for, by interface, type and
    /// subtype (the server's own `player` replies are no device's and never logged).
    pub skipped: BTreeMap<(Interface, u8, u8), u64>,
    /// Where the recording stopped early (a torn tail): everything before was exported.
    pub stopped: Option<String>,
}

/// Writes the recording's messages from servers as a Player log. A torn tail ends the export
/// (reported in the stats); other damage is an error.
pub fn export<W: Write>(mut reader: impl RecordStream, out: W) -> Result<ExportStats, ExportError> {
    let mut out = io::BufWriter::new(out);
    let mut stats = ExportStats::default();
    let mut header_written = false;
    let mut line = String::new();
    loop {
        let record = match reader.next_record() {
            Ok(Some(record)) => record,
            Ok(None) => break,
            Err(e) if e.is_torn_tail() => {
                stats.stopped = Some(e.to_string());
                break;
            }
            Err(e) => return Err(e.into()),
        };
        match record.event {
            Event::Opened { banner } if !header_written => {
                write_preamble(&mut out, &banner)?;
                header_written = true;
            }
            Event::Message {
                direction: Direction::ServerToClient,
                header,
                body,
            } if matches!(header.msg_type, MsgType::Data | MsgType::Ack) => {
                let Ok(message) = Message::decode(header, body) else {
                    continue;
                };
                line.clear();
                if payload(&message.body, &mut line) {
                    writeln!(out, "{}{line}", header_words(&header))?;
                    stats.lines += 1;
                } else if header.addr.interf != Interface::PLAYER {
                    let key = (header.addr.interf, header.msg_type.code(), header.subtype);
                    *stats.skipped.entry(key).or_default() += 1;
                }
            }
            _ => {}
        }
    }
    out.flush()?;
    Ok(stats)
}

/// The `##` lines `writelog` starts a file with.
fn write_preamble(out: &mut impl Write, banner: &[u8; BANNER_LEN]) -> io::Result<()> {
    let version = Banner::parse(banner).map_or_else(|_| "unknown".into(), |b| b.version);
    writeln!(out, "## Player version {version} ")?;
    writeln!(out, "## File version {FILE_VERSION} ")?;
    writeln!(out, "## Format: ")?;
    writeln!(out, "## - Messages are newline-separated")?;
    writeln!(out, "## - Common header to each message is:")?;
    writeln!(
        out,
        "##   time     host   robot  interface index  type   subtype"
    )?;
    writeln!(
        out,
        "##   (double) (uint) (uint) (string)  (uint) (uint) (uint)"
    )?;
    writeln!(
        out,
        "## - Following the common header is the message payload "
    )
}

/// The common start of a line.
fn header_words(h: &Header) -> String {
    format!(
        "{:014.3} {} {} {} {:02} {:03} {:03} ",
        h.timestamp,
        h.addr.host,
        h.addr.robot,
        h.addr.interf,
        h.addr.index,
        h.msg_type.code(),
        h.subtype
    )
}

/// Appends the payload words of a message the format covers; false if it covers none.
fn payload(body: &Body, out: &mut String) -> bool {
    let mut w = |text: std::fmt::Arguments<'_>| out.write_fmt(text).expect("a String");
    match body {
        Body::Position2d(Position2d::State(d)) => w(format_args!(
            "{:+07.3} {:+07.3} {:+04.3} {:+07.3} {:+07.3} {:+07.3} {}",
            d.pos.px, d.pos.py, d.pos.pa, d.vel.px, d.vel.py, d.vel.pa, d.stall
        )),
        Body::Position2d(Position2d::Geometry(g)) => w(format_args!(
            "{:+07.3} {:+07.3} {:+04.3} {:+07.3} {:+07.3}",
            g.pose.px, g.pose.py, g.pose.pyaw, g.size.sl, g.size.sw
        )),
        Body::Laser(Laser::Scan(s)) => {
            w(format_args!(
                "{:04} {:+07.4} {:+07.4} {:+.8} {:+07.4} {:04} ",
                s.id,
                s.min_angle,
                s.max_angle,
                s.resolution,
                s.max_range,
                s.ranges.len()
            ));
            for (i, range) in s.ranges.iter().enumerate() {
                let intensity = s.intensity.get(i).copied().unwrap_or(0);
                w(format_args!("{range:.3} {intensity:2} "));
            }
        }
        Body::Laser(Laser::Geometry(g)) => w(format_args!(
            "{:+7.3} {:+7.3} {:7.3} {:7.3} {:7.3}",
            g.pose.px, g.pose.py, g.pose.pyaw, g.size.sl, g.size.sw
        )),
        Body::Sonar(Sonar::Ranges(d)) => {
            w(format_args!("{} ", d.ranges.len()));
            for range in &d.ranges {
                w(format_args!("{range:.3} "));
            }
        }
        Body::Sonar(Sonar::Geometry(g) | Sonar::GeometryData(g)) => sonar_geometry(g, out),
        Body::Ranger(Ranger::Ranges(d)) => numbers(&d.ranges, out),
        Body::Ranger(Ranger::Intensities(d)) => numbers(&d.intensities, out),
        Body::Ranger(Ranger::Geometry(g)) => ranger_geometry(g, out),
        _ => return false,
    }
    true
}

/// `count r0 r1 …` as the ranger layouts have it.
fn numbers(values: &[f64], out: &mut String) {
    let _ = write!(out, "{:04} ", values.len());
    for v in values {
        let _ = write!(out, "{v:.3} ");
    }
}

fn sonar_geometry(g: &SonarGeometry, out: &mut String) {
    let _ = write!(out, "{} ", g.poses.len());
    for p in &g.poses {
        let _ = write!(out, "{:+07.3} {:+07.3} {:+07.4} ", p.px, p.py, p.pyaw);
    }
}

fn pose3d(p: &Pose3d, out: &mut String) {
    let _ = write!(
        out,
        "{:+07.3} {:+07.3} {:+07.3} {:+07.3} {:+07.3} {:+07.3} ",
        p.px, p.py, p.pz, p.proll, p.ppitch, p.pyaw
    );
}

fn bbox3d(b: &BBox3d, out: &mut String) {
    let _ = write!(out, "{:+07.3} {:+07.3} {:+07.3} ", b.sw, b.sl, b.sh);
}

fn ranger_geometry(g: &RangerGeometry, out: &mut String) {
    pose3d(&g.pose, out);
    bbox3d(&g.size, out);
    let _ = write!(out, "{:04} ", g.element_poses.len());
    for p in &g.element_poses {
        pose3d(p, out);
    }
    let _ = write!(out, "{:04} ", g.element_sizes.len());
    for b in &g.element_sizes {
        bbox3d(b, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::common::Pose2d;
    use crate::interfaces::laser::LaserScan;
    use crate::interfaces::position2d::Position2dData;

    fn line(body: impl Into<Body>) -> String {
        let mut out = String::new();
        assert!(payload(&body.into(), &mut out));
        out
    }

    #[test]
    fn position2d_state_is_laid_out_as_writelog_does() {
        let data = Position2dData {
            pos: Pose2d {
                px: 1.5,
                py: -0.25,
                pa: 0.1,
            },
            vel: Pose2d::default(),
            stall: 1,
        };
        assert_eq!(
            line(Position2d::State(data)),
            "+01.500 -00.250 +0.100 +00.000 +00.000 +00.000 1"
        );
    }

    #[test]
    fn a_laser_scan_has_each_range_with_its_intensity() {
        let scan = LaserScan {
            min_angle: -1.25,
            max_angle: 1.25,
            resolution: 0.5,
            max_range: 8.0,
            ranges: vec![1.0, 2.25],
            intensity: vec![1].into(),
            id: 7,
        };
        assert_eq!(
            line(Laser::Scan(scan)),
            "0007 -1.2500 +1.2500 +0.50000000 +8.0000 0002 1.000  1 2.250  0 "
        );
    }

    #[test]
    fn the_header_words_name_the_device() {
        let mut h = Message::new(
            crate::wire::DevAddr {
                host: 16_777_343,
                robot: 6665,
                interf: Interface::LASER,
                index: 0,
            },
            MsgType::Data,
            1,
            Body::Empty,
        )
        .header;
        h.timestamp = 12.3456;
        assert_eq!(
            header_words(&h),
            "0000000012.346 16777343 6665 laser 00 001 001 "
        );
    }
}
