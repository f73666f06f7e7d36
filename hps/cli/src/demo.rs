//! `skylux demo`: the main job on a built-in default.
//!
//! The full job (simulate a campaign, run the loop, report) lands with the capture, HDR,
//! engine and loop issues. Until then this runs the deepest slice that works end to end: the
//! HPS drivers bring up the cycle-accurate fabric model through the Avalon-MM bus model,
//! program an HDR exposure table and read everything back, exactly as they would on the
//! DE1-SoC through /dev/mem.

use anyhow::{ensure, Context};
use skylux_bus::{RegisterAccess, RegisterBus};
use skylux_hps::fpga::{ExposureSlot, Fabric};
use skylux_regmap::{sys, UNMAPPED_READ_VALUE};
use std::time::Instant;

pub fn run(out_dir: &std::path::Path) -> anyhow::Result<()> {
    fabric_slice()?;
    hdr_slice(out_dir)
}

fn fabric_slice() -> anyhow::Result<()> {
    println!("Skylux demo, part 1: HPS drivers against the cycle-accurate fabric model");
    let started = Instant::now();
    let bus = skylux_sim::SimRegisterBus::new(skylux_rtl::RegisterFile::default());
    let mut fabric = Fabric::bring_up(bus).context("bring-up of the simulated fabric")?;
    let info = fabric.info().clone();
    println!(
        "  bring-up: design SKYL, register map v{}.{}, system clock {} MHz",
        info.version_major,
        info.version_minor,
        info.sys_clock_hz / 1_000_000
    );

    // Five exposures a factor ~20 apart, as an HDR sky sequence uses (in sensor rows).
    let slots: Vec<ExposureSlot> = [1u32, 20, 400, 8000, 160_000]
        .iter()
        .map(|&rows| ExposureSlot {
            shutter_width_rows: rows,
            shutter_delay: 0,
            gain_code: 8,
        })
        .collect();
    fabric.set_exposures(&slots)?;
    let back = fabric.exposures()?;
    ensure!(back == slots, "exposure table read back differs: {back:?}");
    println!(
        "  exposure table: {} slots written and read back: shutter widths {:?} rows",
        back.len(),
        back.iter()
            .map(|s| s.shutter_width_rows)
            .collect::<Vec<_>>()
    );

    // The bus never hangs: an unmapped read answers with a marker and is flagged.
    let bus = fabric.bus();
    let hole = 0x0FF0;
    let value = bus.read32(hole)?;
    ensure!(
        value == UNMAPPED_READ_VALUE,
        "unmapped read returned {value:#x}"
    );
    let flagged = bus.read_field(&sys::bus_status::REG, 0, &sys::bus_status::UNMAPPED_READ)?;
    let where_ = bus.read_field(&sys::bus_error_addr::REG, 0, &sys::bus_error_addr::OFFSET)?;
    ensure!(flagged == 1 && where_ == hole, "unmapped read not flagged");
    println!("  unmapped read at {hole:#x}: {value:#010x}, flagged in sys.bus_status at offset {where_:#x}");

    let mut bus = fabric.into_bus();
    let mut dump = Vec::new();
    crate::regs::dump(&mut bus, &mut dump)?;
    let cycles = bus.host.cycles();
    let elapsed = started.elapsed().as_secs_f64();
    println!(
        "  register dump: {} registers read; {cycles} fabric clock cycles simulated in {elapsed:.2} s ({:.0} cycles/s)",
        dump.iter().filter(|&&b| b == b'\n').count(),
        cycles as f64 / elapsed
    );
    println!("  (`skylux regs` prints the dump)");
    Ok(())
}

/// Part 2: a simulated sky capture (full sensor, five exposures from 1 µs to 500 ms) written
/// in the campaign format, merged into a luminance map by the same code as `skylux hdr`, and
/// compared with the simulator's truth.
fn hdr_slice(out_dir: &std::path::Path) -> anyhow::Result<()> {
    use skylux_hps::camera::{direction_from_alt_az, CameraModel, DeviceConfig, OrientationConfig};
    use skylux_hps::campaign::Readout;
    use skylux_hps::hdr::{map_capture, write_exr, MapFlag};
    use skylux_sim::capture::{simulate_capture, CaptureSpec};
    use skylux_sim::sky::SimulatedSky;

    println!("Skylux demo, part 2: a simulated sky capture through HDR synthesis");
    let started = Instant::now();
    let device = DeviceConfig {
        orientation: OrientationConfig {
            axis_azimuth_deg: 0.0,
            axis_altitude_deg: 90.0,
            roll_deg: 0.0,
        },
        // The whole hemisphere on the sensor's short side.
        lens: skylux_hps::camera::LensConfig {
            focal_px: 600.0,
            ..DeviceConfig::default().lens
        },
        ..DeviceConfig::default()
    };
    let camera = CameraModel::new(device.clone());
    let sky = SimulatedSky {
        zenith_luminance_cd_m2: 6000.0,
        sun_direction: direction_from_alt_az(35.0, 160.0),
        sun_luminance_cd_m2: 1.6e9,
        sun_radius_deg: 0.2665,
        ground_luminance_cd_m2: 1500.0,
    };
    let spec = CaptureSpec {
        time: "2017-05-08T12:00:00+02:00".into(),
        readout: Readout {
            col_start: 0,
            row_start: 0,
            skip: 1,
        },
        raw_width: 2592,
        raw_height: 1944,
        exposures_us: vec![1.0, 26.59, 707.1, 18_803.0, 500_000.0],
        gain: 1.0,
        seed: 2017,
        footprint: skylux_sim::sensor::Footprint::Integrated,
    };
    let capture_dir = out_dir.join("captures").join("2017-05-08T1200");
    let field = |d: glam::DVec3| sky.luminance_cd_m2(d);
    simulate_capture(&capture_dir, &camera, &field, &spec)
        .context("writing the simulated capture")?;
    device.write(&out_dir.join("device.toml"))?;
    let simulated = started.elapsed().as_secs_f64();
    println!("  simulated 5 raw frames of 2592x1944 (shot and read noise, 12 bit) into {} in {simulated:.1} s", capture_dir.display());

    let merge_start = Instant::now();
    let merged = map_capture(&capture_dir, &device)?;
    let merge_s = merge_start.elapsed().as_secs_f64();
    let map_path = out_dir.join("map.exr");
    write_exr(&map_path, &merged.map, &device, &merged.capture.readout)?;
    let map = &merged.map;
    let (mut n, mut sum, mut sum2) = (0usize, 0.0, 0.0);
    let (mut lo, mut hi) = (f64::MAX, 0.0f64);
    for i in 0..map.luminance_cd_m2.len() {
        if map.flags[i] != MapFlag::Valid || !merged.geometry.direction[i].is_finite() {
            continue;
        }
        let d = merged.geometry.direction[i].as_dvec3();
        let truth = sky.luminance_cd_m2(d);
        let l = map.luminance_cd_m2[i] as f64;
        lo = lo.min(l);
        hi = hi.max(l);
        // Groups straddling the disk's edge see a mix: score the sky away from the sun.
        let from_sun_deg = d.angle_between(sky.sun_direction).to_degrees();
        if from_sun_deg > 1.0 {
            let e = l / truth - 1.0;
            n += 1;
            sum += e;
            sum2 += e * e;
        }
    }
    ensure!(n > 0, "no valid sky groups");
    println!(
        "  merged in {merge_s:.2} s -> {} ({}x{} groups): {:.1} dB between {lo:.3e} and {hi:.3e} cd/m2",
        map_path.display(),
        map.width,
        map.height,
        20.0 * (hi / lo).log10()
    );
    println!(
        "  against the simulated truth: sky mean relative error {:+.3} %, RMS {:.3} % over {n} groups",
        100.0 * sum / n as f64,
        100.0 * (sum2 / n as f64).sqrt()
    );

    // The sun, extracted as the device does it (the prediction would come from SPA).
    let search = skylux_hps::sun::SunSearch {
        predicted_direction: Some(sky.sun_direction),
        ..Default::default()
    };
    match skylux_hps::sun::extract_sun(map, &merged.geometry, &search) {
        Ok(sun) => println!(
            "  sun extracted: direction error {:.4} deg, disk luminance {:.4e} cd/m2 (truth {:.4e}), direct-normal illuminance {:.0} lux, flags {:?}",
            sun.direction.angle_between(sky.sun_direction).to_degrees(),
            sun.disk_luminance_cd_m2,
            sky.sun_luminance_cd_m2,
            sun.direct_normal_illuminance_lux,
            sun.flags
        ),
        Err(e) => println!("  sun not extracted: {e}"),
    }
    let radiance_dir = out_dir.join("radiance-sky");
    let lookup = skylux_hps::hdr::SkyLookup::new(&camera, &merged, 4);
    skylux_hps::hdr::write_radiance_sky(&radiance_dir, 1024, &|d| lookup.luminance_cd_m2(d))?;
    println!(
        "  RADIANCE sky written to {} (sky.rad + sky.hdr + skylux_sky.cal)",
        radiance_dir.display()
    );
    println!(
        "  (next stages: the daylighting engine on this sky and the loop arrive with their issues)"
    );
    Ok(())
}
