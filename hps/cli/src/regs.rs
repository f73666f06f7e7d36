//! `skylux regs`: a decoded dump of the register window, from the simulated fabric, a file, or
//! the real bridge.

use anyhow::Context;
use skylux_bus::{MappedWindow, RegisterBus};
use skylux_regmap::{Access, LW_BRIDGE_PHYS_BASE, LW_BRIDGE_SPAN_BYTES, MAP};
use std::io::Write;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct RegsArgs {
    /// Map the real register window through this device file (e.g. /dev/mem, needs root).
    #[arg(long, conflicts_with = "file")]
    dev_mem: Option<PathBuf>,
    /// Map a file holding a snapshot of the register window (2 MiB) instead.
    #[arg(long)]
    file: Option<PathBuf>,
}

pub fn run(args: &RegsArgs) -> anyhow::Result<()> {
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    if let Some(path) = &args.dev_mem {
        let mut w =
            MappedWindow::open_registers(path).with_context(|| "mapping the lightweight bridge")?;
        dump(&mut w, &mut out)
    } else if let Some(path) = &args.file {
        let mut w = MappedWindow::open(
            path,
            0,
            LW_BRIDGE_SPAN_BYTES as u64,
            LW_BRIDGE_PHYS_BASE as u64,
        )?;
        dump(&mut w, &mut out)
    } else {
        writeln!(
            out,
            "# cycle-accurate fabric model (no --dev-mem or --file given)"
        )?;
        let mut bus = skylux_sim::SimRegisterBus::new(skylux_rtl::RegisterFile::default());
        dump(&mut bus, &mut out)
    }
}

/// Prints every register and its fields.
pub fn dump(bus: &mut impl RegisterBus, out: &mut impl Write) -> anyhow::Result<()> {
    for block in MAP {
        for reg in block.registers {
            for i in 0..reg.count {
                let offset = reg.offset + 4 * i;
                let value = bus.read32(offset).with_context(|| {
                    format!("reading {}.{} at {offset:#x}", block.name, reg.name)
                })?;
                let name = if reg.count > 1 {
                    format!("{}.{}[{i}]", block.name, reg.name)
                } else {
                    format!("{}.{}", block.name, reg.name)
                };
                let fields: Vec<String> = reg
                    .fields
                    .iter()
                    .filter(|f| f.access != Access::W1P)
                    .map(|f| format!("{}={:#x}", f.name, f.get(value)))
                    .collect();
                writeln!(
                    out,
                    "{offset:#07x} {name:<32} {value:#010x}  {}",
                    fields.join(" ")
                )?;
            }
        }
    }
    Ok(())
}
