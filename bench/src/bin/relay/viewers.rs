//! Real viewers for `relay --swarm`: the relay's page in Debian's Chromium driven by
//! Playwright (`tests/web/page.mjs watch`) and Foxglove's own client library
//! (`tests/web/foxglove_client.mjs watch`), each a Node process that says `WATCHING` once it
//! shows what it was asked to, then, after the window, prints what it saw as one JSON line.

use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Child, ChildStdout, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

use anyhow::{Context, Result, bail};

/// The Node clients' folder (Playwright, ws-protocol: `scripts/setup.sh` installs them).
fn web_tests() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/web")
}

/// A Node viewer; killed when dropped if it has not finished.
pub struct Viewer {
    child: Child,
    lines: Receiver<String>,
}

impl Viewer {
    /// `node SCRIPT ARGS…` in tests/web.
    pub fn start(script: &str, args: &[String]) -> Result<Viewer> {
        let dir = web_tests();
        if !dir.join("node_modules/playwright-core").is_dir() {
            bail!(
                "{}/node_modules is missing: run scripts/setup.sh",
                dir.display()
            );
        }
        let mut child = Command::new("node")
            .arg(script)
            .args(args)
            .current_dir(&dir)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .context("node runs (scripts/setup.sh installs it)")?;
        let stdout: ChildStdout = child.stdout.take().context("node's stdout")?;
        let (send, lines) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                if send.send(line).is_err() {
                    break;
                }
            }
        });
        Ok(Viewer { child, lines })
    }

    /// Waits (at most `timeout`) for the viewer to show what it was asked to.
    pub fn watching(&self, timeout: Duration) -> Result<()> {
        loop {
            match self.lines.recv_timeout(timeout) {
                Ok(line) if line.trim() == "WATCHING" => return Ok(()),
                Ok(_) => {}
                Err(e) => bail!("the viewer never said WATCHING: {e}"),
            }
        }
    }

    /// What the viewer saw: its last line, as JSON, once it exits (at most `timeout`).
    pub fn finish(mut self, timeout: Duration) -> Result<serde_json::Value> {
        let mut last = None;
        while let Ok(line) = self.lines.recv_timeout(timeout) {
            last = Some(line);
        }
        let status = self.child.wait()?;
        let text = last.context("the viewer printed nothing")?;
        if !status.success() {
            bail!("the viewer failed ({status}): {text}");
        }
        Ok(serde_json::from_str(&text)?)
    }
}

impl Drop for Viewer {
    fn drop(&mut self) {
        if let Ok(None) = self.child.try_wait() {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}
