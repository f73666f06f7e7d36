//! systemd's notification protocol (sd_notify(3)), written by hand: one datagram of
//! `KEY=VALUE` lines to the unix socket named by `$NOTIFY_SOCKET` (a path, or an abstract
//! name when it starts with `@`). Only when `NOTIFY_SOCKET` is set; otherwise every call is a
//! no-op. `$WATCHDOG_USEC` gives the watchdog period; systemd's advice is to ping at half
//! of it.

use std::os::unix::net::UnixDatagram;
use std::time::Duration;

/// A notifier bound to the socket systemd gave, or inert.
#[derive(Debug)]
pub struct Notifier {
    target: Option<(UnixDatagram, String)>,
    watchdog: Option<Duration>,
}

impl Notifier {
    /// From the environment (`NOTIFY_SOCKET`, `WATCHDOG_USEC`, `WATCHDOG_PID`).
    pub fn from_env() -> Self {
        let socket = std::env::var("NOTIFY_SOCKET").ok();
        let usec = std::env::var("WATCHDOG_USEC")
            .ok()
            .and_then(|v| v.parse::<u64>().ok());
        // WATCHDOG_PID, when set, names the process the watchdog is meant for.
        let ours = std::env::var("WATCHDOG_PID")
            .ok()
            .and_then(|p| p.parse::<u32>().ok())
            .is_none_or(|p| p == std::process::id());
        Self::new(socket.as_deref(), usec.filter(|_| ours))
    }

    /// For `socket` (`None`: inert) and a watchdog period in microseconds.
    pub fn new(socket: Option<&str>, watchdog_usec: Option<u64>) -> Self {
        let target = socket
            .filter(|s| !s.is_empty())
            .and_then(|s| UnixDatagram::unbound().ok().map(|d| (d, s.to_string())));
        Self {
            target,
            watchdog: watchdog_usec
                .filter(|&u| u > 0)
                .map(|u| Duration::from_micros(u / 2)),
        }
    }

    /// Whether systemd is listening.
    pub fn active(&self) -> bool {
        self.target.is_some()
    }

    /// How often to send `WATCHDOG=1` (half the configured watchdog period).
    pub fn watchdog_interval(&self) -> Option<Duration> {
        self.watchdog
    }

    /// Sends `state` (e.g. `READY=1\nSTATUS=...`). Errors are logged, never fatal.
    pub fn notify(&self, state: &str) {
        let Some((socket, name)) = &self.target else {
            return;
        };
        let result = if let Some(abstract_name) = name.strip_prefix('@') {
            send_abstract(socket, abstract_name, state)
        } else {
            socket.send_to(state.as_bytes(), name).map(|_| ())
        };
        if let Err(e) = result {
            tracing::warn!(socket = %name, error = %e, "sd_notify failed");
        }
    }

    pub fn ready(&self, status: &str) {
        self.notify(&format!("READY=1\nSTATUS={status}"));
    }

    pub fn status(&self, status: &str) {
        self.notify(&format!("STATUS={status}"));
    }

    pub fn watchdog(&self) {
        self.notify("WATCHDOG=1");
    }

    pub fn stopping(&self) {
        self.notify("STOPPING=1");
    }
}

#[cfg(any(target_os = "linux", target_os = "android"))]
fn send_abstract(socket: &UnixDatagram, name: &str, state: &str) -> std::io::Result<()> {
    #[cfg(target_os = "android")]
    use std::os::android::net::SocketAddrExt;
    #[cfg(target_os = "linux")]
    use std::os::linux::net::SocketAddrExt;
    let addr = std::os::unix::net::SocketAddr::from_abstract_name(name.as_bytes())?;
    socket.send_to_addr(state.as_bytes(), &addr).map(|_| ())
}

#[cfg(not(any(target_os = "linux", target_os = "android")))]
fn send_abstract(_: &UnixDatagram, _: &str, _: &str) -> std::io::Result<()> {
    Err(std::io::Error::other(
        "abstract socket names exist on Linux only",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inert_without_socket() {
        let n = Notifier::new(None, Some(10_000_000));
        assert!(!n.active());
        n.ready("x");
        assert_eq!(n.watchdog_interval(), Some(Duration::from_secs(5)));
    }

    #[test]
    fn datagrams_reach_a_path_socket() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("notify");
        let listener = UnixDatagram::bind(&path).unwrap();
        let n = Notifier::new(path.to_str(), None);
        n.ready("up");
        n.watchdog();
        let mut buf = [0u8; 256];
        let k = listener.recv(&mut buf).unwrap();
        assert_eq!(&buf[..k], b"READY=1\nSTATUS=up");
        let k = listener.recv(&mut buf).unwrap();
        assert_eq!(&buf[..k], b"WATCHDOG=1");
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn datagrams_reach_an_abstract_socket() {
        use std::os::linux::net::SocketAddrExt;
        let name = format!("skyluxd-test-{}", std::process::id());
        let addr = std::os::unix::net::SocketAddr::from_abstract_name(name.as_bytes()).unwrap();
        let bound = UnixDatagram::bind_addr(&addr);
        // Abstract sockets need a network namespace that allows them (some sandboxes refuse
        // it). Path sockets are tested above.
        if !skylux_hps::prerequisite::available_or_skip(
            bound.is_ok(),
            skylux_hps::prerequisite::REQUIRE_HOST,
            "abstract unix sockets unavailable here",
        ) {
            return;
        }
        let listener = bound.unwrap();
        Notifier::new(Some(&format!("@{name}")), None).stopping();
        let mut buf = [0u8; 64];
        let k = listener.recv(&mut buf).unwrap();
        assert_eq!(&buf[..k], b"STOPPING=1");
    }
}
