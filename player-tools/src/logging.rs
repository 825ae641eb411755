//! Logging setup shared by the command-line programs: `RUST_LOG` if set, else a default level,
//! to standard error (standard output carries the programs' own output).

/// Installs the tracing subscriber; `default` is a filter such as `"info"` or `"warn"`.
pub fn init(default: &str) {
    let filter = tracing_subscriber::EnvFilter::try_from_default_env()
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new(default));
    // A second initialisation (tests calling main twice) is not an error worth stopping for.
    let _ = tracing_subscriber::fmt()
        .with_env_filter(filter)
        .with_writer(std::io::stderr)
        .try_init();
}
