//! `playerrecord` and MCAP end to end on real Player traffic: every capture of the repository
//! (real Player 3 + Stage 4 bytes, `captures/` and `captures/nav/`) made into a recording,
//! exported to MCAP and converted back, byte for byte; a damaged MCAP file is refused with
//! where it stopped, keeping what came before.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn captures() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures");
    let mut paths: Vec<PathBuf> = [root.clone(), root.join("nav")]
        .iter()
        .flat_map(|dir| std::fs::read_dir(dir).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "jsonl"))
        .collect();
    paths.sort();
    paths
}

fn playerrecord(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_playerrecord"))
        .args(args)
        .output()
        .unwrap()
}

fn ok(out: Output) -> Output {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn every_real_capture_goes_to_mcap_and_back_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let (prec, mcap, back) = (
        dir.path().join("real.prec"),
        dir.path().join("real.mcap"),
        dir.path().join("back.prec"),
    );
    let captures = captures();
    let mut args = vec!["from-capture", "-o", path(&prec)];
    args.extend(captures.iter().map(|p| path(p)));
    ok(playerrecord(&args));
    ok(playerrecord(&[
        "export",
        "--mcap",
        path(&prec),
        "-o",
        path(&mcap),
    ]));
    ok(playerrecord(&["from-mcap", path(&mcap), "-o", path(&back)]));
    let (original, returned) = (std::fs::read(&prec).unwrap(), std::fs::read(&back).unwrap());
    assert!(original.len() > 100_000, "{} bytes", original.len());
    assert!(
        original == returned,
        "the .prec differs after a trip through MCAP"
    );
    // The name alone asks for MCAP too.
    let named = dir.path().join("named.mcap");
    ok(playerrecord(&["export", path(&prec), "-o", path(&named)]));
    assert_eq!(std::fs::read(&named).unwrap()[..8], *b"\x89MCAP0\r\n");
}

#[test]
fn a_cut_mcap_file_converts_up_to_the_cut_and_says_where() {
    let dir = tempfile::tempdir().unwrap();
    let (prec, mcap, cut, back) = (
        dir.path().join("laser.prec"),
        dir.path().join("laser.mcap"),
        dir.path().join("cut.mcap"),
        dir.path().join("back.prec"),
    );
    let capture = &captures()[0];
    ok(playerrecord(&[
        "from-capture",
        "-o",
        path(&prec),
        path(capture),
    ]));
    ok(playerrecord(&[
        "export",
        "--mcap",
        path(&prec),
        "-o",
        path(&mcap),
    ]));
    let bytes = std::fs::read(&mcap).unwrap();
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    let out = playerrecord(&["from-mcap", path(&cut), "-o", path(&back)]);
    assert!(!out.status.success());
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(error.contains("cut.mcap"), "{error}");
    assert!(error.contains("at or before byte"), "{error}");
    // What was converted is a valid recording, a prefix of the original.
    let original = std::fs::read(&prec).unwrap();
    let kept = std::fs::read(&back).unwrap();
    assert!(original.starts_with(&kept), "not a prefix");
}

/// A recording kept as MCAP (recorded straight to `*.mcap`, or exported) is summarised and
/// exported for Player's `readlog` exactly as the `.prec` it holds; a file that is neither
/// kind is refused by name, each cause said once.
#[test]
fn info_and_export_read_an_mcap_file_as_the_recording_it_holds() {
    let dir = tempfile::tempdir().unwrap();
    let (prec, mcap) = (dir.path().join("real.prec"), dir.path().join("real.mcap"));
    let mut args = vec!["from-capture", "-o", path(&prec)];
    let captures = captures();
    args.extend(captures.iter().map(|p| path(p)));
    ok(playerrecord(&args));
    ok(playerrecord(&["export", path(&prec), "-o", path(&mcap)]));

    let summary = |file: &Path| {
        let out = ok(playerrecord(&["info", path(file)]));
        let text = String::from_utf8(out.stdout).unwrap();
        // The first line starts with the file's own name.
        text.replacen(path(file), "FILE", 1)
    };
    let (of_prec, of_mcap) = (summary(&prec), summary(&mcap));
    assert!(of_prec.contains("laser:0"), "{of_prec}");
    assert_eq!(of_prec, of_mcap);

    let (log_prec, log_mcap) = (dir.path().join("prec.log"), dir.path().join("mcap.log"));
    ok(playerrecord(&[
        "export",
        path(&prec),
        "-o",
        path(&log_prec),
    ]));
    ok(playerrecord(&[
        "export",
        path(&mcap),
        "-o",
        path(&log_mcap),
    ]));
    let log = std::fs::read(&log_prec).unwrap();
    assert!(log.len() > 10_000, "{} bytes", log.len());
    assert!(log == std::fs::read(&log_mcap).unwrap(), "the logs differ");

    let garbage = dir.path().join("garbage.mcap");
    std::fs::write(&garbage, b"\x89MCAP0\r\nnot an MCAP file").unwrap();
    let out = playerrecord(&["info", path(&garbage)]);
    assert!(!out.status.success());
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(error.contains("garbage.mcap"), "{error}");
    assert!(error.contains("at or before byte"), "{error}");
    assert_eq!(error.matches("at or before byte").count(), 1, "{error}");
}
