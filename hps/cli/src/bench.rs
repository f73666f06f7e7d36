//! `skylux bench ...`: speed measured side by side with a reference in the same run
//! (BENCHMARKS.md keeps the figures).

use anyhow::Context;
use skylux_hps::camera::{CameraModel, DeviceConfig, ImagePoint};
use skylux_hps::campaign::BayerPattern;
use skylux_hps::hdr::{merge, Exposure, LuminanceMap, MapFlag};
use skylux_hps::timing::median_ms;
use skylux_sim::hdr_case::{HdrCase, EXPOSURES_S, HEIGHT_PX, WIDTH_PX};

#[derive(clap::Args)]
pub struct BenchArgs {
    #[command(subcommand)]
    what: BenchWhat,
}

#[derive(clap::Subcommand)]
enum BenchWhat {
    /// One frame through the capture path: pixel bus, rust-hdl capture + Bayer grouper +
    /// clock-domain FIFO + frame DMA, the SDRAM model on the f2sdram port with random
    /// waitrequest, and the HPS frame reader; checked against the Bayer golden model.
    Capture(crate::bench_capture::CaptureBenchArgs),
    /// The ray-box unit: tests per cycle in cycle-accurate simulation with memory stalls,
    /// Cyclone V resources, projected tests/s next to the software slab test, false misses.
    Raybox(crate::bench_raybox::RayboxBenchArgs),
    /// `skylux genbsdf` against the pyradiance port of genBSDF, same device, box and rays
    /// per patch: both times, the ratio, the files' per-patch differences.
    Genbsdf(crate::bench_genbsdf::GenbsdfBenchArgs),
    /// The illuminance engine against rtrace at equal error (1 % RMS against a converged
    /// rtrace reference) on the reference room: times, errors and the ratio.
    Illuminance(crate::bench_illuminance::IlluminanceBenchArgs),
    /// Image quality at equal wall time: our renderer (filtered and unfiltered) against
    /// rpict, each picture against a converged rtrace reference (per-pixel RMS relative
    /// error, Ev and DGP).
    Render(crate::bench_render::RenderBenchArgs),
    /// The loop against a battery of random campaigns whose truth comes from RADIANCE:
    /// recall, false discoveries, parameter errors, hold-out error and the confusion matrix
    /// per effect class.
    Loop(crate::bench_loop::LoopBenchArgs),
    /// One daylight-coefficient update for 400 sensors (Reinhart MF4), one core and all.
    Dc {
        #[arg(long)]
        json: bool,
        #[arg(long, default_value_t = 51)]
        repeat: usize,
    },
    /// A window state switch (three-phase, issue 20 item 5): 400 sensors, 5 window states
    /// (each a Klems T), Reinhart MF4 sky; D s once per capture, then one V T_k product per
    /// state, on one core.
    States {
        #[arg(long)]
        json: bool,
        #[arg(long, default_value_t = 51)]
        repeat: usize,
    },
    /// HDR synthesis of five full 2592x1944 frames (1 µs to 500 ms, 150 dB), on one core and
    /// on all cores, next to a naive baseline, with the accuracy against the simulated truth.
    Hdr {
        /// Print one JSON object instead of a table.
        #[arg(long)]
        json: bool,
        /// Timed repetitions (the median is reported).
        #[arg(long, default_value_t = 5)]
        repeat: usize,
    },
}

pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    match &args.what {
        BenchWhat::Hdr { json, repeat } => bench_hdr(*json, (*repeat).max(1)),
        BenchWhat::Capture(args) => crate::bench_capture::run(args),
        BenchWhat::Raybox(args) => crate::bench_raybox::run(args),
        BenchWhat::Dc { json, repeat } => crate::dc::bench(*json, (*repeat).max(1)),
        BenchWhat::States { json, repeat } => crate::dc_phase::bench(*json, (*repeat).max(1)),
        BenchWhat::Illuminance(args) => crate::bench_illuminance::run(args),
        BenchWhat::Genbsdf(args) => crate::bench_genbsdf::run(args),
        BenchWhat::Render(args) => crate::bench_render::run(args),
        BenchWhat::Loop(args) => crate::bench_loop::run(args),
    }
}

const WIDTH: usize = WIDTH_PX;
const HEIGHT: usize = HEIGHT_PX;

/// CPU time of the calling thread, ms; `None` where the platform has no per-thread clock.
fn thread_cpu_ms() -> Option<f64> {
    #[cfg(unix)]
    {
        let mut t = libc::timespec {
            tv_sec: 0,
            tv_nsec: 0,
        };
        // SAFETY: clock_gettime writes the timespec it is given and nothing else.
        if unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0 {
            return Some(t.tv_sec as f64 * 1e3 + t.tv_nsec as f64 * 1e-6);
        }
    }
    None
}

/// The 1-minute load average (Linux), so a reader sees how busy the machine was.
fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

fn bench_hdr(json: bool, repeat: usize) -> anyhow::Result<()> {
    let case = HdrCase::new();
    let (device, camera, geometry) = (&case.device, &case.camera, &case.geometry);
    let exposures = case.exposures();

    let one_core = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .context("thread pool")?;
    let mut map = None;
    // Wall time, and the CPU time of the pool's one thread: on a shared machine the second
    // is what one core spends, whatever else runs.
    let mut cpu_ms = Vec::new();
    let single_core_ms = median_ms(repeat, || {
        map = Some(one_core.install(|| {
            let start = thread_cpu_ms();
            let m = merge(&exposures, device, BayerPattern::GRBG, geometry);
            if let (Some(a), Some(b)) = (start, thread_cpu_ms()) {
                cpu_ms.push(b - a);
            }
            m
        }));
    });
    cpu_ms.sort_by(f64::total_cmp);
    let single_core_cpu_ms = cpu_ms.get(cpu_ms.len() / 2).copied();
    let all_cores_ms = median_ms(repeat, || {
        map = Some(merge(&exposures, device, BayerPattern::GRBG, geometry));
    });
    let map = map.unwrap()?;
    let baseline_ms = median_ms(repeat.min(2), || {
        std::hint::black_box(naive_merge(&exposures, device, camera));
    });

    // Accuracy against the truth, and the noise-limited bound for the same groups.
    let (mut n, mut sum, mut sum2, mut bound2) = (0usize, 0.0, 0.0, 0.0);
    let (mut min_l, mut max_l) = (f64::MAX, 0.0f64);
    for i in 0..map.luminance_cd_m2.len() {
        if map.flags[i] != MapFlag::Valid || !geometry.direction[i].is_finite() {
            continue;
        }
        let truth = case.truth_cd_m2(geometry.direction[i].as_dvec3());
        let l = map.luminance_cd_m2[i] as f64;
        let rate = truth / geometry.inverse_vignetting[i] as f64 / device.response.cg;
        let Some(b) = skylux_sim::analysis::hdr_relative_sigma_bound(device, &EXPOSURES_S, rate)
        else {
            continue;
        };
        let e = l / truth - 1.0;
        n += 1;
        sum += e;
        sum2 += e * e;
        bound2 += b * b;
        min_l = min_l.min(l);
        max_l = max_l.max(l);
    }
    let nf = n.max(1) as f64;
    let result = serde_json::json!({
        "frames": EXPOSURES_S.len(),
        "width": WIDTH,
        "height": HEIGHT,
        "groups": map.width * map.height,
        "threads": rayon::current_num_threads(),
        "single_core_ms": single_core_ms,
        "single_core_cpu_ms": single_core_cpu_ms,
        "all_cores_ms": all_cores_ms,
        "load_average_1min": load_average(),
        "baseline_ms": baseline_ms,
        "geometry_precompute_ms": case.geometry_ms,
        "valid_groups": n,
        "mean_rel_error": sum / nf,
        "rms_rel_error": (sum2 / nf).sqrt(),
        "rms_rel_bound": (bound2 / nf).sqrt(),
        "dynamic_range_db": 20.0 * (max_l / min_l).log10(),
    });
    if json {
        println!("{result}");
    } else {
        println!("{}", serde_json::to_string_pretty(&result)?);
    }
    Ok(())
}

/// The naive baseline: what a first implementation does. Per group, the lens is inverted and
/// the vignetting evaluated again, every exposure's luminance is computed, and the valid ones
/// are averaged with exposure-time weights; one thread.
fn naive_merge(
    exposures: &[Exposure],
    device: &DeviceConfig,
    camera: &CameraModel,
) -> LuminanceMap {
    let (w, h) = (WIDTH / 2, HEIGHT / 2);
    let [wr, wg, wb] = device.response.weights;
    let mut luminance = vec![f32::NAN; w * h];
    let mut flags = vec![MapFlag::UnderRange; w * h];
    for gy in 0..h {
        for gx in 0..w {
            let p = ImagePoint {
                x_px: 2.0 * gx as f64 + 1.0,
                y_px: 2.0 * gy as f64 + 1.0,
            };
            let Some(d) = camera.unproject(p) else {
                continue;
            };
            let v = camera.vignetting(camera.off_axis_rad(d));
            let (mut num, mut den) = (0.0, 0.0);
            for e in exposures {
                let s = |dx: usize, dy: usize| e.frame.at(2 * gx + dx, 2 * gy + dy) as f64;
                let (g1, r, b, g2) = (s(0, 0), s(1, 0), s(0, 1), s(1, 1));
                if [g1, r, b, g2]
                    .iter()
                    .all(|x| *x >= device.sensor.valid_min_dn && *x <= device.sensor.valid_max_dn)
                {
                    let k = device.sensor.black_level_dn;
                    let signal = wr * (r - k) + wg * ((g1 - k) + (g2 - k)) / 2.0 + wb * (b - k);
                    let l = device.response.cg * signal / (e.exposure_s * e.gain * v);
                    num += e.exposure_s * l;
                    den += e.exposure_s;
                }
            }
            if den > 0.0 {
                luminance[gy * w + gx] = (num / den) as f32;
                flags[gy * w + gx] = MapFlag::Valid;
            }
        }
    }
    LuminanceMap {
        width: w,
        height: h,
        relative_sigma: vec![f32::NAN; w * h],
        luminance_cd_m2: luminance,
        flags,
    }
}
