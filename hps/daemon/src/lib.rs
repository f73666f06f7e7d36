//! skyluxd: the Skylux HPS daemon. Captures an HDR sky on a schedule, turns it into a
//! luminance map, finds the sun, computes the illuminance at the room's sensors through
//! daylight coefficients (the offline pipeline's own functions), writes the results safely
//! and serves them over a read-only HTTP API.
//!
//! | module | what |
//! |---|---|
//! | [`config`] | `skyluxd.toml`, validated (including which physical memory may be mapped) |
//! | [`source`] | the capture source trait and the simulated source |
//! | [`fabric_source`] | the fabric source (board and cycle-accurate simulation): maps or raw frames |
//! | [`raw_captures`] | when a capture is raw in map mode: the cadence and SIGUSR1 |
//! | [`fabric_model_source`] | the fabric source over the behavioural fabric model, with hardware faults |
//! | [`wait`] | waiting for frames: UIO interrupt or polling, with a timeout |
//! | [`budget`] | `--bench-cycle`: the cycle budget by stage |
//! | [`cycle`] | capture → HDR → sun → illuminance → record |
//! | [`views`] | glare at the occupants' views: fisheye render, Ev, DGP, or DGPs in short time |
//! | [`output`] | crash-safe results, maps and captures, with retention |
//! | [`api`] | `/v1/latest`, `/v1/health`, `/v1/metrics` |
//! | [`daemon`] | the loop: schedule, back-off, signals, watchdog |
//! | [`notify`] | sd_notify over `$NOTIFY_SOCKET` |
//! | [`hardware`], [`privilege`] | map the two windows, then drop root |
//! | [`fuzzing`] | fuzz harnesses of `skyluxd.toml` and the API's requests (FUZZING.md) |
//! | [`drivers`] | embedded-hal drivers: the shield stepper, the MT9P031 on HPS I2C |

pub mod api;
pub mod budget;
pub mod config;
pub mod cycle;
pub mod daemon;
pub mod drivers;
pub mod fabric_model_source;
pub mod fabric_source;
pub mod fuzzing;
pub mod hardware;
pub mod interior_truth;
pub mod notify;
pub mod output;
pub mod plausibility;
pub mod privilege;
pub mod raw_captures;
pub mod sim_stage;
pub mod source;
pub mod spawn;
pub mod views;
pub mod wait;
pub mod window_states;
