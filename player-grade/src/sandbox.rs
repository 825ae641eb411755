//! Where a student's program runs: a network namespace of its own (its simulation listens
//! there, and nothing else can be reached from it — no other student's simulation, no
//! network), as the unprivileged `nobody` when the grader is root, in a process group of its
//! own, with limits on processes, file sizes and core dumps. When it ends, everything in its
//! namespace is killed, whatever it forked or however it left its group.
//!
//! When `nobody` cannot run the grader's Python (a Python under root's home, as pyenv's), the
//! programs run as root with every capability dropped for good: still in their namespace, which
//! they cannot leave, but with root's files — the run says so.
//!
//! A namespace is a thread's: [`Sandbox::enter`] moves the calling thread, which then starts
//! the simulation (its sockets are made in the namespace) and the program (a child starts
//! where its parent thread is). Without the privilege for it (not root), programs run beside
//! each other on the machine's loopback, and each run says so.

use std::io;
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Command, Stdio};

/// `nobody`'s ids on Debian.
const NOBODY: u32 = 65534;
/// Processes (threads count) the program's user may have: numpy's thread pools fit, a fork
/// bomb does not.
const MOST_PROCESSES: u64 = 512;
/// The largest file the program may write.
const LARGEST_FILE: u64 = 64 << 20;

/// Who the programs run as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Privilege {
    /// `nobody`, with a limit on its processes.
    Nobody,
    /// Root without capabilities: `nobody` cannot run the Python.
    RootWithoutCapabilities,
    /// As the grader: it is not root.
    Grader,
}

impl Privilege {
    /// Who can run `python` with player3: `nobody` if it can, when the grader is root.
    pub fn for_python(python: &Path) -> Privilege {
        if unsafe { libc::geteuid() } != 0 {
            return Privilege::Grader;
        }
        let probe = Command::new(python)
            .args(["-c", "import player3"])
            .current_dir("/")
            .uid(NOBODY)
            .gid(NOBODY)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status();
        if probe.is_ok_and(|s| s.success()) {
            Privilege::Nobody
        } else {
            Privilege::RootWithoutCapabilities
        }
    }

    /// What a teacher should know of it, when it is weaker than `nobody`.
    pub fn note(self, python: &Path) -> Option<String> {
        match self {
            Privilege::Nobody => None,
            Privilege::RootWithoutCapabilities => Some(format!(
                "ran as root without capabilities: nobody cannot run {}",
                python.display()
            )),
            Privilege::Grader => Some("ran as the grader's own user (not root)".into()),
        }
    }
}

/// The calling thread's sandbox.
#[derive(Debug)]
pub struct Sandbox {
    /// The namespace's identity (`net:[inode]`), when the thread is in one of its own.
    namespace: Option<String>,
    /// Why not, when it is not.
    pub not_isolated: Option<String>,
    privilege: Privilege,
}

impl Sandbox {
    /// Moves the calling thread into a new network namespace with its loopback up; programs
    /// will run with `privilege`.
    pub fn enter(privilege: Privilege) -> Sandbox {
        match new_namespace() {
            Ok(namespace) => Sandbox {
                namespace: Some(namespace),
                not_isolated: None,
                privilege,
            },
            Err(e) => Sandbox {
                namespace: None,
                not_isolated: Some(format!(
                    "not isolated: the program shares the machine's network (a network \
                     namespace needs root: {e})"
                )),
                privilege,
            },
        }
    }

    /// `program` to run in the sandbox, from `folder` (made the program's own when it runs
    /// as `nobody`).
    pub fn command(&self, program: &Path, folder: &Path) -> io::Result<Command> {
        let mut command = Command::new(program);
        command.current_dir(folder).process_group(0);
        if self.privilege == Privilege::Nobody {
            give_to_nobody(folder)?;
            command.uid(NOBODY).gid(NOBODY);
        }
        let privilege = self.privilege;
        // SAFETY: between fork and exec only async-signal-safe calls (setrlimit, prctl).
        unsafe {
            command.pre_exec(move || {
                limit(libc::RLIMIT_CORE, 0)?;
                limit(libc::RLIMIT_FSIZE, LARGEST_FILE)?;
                match privilege {
                    Privilege::Nobody => limit(libc::RLIMIT_NPROC, MOST_PROCESSES)?,
                    Privilege::RootWithoutCapabilities => drop_capabilities()?,
                    Privilege::Grader => {}
                }
                Ok(())
            });
        }
        Ok(command)
    }

    /// The mark a run's processes carry in their environment ([`MARK`]), so that what they
    /// leave behind is found even outside a namespace of their own.
    pub fn mark(&self) -> String {
        format!(
            "{}-{}",
            std::process::id(),
            self.namespace.as_deref().unwrap_or("shared")
        )
    }

    /// Kills the program's process group, every process left in the namespace, and every
    /// process carrying the run's mark (`MARK=mark` in its environment).
    pub fn kill_all(&self, group: u32, mark: &str) {
        if let Ok(group) = i32::try_from(group) {
            unsafe {
                libc::killpg(group, libc::SIGKILL);
            }
        }
        let me = std::process::id();
        let Ok(entries) = std::fs::read_dir("/proc") else {
            return;
        };
        let marked = format!("{MARK}={mark}");
        for entry in entries.flatten() {
            let Some(pid) = entry
                .file_name()
                .to_str()
                .and_then(|s| s.parse::<u32>().ok())
            else {
                continue;
            };
            if pid == me {
                continue;
            }
            let in_namespace = self.namespace.as_ref().is_some_and(|namespace| {
                std::fs::read_link(entry.path().join("ns/net"))
                    .is_ok_and(|ns| ns.as_os_str() == namespace.as_str())
            });
            let carries_mark = || {
                std::fs::read(entry.path().join("environ"))
                    .is_ok_and(|environ| environ.split(|&b| b == 0).any(|v| v == marked.as_bytes()))
            };
            if (in_namespace || carries_mark())
                && let Ok(pid) = i32::try_from(pid)
            {
                unsafe {
                    libc::kill(pid, libc::SIGKILL);
                }
            }
        }
    }
}

/// The environment variable that marks a run's processes.
pub const MARK: &str = "PLAYER_GRADE_RUN";

/// Root's capabilities gone for good: not regained by exec (SECBIT_NOROOT, locked), none left
/// in the bounding set, no privilege from set-uid programs. Root without them cannot leave
/// its network namespace.
fn drop_capabilities() -> io::Result<()> {
    const SECBIT_NOROOT: libc::c_ulong = 1 << 0;
    const SECBIT_NOROOT_LOCKED: libc::c_ulong = 1 << 1;
    const SECBIT_NO_SETUID_FIXUP: libc::c_ulong = 1 << 2;
    const SECBIT_NO_SETUID_FIXUP_LOCKED: libc::c_ulong = 1 << 3;
    let bits = SECBIT_NOROOT
        | SECBIT_NOROOT_LOCKED
        | SECBIT_NO_SETUID_FIXUP
        | SECBIT_NO_SETUID_FIXUP_LOCKED;
    let ok = |r: libc::c_int| {
        if r == 0 {
            Ok(())
        } else {
            Err(io::Error::last_os_error())
        }
    };
    unsafe {
        ok(libc::prctl(libc::PR_SET_SECUREBITS, bits, 0, 0, 0))?;
        for capability in 0..64 {
            // Past the last capability the kernel knows: EINVAL, and nothing to drop.
            libc::prctl(libc::PR_CAPBSET_DROP, capability, 0, 0, 0);
        }
        ok(libc::prctl(libc::PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0))?;
    }
    Ok(())
}

fn limit(resource: libc::__rlimit_resource_t, most: u64) -> io::Result<()> {
    let value = libc::rlimit {
        rlim_cur: most,
        rlim_max: most,
    };
    if unsafe { libc::setrlimit(resource, &value) } == 0 {
        Ok(())
    } else {
        Err(io::Error::last_os_error())
    }
}

/// The calling thread in a new network namespace, its loopback up; the namespace's identity.
fn new_namespace() -> io::Result<String> {
    if unsafe { libc::unshare(libc::CLONE_NEWNET) } != 0 {
        return Err(io::Error::last_os_error());
    }
    loopback_up()?;
    let link = std::fs::read_link("/proc/thread-self/ns/net")?;
    Ok(link.to_string_lossy().into_owned())
}

/// `ip link set lo up`, in the calling thread's namespace.
fn loopback_up() -> io::Result<()> {
    let socket = unsafe { libc::socket(libc::AF_INET, libc::SOCK_DGRAM | libc::SOCK_CLOEXEC, 0) };
    if socket < 0 {
        return Err(io::Error::last_os_error());
    }
    let result = (|| {
        let mut request: libc::ifreq = unsafe { std::mem::zeroed() };
        for (to, from) in request.ifr_name.iter_mut().zip(b"lo\0") {
            *to = *from as libc::c_char;
        }
        if unsafe { libc::ioctl(socket, libc::SIOCGIFFLAGS, &mut request) } != 0 {
            return Err(io::Error::last_os_error());
        }
        unsafe {
            request.ifr_ifru.ifru_flags |= libc::IFF_UP as libc::c_short;
        }
        if unsafe { libc::ioctl(socket, libc::SIOCSIFFLAGS, &request) } != 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    })();
    unsafe {
        libc::close(socket);
    }
    result
}

/// Makes `folder` and what is in it `nobody`'s, so the program can write beside itself.
fn give_to_nobody(folder: &Path) -> io::Result<()> {
    std::os::unix::fs::chown(folder, Some(NOBODY), Some(NOBODY))?;
    for entry in std::fs::read_dir(folder)? {
        let path = entry?.path();
        if path.is_dir() {
            give_to_nobody(&path)?;
        } else {
            std::os::unix::fs::lchown(&path, Some(NOBODY), Some(NOBODY))?;
        }
    }
    Ok(())
}
