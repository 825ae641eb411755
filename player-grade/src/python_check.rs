//! A teacher's check written in Python: a function given the run (a dict of lists: time, x,
//! y, yaw, stall, speed, the other robots' paths, how the run ended and the program's last
//! lines) that returns the share of the points — a number from 0 to 1, a bool, or a
//! `(share, message)` pair. It runs with the grader's Python, not in the students' sandbox:
//! it is the teacher's code.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::{Value, json};

use crate::output::Output;
use crate::trace::Trace;

/// How long a check may take.
const CHECK_TIME: Duration = Duration::from_secs(30);
/// The line the driver prints the result on.
const RESULT: &str = "PLAYER_GRADE_RESULT ";

const DRIVER: &str = r#"
import importlib.util, json, sys
path, function, run_file = sys.argv[1:4]
spec = importlib.util.spec_from_file_location("teacher_checks", path)
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)
with open(run_file) as f:
    run = json.load(f)
result = getattr(module, function)(run)
message = ""
if isinstance(result, tuple):
    result, message = result
share = (1.0 if result else 0.0) if isinstance(result, bool) else float(result)
print("PLAYER_GRADE_RESULT " + json.dumps({"share": share, "message": str(message)}))
"#;

/// Why a teacher's check gave no verdict (it then gives no points).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CheckError {
    #[error("cannot start {python}: {source}")]
    Start {
        python: String,
        source: std::io::Error,
    },
    #[error("the check took longer than {0} s")]
    TooLong(u64),
    #[error("the check failed: {0}")]
    Failed(String),
    #[error("the check returned {0}, not a share from 0 to 1")]
    BadShare(String),
}

/// The run as a teacher's function sees it.
pub fn run_json(trace: &Trace, ended: &str, output: &str) -> Value {
    let column = |f: &dyn Fn(usize, &crate::trace::Sample) -> Value| -> Vec<Value> {
        trace.samples.iter().map(|s| f(trace.robot, s)).collect()
    };
    let mut robots = serde_json::Map::new();
    for (index, name) in trace.names.iter().enumerate() {
        let xs: Vec<f64> = trace.samples.iter().map(|s| s.poses[index].0).collect();
        let ys: Vec<f64> = trace.samples.iter().map(|s| s.poses[index].1).collect();
        let yaws: Vec<f64> = trace.samples.iter().map(|s| s.poses[index].2).collect();
        robots.insert(name.clone(), json!({"x": xs, "y": ys, "yaw": yaws}));
    }
    json!({
        "robot": trace.names[trace.robot],
        "interval": trace.interval,
        "time": column(&|_, s| json!(s.time)),
        "x": column(&|r, s| json!(s.poses[r].0)),
        "y": column(&|r, s| json!(s.poses[r].1)),
        "yaw": column(&|r, s| json!(s.poses[r].2)),
        "stall": column(&|_, s| json!(s.stall)),
        "speed": column(&|_, s| json!(s.speed)),
        "robots": robots,
        "ended": ended,
        "output": output,
    })
}

/// Runs `function` of `file` over the run saved in `run_file`: its share of the points and its
/// message, or what went wrong (the check then gives nothing).
pub fn judge(
    python: &Path,
    file: &Path,
    function: &str,
    run_file: &Path,
) -> Result<(f64, String), CheckError> {
    let start = |source| CheckError::Start {
        python: python.display().to_string(),
        source,
    };
    let (reader, writer) = std::io::pipe().map_err(start)?;
    let output = Output::drain(reader);
    let mut child = Command::new(python)
        .arg("-c")
        .arg(DRIVER)
        .arg(file)
        .arg(function)
        .arg(run_file)
        .stdin(Stdio::null())
        .stdout(writer.try_clone().map_err(start)?)
        .stderr(writer)
        .spawn()
        .map_err(start)?;
    let deadline = Instant::now() + CHECK_TIME;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if Instant::now() < deadline => std::thread::sleep(Duration::from_millis(10)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(CheckError::TooLong(CHECK_TIME.as_secs()));
            }
        }
    };
    // The pipe's writers are gone with the child: what it printed is read to the end.
    output.wait_closed(Duration::from_secs(2));
    let text = output.last_lines(40);
    let Some(line) = text.lines().find_map(|l| l.strip_prefix(RESULT)) else {
        let error = output
            .python_error()
            .unwrap_or_else(|| format!("it ended with {status}"));
        return Err(CheckError::Failed(error));
    };
    let value: Value =
        serde_json::from_str(line).map_err(|e| CheckError::Failed(format!("its result: {e}")))?;
    let share = value["share"].as_f64().filter(|s| s.is_finite());
    let message = value["message"].as_str().unwrap_or_default().to_string();
    match share {
        Some(share) if (0.0..=1.0).contains(&share) => Ok((share, message)),
        _ => Err(CheckError::BadShare(value["share"].to_string())),
    }
}
