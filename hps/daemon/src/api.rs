//! The read-only HTTP API: `GET /v1/latest`, `GET /v1/health`, `GET /v1/metrics`.
//!
//! Served by `tiny_http` on one thread of its own. The API answers a few requests a minute
//! from building automation; a blocking HTTP/1.1 server is all that needs, and it keeps the
//! daemon's dependency tree and its ARM binary small. An async stack (tokio + axum/hyper)
//! would bring a runtime, a scheduler and ~100 crates for no gain in this load, and a larger
//! attack surface on a device that runs unattended for months.
//!
//! Nothing here can change the daemon: every method but GET (and HEAD, which tiny_http
//! answers as GET without a body) gets 405 with `Allow: GET`.

use crate::cycle::{CycleRecord, StageDurations};
use serde::Serialize;
use std::net::SocketAddr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// What the API shows, updated by the main loop.
#[derive(Clone, Debug, Default)]
pub struct ApiState {
    pub latest: Option<CycleRecord>,
    pub consecutive_failures: u64,
    pub last_error: Option<ErrorReport>,
    pub cycles_ok: u64,
    pub cycles_failed: u64,
    /// Successful cycles per place their HDR map was made (`fabric`: the fabric's map;
    /// `hps`: raw frames merged on the HPS).
    pub cycles_by_hdr: std::collections::BTreeMap<String, u64>,
    /// Successful cycles per place their sun came from (`fabric`: the accumulators; `hps`:
    /// the scan of the map).
    pub cycles_by_sun_source: std::collections::BTreeMap<String, u64>,
    /// Map-mode cycles whose sun fell back to the scan, per reason (`SunFallback::tag`).
    pub sun_fallbacks_by_reason: std::collections::BTreeMap<String, u64>,
    /// Failures per kind (`sensor_absent`, `output`, ...).
    pub failures_by_kind: std::collections::BTreeMap<String, u64>,
    /// Successful cycles whose record carried each plausibility flag.
    pub plausibility_by_flag: std::collections::BTreeMap<String, u64>,
    pub last_durations: Option<StageDurations>,
    /// Time to write the last successful cycle's results, ms.
    pub last_output_ms: f64,
    pub started_unix_s: f64,
    /// A configuration refused on SIGHUP (the daemon runs on the previous one), until a
    /// good one is loaded.
    pub config_error: Option<ErrorReport>,
}

/// The last error, for `/v1/health`.
#[derive(Clone, Debug, Serialize)]
pub struct ErrorReport {
    pub kind: String,
    pub message: String,
    /// When it happened (the capture time of the failed cycle).
    pub time: String,
}

/// Shared between the loop and the server thread.
pub type SharedState = Arc<Mutex<ApiState>>;

#[derive(Serialize)]
struct Health<'a> {
    status: &'static str,
    consecutive_failures: u64,
    last_error: Option<&'a ErrorReport>,
    cycles_ok: u64,
    cycles_failed: u64,
    latest_time: Option<&'a str>,
    /// A configuration refused on SIGHUP, with its file, line and field.
    #[serde(skip_serializing_if = "Option::is_none")]
    config_error: Option<&'a ErrorReport>,
}

#[derive(Serialize)]
struct Latest<'a> {
    time: &'a str,
    sequence: u64,
    sun: &'a crate::cycle::SunRecord,
    illuminance: &'a [crate::cycle::SensorLux],
    #[serde(skip_serializing_if = "Option::is_none")]
    monte_carlo: Option<&'a Vec<crate::cycle::SensorLux>>,
    /// Glare per occupant view: `ev_lux`, `dgp`, `dgps`, `method` and their companions.
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    views: &'a [crate::views::ViewGlare],
    outdoor_horizontal_lux: f64,
    /// The values outside physical bounds (`plausibility.rs`): a building acting on the
    /// numbers must see that they are doubtful.
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    plausibility: &'a [String],
    /// In simulation, the world's own values beside the measured ones.
    #[serde(skip_serializing_if = "Option::is_none")]
    truth_outdoor_horizontal_lux: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    truth_illuminance: Option<&'a Vec<crate::cycle::SensorLux>>,
}

/// A response: status, content type, body.
pub type Response = (u16, &'static str, String);

/// Answers one request (pure, so it is tested without sockets).
pub fn respond(method: &str, url: &str, state: &ApiState) -> Response {
    const JSON: &str = "application/json";
    let path = url.split('?').next().unwrap_or("");
    let known = matches!(path, "/v1/latest" | "/v1/health" | "/v1/metrics");
    if !known {
        return (404, JSON, r#"{"error":"not found"}"#.into());
    }
    if method != "GET" && method != "HEAD" {
        return (
            405,
            JSON,
            r#"{"error":"method not allowed: the API is read-only (GET)"}"#.into(),
        );
    }
    match path {
        "/v1/latest" => match &state.latest {
            Some(r) => (
                200,
                JSON,
                serde_json::to_string(&Latest {
                    time: &r.time,
                    sequence: r.sequence,
                    sun: &r.sun,
                    illuminance: &r.illuminance,
                    monte_carlo: r.monte_carlo.as_ref(),
                    views: &r.views,
                    outdoor_horizontal_lux: r.outdoor_horizontal_lux,
                    plausibility: &r.plausibility,
                    truth_outdoor_horizontal_lux: r.truth_outdoor_horizontal_lux,
                    truth_illuminance: r.truth_illuminance.as_ref(),
                })
                .unwrap_or_default(),
            ),
            None => (
                503,
                JSON,
                r#"{"error":"no capture has completed yet"}"#.into(),
            ),
        },
        "/v1/health" => {
            let h = Health {
                status: if state.consecutive_failures == 0 && state.config_error.is_none() {
                    "ok"
                } else {
                    "degraded"
                },
                consecutive_failures: state.consecutive_failures,
                last_error: state.last_error.as_ref(),
                cycles_ok: state.cycles_ok,
                cycles_failed: state.cycles_failed,
                latest_time: state.latest.as_ref().map(|r| r.time.as_str()),
                config_error: state.config_error.as_ref(),
            };
            (200, JSON, serde_json::to_string(&h).unwrap_or_default())
        }
        _ => (200, "text/plain; version=0.0.4", metrics(state)),
    }
}

/// Prometheus text exposition format.
fn metrics(s: &ApiState) -> String {
    let mut out = String::new();
    let mut put = |name: &str, kind: &str, help: &str, lines: Vec<(String, f64)>| {
        out.push_str(&format!("# HELP {name} {help}\n# TYPE {name} {kind}\n"));
        for (labels, v) in lines {
            out.push_str(&format!("{name}{labels} {v}\n"));
        }
    };
    put(
        "skyluxd_cycles_total",
        "counter",
        "Measurement cycles by outcome.",
        vec![
            ("{outcome=\"ok\"}".into(), s.cycles_ok as f64),
            ("{outcome=\"failed\"}".into(), s.cycles_failed as f64),
        ],
    );
    put(
        "skyluxd_captures_total",
        "counter",
        "Successful cycles by where their HDR map was made (fabric: the fabric's map; hps: \
         raw frames merged on the HPS, kept in campaign format).",
        s.cycles_by_hdr
            .iter()
            .map(|(k, v)| (format!("{{hdr=\"{k}\"}}"), *v as f64))
            .collect(),
    );
    put(
        "skyluxd_sun_source_total",
        "counter",
        "Successful cycles by where their sun came from (fabric: the fabric's accumulators; \
         hps: the HPS's scan of the map).",
        s.cycles_by_sun_source
            .iter()
            .map(|(k, v)| (format!("{{source=\"{k}\"}}"), *v as f64))
            .collect(),
    );
    put(
        "skyluxd_sun_fabric_fallbacks_total",
        "counter",
        "Map-mode cycles whose sun came from the HPS's scan instead of the accumulators, by \
         reason (not_armed, none, saturated, undersampled, scattered, not_measurable; faults: \
         bus, unsettled, stale, inconsistent).",
        s.sun_fallbacks_by_reason
            .iter()
            .map(|(k, v)| (format!("{{reason=\"{k}\"}}"), *v as f64))
            .collect(),
    );
    put(
        "skyluxd_failures_total",
        "counter",
        "Failed cycles by kind.",
        s.failures_by_kind
            .iter()
            .map(|(k, v)| (format!("{{kind=\"{k}\"}}"), *v as f64))
            .collect(),
    );
    put(
        "skyluxd_plausibility_flags_total",
        "counter",
        "Successful cycles with a value outside physical bounds, by flag.",
        s.plausibility_by_flag
            .iter()
            .map(|(k, v)| (format!("{{flag=\"{k}\"}}"), *v as f64))
            .collect(),
    );
    put(
        "skyluxd_consecutive_failures",
        "gauge",
        "Failed cycles since the last success.",
        vec![(String::new(), s.consecutive_failures as f64)],
    );
    if let Some(d) = &s.last_durations {
        put(
            "skyluxd_stage_duration_ms",
            "gauge",
            "Duration of each stage of the last successful cycle, milliseconds.",
            [
                ("capture", d.capture_ms),
                ("hdr", d.hdr_ms),
                ("sun", d.sun_ms),
                ("terms", d.terms_ms),
                ("illuminance", d.illuminance_ms),
                ("monte_carlo", d.monte_carlo_ms),
                ("views", d.views_ms),
                ("output", s.last_output_ms),
                ("total", d.total_ms),
            ]
            .into_iter()
            .map(|(k, v)| (format!("{{stage=\"{k}\"}}"), v))
            .collect(),
        );
    }
    if let Some(r) = &s.latest {
        put(
            "skyluxd_illuminance_lux",
            "gauge",
            "Latest illuminance per sensor, lux.",
            r.illuminance
                .iter()
                .map(|x| (format!("{{sensor=\"{}\"}}", x.sensor), x.lux))
                .collect(),
        );
    }
    out
}

/// The running server.
pub struct ApiServer {
    pub address: SocketAddr,
    stop: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl ApiServer {
    /// Binds `address` and serves `state` on a thread until [`ApiServer::stop`].
    pub fn start(address: SocketAddr, state: SharedState) -> Result<Self, String> {
        let server = tiny_http::Server::http(address)
            .map_err(|e| format!("cannot bind the API to {address}: {e}"))?;
        let bound = server
            .server_addr()
            .to_ip()
            .ok_or_else(|| "the API is not bound to an IP address".to_string())?;
        let stop = Arc::new(AtomicBool::new(false));
        let stop_thread = stop.clone();
        let thread = std::thread::Builder::new()
            .name("api".into())
            .spawn(move || {
                while !stop_thread.load(Ordering::Relaxed) {
                    let request = match server.recv_timeout(Duration::from_millis(200)) {
                        Ok(Some(r)) => r,
                        Ok(None) => continue,
                        Err(e) => {
                            tracing::warn!(error = %e, "API: receive failed");
                            continue;
                        }
                    };
                    let (status, content_type, body) = {
                        let guard = state.lock().unwrap_or_else(|p| p.into_inner());
                        respond(request.method().as_str(), request.url(), &guard)
                    };
                    let mut response =
                        tiny_http::Response::from_string(body).with_status_code(status);
                    if let Ok(h) = tiny_http::Header::from_bytes("Content-Type", content_type) {
                        response.add_header(h);
                    }
                    if status == 405 {
                        if let Ok(h) = tiny_http::Header::from_bytes("Allow", "GET") {
                            response.add_header(h);
                        }
                    }
                    if let Err(e) = request.respond(response) {
                        tracing::debug!(error = %e, "API: client went away");
                    }
                }
            })
            .map_err(|e| format!("cannot start the API thread: {e}"))?;
        Ok(Self {
            address: bound,
            stop,
            thread: Some(thread),
        })
    }

    /// Stops serving and joins the thread.
    pub fn stop(mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_get_and_known_paths() {
        let s = ApiState::default();
        assert_eq!(respond("POST", "/v1/latest", &s).0, 405);
        assert_eq!(respond("DELETE", "/v1/health", &s).0, 405);
        assert_eq!(respond("PUT", "/v1/metrics", &s).0, 405);
        assert_eq!(respond("GET", "/v2/latest", &s).0, 404);
        assert_eq!(respond("GET", "/v1/latest", &s).0, 503);
        let (code, _, body) = respond("GET", "/v1/health?x=1", &s);
        assert_eq!(code, 200);
        let v: serde_json::Value = serde_json::from_str(&body).unwrap();
        assert_eq!(v["status"], "ok");
        let degraded = ApiState {
            consecutive_failures: 2,
            last_error: Some(ErrorReport {
                kind: "i2c_nack".into(),
                message: "m".into(),
                time: "t".into(),
            }),
            plausibility_by_flag: [("outdoor_above_clear_sky_bound".to_string(), 3)].into(),
            ..ApiState::default()
        };
        let v: serde_json::Value =
            serde_json::from_str(&respond("GET", "/v1/health", &degraded).2).unwrap();
        assert_eq!(v["status"], "degraded");
        assert_eq!(v["last_error"]["kind"], "i2c_nack");
        // A refused reload alone degrades the health, and says why.
        let refused = ApiState {
            config_error: Some(ErrorReport {
                kind: "config".into(),
                message: "skyluxd.toml:3: capture.period_s".into(),
                time: "t".into(),
            }),
            ..ApiState::default()
        };
        let v: serde_json::Value =
            serde_json::from_str(&respond("GET", "/v1/health", &refused).2).unwrap();
        assert_eq!(v["status"], "degraded");
        assert_eq!(
            v["config_error"]["message"],
            "skyluxd.toml:3: capture.period_s"
        );
        // A doubtful record says so in /v1/latest too.
        let mut record = crate::cycle::CycleRecord::minimal("2017-05-08T12:00:00+02:00", "sim");
        record.plausibility = vec!["outdoor_above_clear_sky_bound".into()];
        let flagged = ApiState {
            latest: Some(record),
            ..ApiState::default()
        };
        let v: serde_json::Value =
            serde_json::from_str(&respond("GET", "/v1/latest", &flagged).2).unwrap();
        assert_eq!(
            v["plausibility"],
            serde_json::json!(["outdoor_above_clear_sky_bound"])
        );
        assert!(v.get("truth_illuminance").is_none(), "{v}");
        let m = respond("GET", "/v1/metrics", &degraded).2;
        assert!(m.contains("skyluxd_consecutive_failures 2"), "{m}");
        assert!(
            m.contains(
                "skyluxd_plausibility_flags_total{flag=\"outdoor_above_clear_sky_bound\"} 3"
            ),
            "{m}"
        );
    }

    #[test]
    fn serves_over_tcp() {
        use std::io::{Read, Write};
        let state: SharedState = Arc::default();
        let server = ApiServer::start("127.0.0.1:0".parse().unwrap(), state).unwrap();
        let get = |req: &str| {
            let mut s = std::net::TcpStream::connect(server.address).unwrap();
            s.write_all(req.as_bytes()).unwrap();
            let mut out = String::new();
            s.read_to_string(&mut out).unwrap();
            out
        };
        let r = get("GET /v1/health HTTP/1.0\r\n\r\n");
        assert!(r.starts_with("HTTP/1.0 200"), "{r}");
        let r = get("POST /v1/latest HTTP/1.0\r\nContent-Length: 0\r\n\r\n");
        assert!(
            r.starts_with("HTTP/1.0 405") && r.contains("Allow: GET"),
            "{r}"
        );
        server.stop();
    }
}
