//! Logging set-up shared by the programs: `RUST_LOG` if set, else a default level, to standard
//! error (standard output carries the programs' own output). Colour only where a person reads
//! it: on a terminal, and not when `NO_COLOR` is set — a log written to a file or a pipe
//! carries no escape codes.

use std::io::IsTerminal;

/// Installs the tracing subscriber; `default` is a filter such as `"info"` or `"warn"`.
pub fn init(default: &str) {
    let filter = tracing_subscriber::EnvFilter::try_from_default_env()
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new(default));
    // A second initialisation (tests calling main twice) is not an error worth stopping for.
    let _ = tracing_subscriber::fmt()
        .with_env_filter(filter)
        .with_writer(std::io::stderr)
        .with_ansi(colour_wanted(
            std::io::stderr().is_terminal(),
            std::env::var_os("NO_COLOR").as_deref(),
        ))
        .try_init();
}

/// Whether to colour: on a terminal, unless `NO_COLOR` is set to anything but "" (no-color.org).
fn colour_wanted(on_terminal: bool, no_color: Option<&std::ffi::OsStr>) -> bool {
    on_terminal && no_color.is_none_or(|v| v.is_empty())
}

#[cfg(test)]
mod tests {
    use super::colour_wanted;

    #[test]
    fn colour_only_on_a_terminal_that_did_not_say_no_color() {
        assert!(colour_wanted(true, None));
        assert!(colour_wanted(true, Some("".as_ref())));
        assert!(!colour_wanted(true, Some("1".as_ref())));
        assert!(!colour_wanted(false, None), "a file or a pipe");
    }
}
