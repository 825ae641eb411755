//! How a command-line tool ends: quietly when its reader went away (`playerprint … | head`
//! closes the pipe, which is what the person asked for), with the error's whole chain on
//! standard error otherwise, each cause said once.

use std::process::ExitCode;

/// The exit code for `result`; prints the error, prefixed with the program's `name`.
pub fn exit_code(name: &str, result: anyhow::Result<()>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{name}: {}", describe(&e));
            ExitCode::FAILURE
        }
    }
}

/// The error and its causes, joined by ": ", leaving out a cause whose words are already
/// there. The workspace's error types write their cause into their own message (so that a log
/// line of one error says everything) and also name it as their `source`, so walking the
/// chain as `{:#}` does would say each cause twice or more.
pub fn describe(error: &anyhow::Error) -> String {
    let mut said = String::new();
    for cause in error.chain() {
        let words = cause.to_string();
        if said.contains(&words) {
            continue;
        }
        if !said.is_empty() {
            said.push_str(": ");
        }
        said.push_str(&words);
    }
    said
}

fn is_broken_pipe(error: &anyhow::Error) -> bool {
    error
        .chain()
        .filter_map(|cause| cause.downcast_ref::<std::io::Error>())
        .any(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
}

#[cfg(test)]
mod tests {
    use super::*;
    use anyhow::Context;

    #[test]
    fn a_closed_pipe_ends_quietly_even_under_context() {
        let pipe = std::io::Error::from(std::io::ErrorKind::BrokenPipe);
        let wrapped = Err::<(), _>(pipe).context("printing a scan");
        assert_eq!(exit_code("t", wrapped), ExitCode::SUCCESS);
        let other = anyhow::anyhow!("no such device");
        assert_eq!(exit_code("t", Err(other)), ExitCode::FAILURE);
    }

    /// A cause that writes its own cause into its message, as the workspace's errors do.
    #[derive(Debug)]
    struct SaysItsCause(std::io::Error);

    impl std::fmt::Display for SaysItsCause {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            write!(f, "run.mcap is cut short at byte 10: {}", self.0)
        }
    }

    impl std::error::Error for SaysItsCause {
        fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
            Some(&self.0)
        }
    }

    #[test]
    fn each_cause_is_said_once_and_context_is_kept() {
        let cut = std::io::Error::new(std::io::ErrorKind::UnexpectedEof, "ended mid-record");
        let error = Err::<(), _>(SaysItsCause(cut))
            .context("reading run.mcap")
            .unwrap_err();
        assert_eq!(
            describe(&error),
            "reading run.mcap: run.mcap is cut short at byte 10: ended mid-record"
        );
        // A cause that its wrapper does not repeat is still said.
        let plain = Err::<(), _>(std::io::Error::other("permission denied"))
            .context("opening run.prec")
            .unwrap_err();
        assert_eq!(describe(&plain), "opening run.prec: permission denied");
    }
}
