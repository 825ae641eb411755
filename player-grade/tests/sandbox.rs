//! A program in its sandbox reaches its own simulation and nothing else: not a server on the
//! machine's loopback (another submission's simulation), and nor does what it starts.

use std::net::{TcpListener, TcpStream};
use std::path::Path;
use std::time::Duration;

use player_grade::sandbox::{Privilege, Sandbox};

/// What a program in the sandbox saw: (its own server reached by a child process, the outside
/// server reached by a child process), or why there is no sandbox.
fn inside_and_out(outside: u16) -> Result<(bool, bool), String> {
    let sandbox = Sandbox::enter(Privilege::RootWithoutCapabilities);
    if let Some(note) = &sandbox.not_isolated {
        return Err(note.clone());
    }
    let own = TcpListener::bind("127.0.0.1:0").unwrap();
    let folder = tempfile::tempdir().unwrap();
    let reaches = |port: u16| {
        sandbox
            .command(Path::new("python3"), folder.path())
            .unwrap()
            .args([
                "-c",
                &format!(
                    "import socket; socket.create_connection(('127.0.0.1', {port}), timeout=2)"
                ),
            ])
            .stderr(std::process::Stdio::null())
            .status()
            .unwrap()
            .success()
    };
    Ok((reaches(own.local_addr().unwrap().port()), reaches(outside)))
}

#[test]
fn a_sandboxed_program_reaches_its_own_loopback_and_not_the_machines() {
    let outside = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = outside.local_addr().unwrap().port();
    // The outside server is there: reached from here.
    assert!(
        TcpStream::connect_timeout(&outside.local_addr().unwrap(), Duration::from_secs(2)).is_ok()
    );
    let seen = std::thread::spawn(move || inside_and_out(port))
        .join()
        .unwrap();
    if unsafe_is_root() {
        assert_eq!(
            seen,
            Ok((true, false)),
            "own loopback up; the machine's out of reach"
        );
    } else {
        let note = seen.unwrap_err();
        assert!(note.starts_with("not isolated"), "{note}");
    }
}

fn unsafe_is_root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .unwrap()
        .lines()
        .find_map(|l| l.strip_prefix("Uid:"))
        .is_some_and(|ids| ids.split_whitespace().nth(1) == Some("0"))
}
