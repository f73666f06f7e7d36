//! `skylux bench capture`: a frame through the cycle-accurate capture path, timed, and
//! checked word for word against the Bayer golden model (BENCHMARKS.md keeps the figures).

use anyhow::{bail, Context};
use skylux_hps::fpga::frames::RingLayout;
use skylux_rtl::bayer::golden::{expected_words, Frame};
use skylux_sim::bus::WaitPolicy;
use skylux_sim::capture_path::{CapturePathSim, PathConfig};
use skylux_sim::pixel_bus::Blanking;
use std::time::Instant;

#[derive(clap::Args)]
pub struct CaptureBenchArgs {
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
    /// Frame width in pixels (even, at most 4094).
    #[arg(long, default_value_t = 2592)]
    width: u16,
    /// Frame height in lines (even, at most 4094).
    #[arg(long, default_value_t = 1944)]
    height: u16,
    /// Fraction of cycles with waitrequest on the f2sdram port.
    #[arg(long, default_value_t = 0.3)]
    waitrequest: f64,
    /// PIXCLK in MHz (the MT9P031's maximum is 96).
    #[arg(long, default_value_t = 96.0)]
    pixclk_mhz: f64,
    /// LINE_VALID low between lines, in PIXCLK.
    #[arg(long, default_value_t = 16)]
    h_blank_pixclk: usize,
    /// Store raw samples instead of grouped words.
    #[arg(long)]
    raw: bool,
    /// Seed of the frame's samples and of waitrequest.
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

/// A frame with structure and noise: a diagonal ramp over the ADC range plus xorshift noise.
fn test_frame(width: usize, height: usize, seed: u64) -> Frame {
    let mut state = seed | 1;
    let samples = (0..width * height)
        .map(|i| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let (x, y) = (i % width, i / width);
            let ramp = (x + y) * 4095 / (width + height).max(1);
            ((ramp as u64 + (state & 0xFF)) % 4096) as u16
        })
        .collect();
    Frame {
        width,
        height,
        samples,
    }
}

pub fn run(args: &CaptureBenchArgs) -> anyhow::Result<()> {
    if !args.width.is_multiple_of(2)
        || !args.height.is_multiple_of(2)
        || args.width > 4094
        || args.height > 4094
    {
        bail!(
            "--width {} --height {}: both must be even and at most 4094",
            args.width,
            args.height
        );
    }
    if !(0.0..1.0).contains(&args.waitrequest) {
        bail!("--waitrequest {}: must be in [0, 1)", args.waitrequest);
    }
    if !(args.pixclk_mhz > 0.0 && args.pixclk_mhz <= 200.0) {
        bail!("--pixclk-mhz {}: must be in (0, 200]", args.pixclk_mhz);
    }
    let (w, h) = (usize::from(args.width), usize::from(args.height));
    let mut config = PathConfig::fitted(args.width, args.height, 1);
    config.bayer.raw = args.raw;
    config.pixclk_hz = args.pixclk_mhz * 1e6;
    let frame = test_frame(w, h, args.seed);
    let golden = expected_words(&frame, &config.bayer);
    let blanking = Blanking {
        horizontal_pixclk: args.h_blank_pixclk,
        ..Blanking::default()
    };

    let mut sim = CapturePathSim::new(config, WaitPolicy::random(args.waitrequest), args.seed);
    sim.bus.push_idle(8);
    sim.set_tags(0, 1);
    sim.push_frame(&frame.samples, w, h, &blanking, &[]);
    let start = Instant::now();
    let settled = sim
        .run_until_idle(2000, 200_000_000)
        .context("simulating the capture path")?;
    let wall_s = start.elapsed().as_secs_f64();
    if !settled {
        bail!("the capture path did not finish the frame");
    }

    let ring = RingLayout {
        window_base: u64::from(config.window_base),
        slot_stride_bytes: config.slot_stride_bytes,
        slots: config.slots,
    };
    let captured = ring
        .read_slot(&mut sim.memory, 0)
        .context("reading the frame back")?
        .context("no descriptor in slot 0: the frame was not written")?;
    let words = &captured.words;
    let mismatches = words.iter().zip(&golden).filter(|(a, b)| a != b).count()
        + words.len().abs_diff(golden.len());
    let pixels_per_word = if args.raw { 2 } else { 4 };
    let pixels = sim.counters.pixels_sent;
    let dropped_pixels = pixels.saturating_sub(pixels_per_word * words.len() as u64);
    let c = &sim.counters;
    let cycles = c.pixclk_cycles + c.sys_cycles;
    let result = serde_json::json!({
        "width": w,
        "height": h,
        "raw": args.raw,
        "pixclk_mhz": args.pixclk_mhz,
        "sys_clock_mhz": config.sys_clock_hz / 1e6,
        "waitrequest_fraction": args.waitrequest,
        "h_blank_pixclk": args.h_blank_pixclk,
        "pixels": pixels,
        "pixclk_cycles": c.pixclk_cycles,
        "sys_cycles": c.sys_cycles,
        "stall_cycles": sim.memory.stall_cycles,
        "beats_written": sim.memory.beats,
        "fifo_high_water": c.fifo_high_water,
        "dropped_pixels": dropped_pixels,
        "mismatches": mismatches,
        "words": words.len(),
        "flags": captured.flag_names(),
        "checksum_ok": captured.checksum_ok(),
        "bus_violations": sim.memory.violations.len(),
        "wall_s": wall_s,
        "sim_cycles_per_s": cycles as f64 / wall_s,
    });
    if args.json {
        println!("{}", serde_json::to_string(&result)?);
    } else {
        println!("{}", serde_json::to_string_pretty(&result)?);
    }
    if mismatches != 0 || !captured.is_good() || !sim.memory.violations.is_empty() {
        bail!(
            "the frame is not exact: {mismatches} mismatches, flags {:?}, {} bus violations",
            captured.flag_names(),
            sim.memory.violations.len()
        );
    }
    Ok(())
}
