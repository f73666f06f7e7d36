//! yosys: structural checks and Cyclone V resource estimates.

use super::tools::{run, work_dir, Tool, ToolError};

/// Cyclone V resources of a design as yosys `synth_intel_alm -family cyclonev` maps it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Resources {
    /// Logic LUTs (MISTRAL_ALUT2..6 and MISTRAL_NOT).
    pub luts: u64,
    /// Carry-chain ALUTs (MISTRAL_ALUT_ARITH).
    pub carry_aluts: u64,
    /// Flip-flops (MISTRAL_FF).
    pub flip_flops: u64,
    /// Block RAMs (MISTRAL_M10K).
    pub m10k: u64,
    /// DSP multipliers (MISTRAL_MUL*).
    pub dsp: u64,
    /// Memory LABs used as RAM (MISTRAL_MLAB).
    pub mlab: u64,
}

/// Capacity of the 5CSEMA5 (hardware-facts.md §2: 32,070 ALMs, 397 M10K, 87 DSP blocks).
pub const DEVICE_ALMS: u64 = 32_070;
pub const DEVICE_M10K: u64 = 397;
pub const DEVICE_DSP: u64 = 87;
/// The whole core's ALM budget, in percent of the device: room for timing closure and later
/// blocks (issue 10).
pub const CORE_BUDGET_PERCENT: u64 = 60;
/// The block the budget applies to.
pub const CORE_BLOCK: &str = "skylux_core";

impl Resources {
    /// Whether block `name` fits the 5CSEMA5, and the whole core its budget: the error says
    /// which limit it passes.
    pub fn check_fit(&self, name: &str) -> Result<(), String> {
        let alms = self.alm_estimate();
        if alms > DEVICE_ALMS || self.m10k > DEVICE_M10K || self.dsp > DEVICE_DSP {
            return Err(format!("{name} does not fit the 5CSEMA5: {self:?}"));
        }
        if name == CORE_BLOCK && alms * 100 > CORE_BUDGET_PERCENT * DEVICE_ALMS {
            return Err(format!(
                "{name} uses {alms} ALMs, over its budget of {CORE_BUDGET_PERCENT} % of {DEVICE_ALMS}"
            ));
        }
        Ok(())
    }

    /// ALMs needed, estimated: yosys 0.23 does not pack ALMs, so this takes the larger of
    /// the LUT bound (two ALUTs per ALM, an arithmetic ALUT pair per ALM) and the register
    /// bound (four flip-flops per ALM). Quartus packs less tightly; treat it as a floor.
    pub fn alm_estimate(&self) -> u64 {
        let lut_bound = (self.luts + self.carry_aluts).div_ceil(2);
        let ff_bound = self.flip_flops.div_ceil(4);
        lut_bound.max(ff_bound) + self.mlab * 10
    }
}

fn write(name: &str, verilog: &str) -> Result<std::path::PathBuf, ToolError> {
    let dir = work_dir(name)?;
    let file = dir.join(format!("{name}.v"));
    std::fs::write(&file, verilog).map_err(|e| ToolError::Io(file.clone(), e))?;
    Ok(dir)
}

/// `hierarchy -check; proc; flatten; check -assert`: fails on latches, undriven or
/// multiply-driven nets and combinational loops, including loops across modules.
pub fn structural_check(name: &str, verilog: &str) -> Result<(), ToolError> {
    let dir = write(name, verilog)?;
    let script = format!("read_verilog {name}.v; hierarchy -check -top top; proc; flatten; check -assert; select -assert-none t:$dlatch t:$adlatch t:$dlatchsr");
    run(Tool::Yosys, &dir, &["-q", "-p", &script]).map(|_| ())
}

/// Synthesises for the Cyclone V and counts the mapped cells.
pub fn synthesize(name: &str, verilog: &str) -> Result<Resources, ToolError> {
    let dir = write(name, verilog)?;
    let script = format!(
        "read_verilog {name}.v; synth_intel_alm -family cyclonev -top top; check -assert; tee -o stat.txt stat"
    );
    run(Tool::Yosys, &dir, &["-q", "-p", &script])?;
    let stat = std::fs::read_to_string(dir.join("stat.txt"))
        .map_err(|e| ToolError::Io(dir.join("stat.txt"), e))?;
    Ok(parse_stat(&stat))
}

fn parse_stat(stat: &str) -> Resources {
    let mut r = Resources::default();
    // Only the design-wide totals: the last "Number of cells" section (the flattened top).
    for line in stat.lines() {
        let mut parts = line.split_whitespace();
        let (Some(cell), Some(count)) = (parts.next(), parts.next()) else {
            continue;
        };
        let Ok(count) = count.parse::<u64>() else {
            continue;
        };
        match cell {
            "MISTRAL_ALUT_ARITH" => r.carry_aluts += count,
            c if c.starts_with("MISTRAL_ALUT") || c == "MISTRAL_NOT" => r.luts += count,
            "MISTRAL_FF" => r.flip_flops += count,
            "MISTRAL_M10K" => r.m10k += count,
            "MISTRAL_MLAB" => r.mlab += count,
            c if c.starts_with("MISTRAL_MUL") => r.dsp += count,
            _ => {}
        }
    }
    r
}

#[cfg(test)]
mod tests {
    #[test]
    fn parses_yosys_stat() {
        let stat = "   Number of cells: 10\n     MISTRAL_ALUT2  3\n     MISTRAL_ALUT6  2\n     MISTRAL_ALUT_ARITH  4\n     MISTRAL_FF   9\n     MISTRAL_M10K  1\n     MISTRAL_MUL18X18 2\n";
        let r = super::parse_stat(stat);
        assert_eq!(
            (r.luts, r.carry_aluts, r.flip_flops, r.m10k, r.dsp),
            (5, 4, 9, 1, 2)
        );
        assert_eq!(r.alm_estimate(), 5);
    }
}
