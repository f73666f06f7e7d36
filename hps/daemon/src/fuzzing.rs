//! Fuzz harnesses of the daemon's readers of outside data, `fn(&[u8])` as in
//! `skylux_hps::fuzzing`: `skyluxd.toml`, and requests to the HTTP API. Shared by the fuzzers
//! of `fuzz/` and the replay test `tests/fuzz_replay.rs` (FUZZING.md).

use crate::api::{respond, ApiState};
use crate::config::{Config, Overrides};
use crate::cycle::CycleRecord;
use std::path::Path;
use std::sync::OnceLock;

/// Every harness of the daemon by the name of its fuzz target (and corpus folder).
pub const TARGETS: &[(&str, skylux_hps::fuzzing::Harness)] =
    &[("daemon_config", daemon_config), ("http_api", http_api)];

/// The harness named `name`, if the daemon has one.
pub fn harness(name: &str) -> Option<skylux_hps::fuzzing::Harness> {
    TARGETS.iter().find(|(n, _)| *n == name).map(|(_, h)| *h)
}

/// `skyluxd.toml` parsed, resolved and validated; errors name the file.
pub fn daemon_config(bytes: &[u8]) {
    let text = String::from_utf8_lossy(bytes);
    let path = Path::new("/etc/skylux/skyluxd.toml");
    if let Err(e) = Config::parse(&text, path, &Overrides::default()) {
        let message = e.to_string();
        assert!(message.contains("skyluxd.toml"), "{message}");
    }
}

/// An HTTP request as tiny_http hands it to the router: the request line's method and
/// target (tiny_http parses the rest of the head and never shows it to the API). Answered
/// both before the first capture and with a record, so every resource is serialised.
pub fn http_api(bytes: &[u8]) {
    let head = String::from_utf8_lossy(bytes);
    let line = head.split(['\r', '\n']).next().unwrap_or("");
    let mut words = line.split(' ');
    let method = words.next().unwrap_or("");
    let url = words.next().unwrap_or("");
    for state in [&ApiState::default(), with_record()] {
        let (status, content_type, body) = respond(method, url, state);
        assert!(matches!(status, 200 | 404 | 405 | 503), "status {status}");
        assert!(!content_type.is_empty() && !body.is_empty());
    }
}

/// A state after one successful cycle with a failure before it.
fn with_record() -> &'static ApiState {
    static STATE: OnceLock<ApiState> = OnceLock::new();
    STATE.get_or_init(|| ApiState {
        latest: Some(CycleRecord {
            sequence: 2,
            ..CycleRecord::minimal("2017-05-08T10:00:00+02:00", "fuzz")
        }),
        cycles_ok: 1,
        cycles_failed: 1,
        failures_by_kind: [("i2c_nack".to_string(), 1)].into(),
        last_durations: Some(Default::default()),
        ..ApiState::default()
    })
}
