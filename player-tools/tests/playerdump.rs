//! `playerdump` on real server bytes, and on broken ones.

#[path = "../../player-proto/tests/support/captures.rs"]
mod captures;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn sample() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/laser_push.s2c")
}

fn playerdump(args: &[&std::ffi::OsStr]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_playerdump"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn the_sample_stream_decodes_one_line_per_message() {
    let out = playerdump(&[sample().as_os_str()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines[0], "banner: Player v.3.1.1-dev");
    assert_eq!(lines.len(), 1 + 64);
    let scans = lines
        .iter()
        .filter(|l| l.contains("laser:0 DATA") && l.contains("181 ranges, min 2.28 m"))
        .count();
    assert_eq!(scans, 60);
    assert!(String::from_utf8_lossy(&out.stderr).contains("64 messages"));
}

fn broken_copy(dir: &Path, name: &str, edit: impl FnOnce(&mut Vec<u8>)) -> PathBuf {
    let mut bytes = std::fs::read(sample()).unwrap();
    edit(&mut bytes);
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

#[test]
fn a_truncated_stream_fails_naming_the_offset() {
    let dir = tempfile::tempdir().unwrap();
    let path = broken_copy(dir.path(), "short.s2c", |b| b.truncate(b.len() - 100));
    let out = playerdump(&[path.as_os_str()]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("stream ends in the middle of a message")
            && stderr.contains("at stream byte"),
        "{stderr}"
    );
}

#[test]
fn a_lying_size_fails_naming_the_offset() {
    let dir = tempfile::tempdir().unwrap();
    // The first message starts after the 32-byte banner; its size field is bytes 36..40 of it.
    let path = broken_copy(dir.path(), "lying.s2c", |b| {
        b[32 + 36..32 + 40].copy_from_slice(&[0x7f, 0xff, 0xff, 0xff])
    });
    let out = playerdump(&[path.as_os_str()]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("at stream byte 32") && stderr.contains("above the"),
        "{stderr}"
    );
}

#[test]
fn a_corrupt_body_names_interface_subtype_and_offset() {
    let dir = tempfile::tempdir().unwrap();
    // Message 4 is the first laser scan: make its ranges count claim far more than is there.
    let path = broken_copy(dir.path(), "corrupt.s2c", |b| {
        let mut at = 32;
        for _ in 0..3 {
            let size = u32::from_be_bytes(b[at + 36..at + 40].try_into().unwrap()) as usize;
            at += 40 + size;
        }
        b[at + 40 + 16..at + 40 + 24].copy_from_slice(&[0, 0, 0x10, 0, 0, 0, 0x10, 0]);
    });
    let out = playerdump(&[path.as_os_str()]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("message 4 at stream byte") && stderr.contains("laser DATA subtype 1"),
        "{stderr}"
    );
}

#[test]
fn captures_decode_in_either_direction() {
    let capture = captures::capture("position2d_move.jsonl");
    for dir in ["s2c", "c2s"] {
        let out = playerdump(&[
            "--capture".as_ref(),
            "--dir".as_ref(),
            dir.as_ref(),
            capture.as_os_str(),
        ]);
        assert!(
            out.status.success(),
            "{dir}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let out = playerdump(&[
        "--capture".as_ref(),
        "--dir".as_ref(),
        "c2s".as_ref(),
        capture.as_os_str(),
    ]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("vel (0.40, 0.00, 0.30) motors 1"));
}
