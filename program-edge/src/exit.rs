//! How a command-line tool ends: quietly when its reader went away (`playerprint … | head`
//! closes the pipe, which is what the person asked for), with the error's whole chain on
//! standard error otherwise.

use std::process::ExitCode;

/// The exit code for `result`; prints the error, prefixed with the program's `name`.
pub fn exit_code(name: &str, result: anyhow::Result<()>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{name}: {e:#}");
            ExitCode::FAILURE
        }
    }
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
}
