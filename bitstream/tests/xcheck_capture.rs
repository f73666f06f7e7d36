//! The capture path's Verilog (exported from a fresh instance) against its rust-hdl
//! simulation: two small frames (grouped, then raw) through both clock domains with random
//! waitrequest, recorded at every settle and replayed in Icarus.

use rust_hdl::prelude::*;
use skylux_bitstream::xcheck::{self, Tool};
use skylux_rtl::bayer::golden::{expected_words, Frame};
use skylux_rtl::capture::CapturePath;
use skylux_sim::bus::WaitPolicy;
use skylux_sim::capture_path::{CapturePathSim, PathConfig};
use skylux_sim::pixel_bus::{Blanking, Fault};

#[test]
fn capture_path_verilog_equals_rust_hdl() {
    if !xcheck::require(&[Tool::Iverilog, Tool::Vvp]) {
        return;
    }
    let (w, h) = (16usize, 4usize);
    let mut config = PathConfig::fitted(w as u16, h as u16, 2);
    config.bayer.black = 20;
    config.bayer.valid_max = 4000;
    let mut sim = CapturePathSim::new(config, WaitPolicy::random(0.3), 3);
    sim.driver.record();
    let blanking = Blanking {
        fv_to_lv_pixclk: 2,
        horizontal_pixclk: 4,
        lv_to_fv_pixclk: 2,
        vertical_pixclk: 16,
    };
    let frame = Frame {
        width: w,
        height: h,
        samples: (0..w * h).map(|i| ((i * 797 + 13) % 4096) as u16).collect(),
    };
    sim.bus.push_idle(4);
    sim.set_tags(3, 42);
    sim.push_frame(&frame.samples, w, h, &blanking, &[]);
    assert!(sim.run_until_idle(40, 100_000).unwrap());
    // A malformed frame too, so the flag paths are exercised.
    sim.set_tags(4, 43);
    sim.push_frame(
        &frame.samples,
        w,
        h,
        &blanking,
        &[Fault::ShortLine { row: 1, pixels: 2 }],
    );
    assert!(sim.run_until_idle(40, 100_000).unwrap());
    // The recorded run is itself right.
    assert_eq!(sim.status.frames_done, 2);
    assert!(sim.status.line_short);
    assert!(sim.memory.violations.is_empty());
    let mut payload = vec![0u8; 4 * expected_words(&frame, &config.bayer).len()];
    skylux_bus::DmaMemory::read_bytes(
        &mut sim.memory,
        // The memory model starts a 4 KiB guard below the window; slot 0's payload is at +64.
        4096 + 64,
        &mut payload,
    )
    .unwrap();
    let words: Vec<u32> = payload
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    assert_eq!(words, expected_words(&frame, &config.bayer));

    let trace = sim.driver.take_trace();
    let mut fresh = CapturePath::default();
    fresh.connect_all();
    let verilog = generate_verilog(&fresh);
    let report = xcheck::replay("capture_path", &verilog, &trace).unwrap();
    println!("{}", report.summary());
    assert!(
        report.steps > 500,
        "trace too short: {} steps",
        report.steps
    );
    assert!(report.is_clean(), "{}", report.summary());
}
