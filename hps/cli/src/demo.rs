//! `skylux demo`: the main job on a built-in default.
//!
//! First the HPS drivers bring up the cycle-accurate fabric model through the Avalon-MM bus
//! model, program an HDR exposure table and read everything back, exactly as they would on
//! the DE1-SoC through /dev/mem. Then the main job: a simulated campaign with an undeclared
//! effect, and the loop that finds it (`skylux sim campaign` and `skylux loop` in one).

use anyhow::{ensure, Context};
use skylux_bus::{RegisterAccess, RegisterBus};
use skylux_hps::fpga::{ExposureSlot, Fabric};
use skylux_regmap::{sys, UNMAPPED_READ_VALUE};
use std::time::Instant;

pub fn run(out_dir: &std::path::Path) -> anyhow::Result<()> {
    fabric_slice()?;
    campaign_and_loop(out_dir)
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

/// Part 2: the main job. A simulated campaign (the reference test module in Lausanne, a clear
/// and an overcast day, five exposures per capture, lux-meters and a pyranometer), with
/// an effect the model is not told about (dirty glazing), and a base model that leaves the
/// sun in the map as the published device first did; then the loop finds what is missing
/// and reports before and after on held-out times.
fn campaign_and_loop(out_dir: &std::path::Path) -> anyhow::Result<()> {
    use skylux_hps::campaign::Campaign;
    use skylux_hps::validation::illuminance_loop::LoopOptions;
    use skylux_sim::campaign::{simulate_campaign, CampaignSpec};

    println!();
    println!("Skylux demo, part 2: simulate a campaign, then close the loop");
    let started = Instant::now();
    let room = crate::sim_cmd::default_room()?;
    let mut spec = CampaignSpec::lausanne(room);
    spec.effects.glazing_transmittance = 0.85;
    spec.truth_samples = 16_384;
    let campaign_dir = out_dir.join("campaign");
    if campaign_dir.exists() {
        std::fs::remove_dir_all(&campaign_dir)
            .with_context(|| format!("clearing {}", campaign_dir.display()))?;
    }
    println!(
        "  world: {} at {:.2} N {:.2} E, {} days, captures every hour 8:00-18:00 (5 exposures, \
         1 us to 500 ms, {}x{} raw), 5 lux-meters, a pyranometer",
        spec.name,
        spec.site.latitude_deg,
        spec.site.longitude_deg,
        spec.days.len(),
        2592 / spec.skip,
        1944 / spec.skip
    );
    println!("  undeclared in the world: glazing transmittance x0.85 (dirt)");
    let bar = indicatif::ProgressBar::new((spec.days.len() * spec.hours.len()) as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("  {msg:28} [{bar:30}] {pos}/{len}")
            .expect("template")
            .progress_chars("=> "),
    );
    bar.set_message("simulating captures");
    let truth = simulate_campaign(&campaign_dir, &spec, &|done, _| {
        bar.set_position(done as u64)
    })
    .context("simulating the campaign")?;
    bar.finish_and_clear();
    println!(
        "  simulated {} captures into {} in {:.0} s",
        truth.len(),
        campaign_dir.display(),
        started.elapsed().as_secs_f64()
    );

    let loop_start = Instant::now();
    let campaign = Campaign::open(&campaign_dir)?;
    let mut options = LoopOptions::default();
    // The published device's first model: the sun stays in the map's patches.
    options.base.model.concentrated_sun = false;
    let outcome = crate::loop_cmd::run_with_progress(&campaign, &options)?;
    let report_dir = out_dir.join("report");
    crate::loop_cmd::write_outcome(&report_dir, &campaign, &outcome)?;
    println!(
        "  loop: HDR, sun, daylight coefficients and effects in {:.0} s",
        loop_start.elapsed().as_secs_f64()
    );
    crate::loop_cmd::print_summary(&report_dir, &outcome);
    Ok(())
}
