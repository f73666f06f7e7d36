//! Row, frame and exposure timing of the MT9P031 in PIXCLK periods (hardware-facts.md §1.5 and
//! §0 items 1 and 2).

use super::registers::{addr, Registers};

/// Which shutter-overhead constants the exposure formula uses: the sources disagree
/// (hardware-facts.md §0 item 2), and the bench settles it (§1.6 calibration tip).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum ShutterOverhead {
    /// `SO = 208 (Row_Bin + 1) + 98 + min(SD, SDmax) − 94`, SDmax 1232 (SW < 3) or 1504: the
    /// MT9P031 Linux drivers (S4, S5) and the MT9P401 path of S6.
    #[default]
    VariantA,
    /// `SO = 346 (Row_Bin + 1) + 98 + min(SD, SDmax) + 166`, SDmax 1315 (SW < 3) or 1604: the
    /// "MT9P031" branch of S6, and S7.
    VariantB,
}

/// Readout geometry and timing settings decoded from the registers.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct FrameGeometry {
    /// Output pixels per line: `2 ceil((Column_Size + 1) / (2 (Column_Skip + 1)))`.
    pub width: u32,
    /// Output lines: the same from Row_Size and Row_Skip.
    pub height: u32,
    pub col_start: u32,
    pub row_start: u32,
    /// Skip factors (field + 1).
    pub col_skip: u32,
    pub row_skip: u32,
    /// Row_Bin and Column_Bin fields (0, 1 or 3).
    pub row_bin: u32,
    pub col_bin: u32,
    /// HB = R0x05 + 1, VB = R0x06 + 1.
    pub hb: u32,
    pub vb: u32,
}

fn output_size(size_reg: u16, skip: u32) -> u32 {
    2 * (u32::from(size_reg) + 1).div_ceil(2 * skip)
}

impl FrameGeometry {
    pub fn from_registers(r: &Registers) -> Self {
        let col_mode = u32::from(r.read(addr::COLUMN_ADDRESS_MODE));
        let row_mode = u32::from(r.read(addr::ROW_ADDRESS_MODE));
        let (col_skip, row_skip) = ((col_mode & 7) + 1, (row_mode & 7) + 1);
        Self {
            width: output_size(r.read(addr::COLUMN_SIZE), col_skip),
            height: output_size(r.read(addr::ROW_SIZE), row_skip),
            col_start: u32::from(r.read(addr::COLUMN_START)),
            row_start: u32::from(r.read(addr::ROW_START)),
            col_skip,
            row_skip,
            row_bin: (row_mode >> 4) & 3,
            col_bin: (col_mode >> 4) & 3,
            hb: u32::from(r.read(addr::HORIZONTAL_BLANK)) + 1,
            vb: u32::from(r.read(addr::VERTICAL_BLANK)) + 1,
        }
    }

    /// Minimum horizontal blanking: `346 (Row_Bin + 1) + 64 + W_DC / 2`, W_DC 80, 40, 20 for
    /// Column_Bin 0, 1, 3 (hardware-facts.md §1.5).
    pub fn hb_min(&self) -> u32 {
        let w_dc = match self.col_bin {
            0 => 80,
            1 => 40,
            _ => 20,
        };
        346 * (self.row_bin + 1) + 64 + w_dc / 2
    }

    /// Row time in PIXCLK: `2 max(W/2 + max(HB, HB_MIN), 41 + 346 (Row_Bin + 1) + 99)`.
    pub fn row_pixclk(&self) -> u64 {
        let a = self.width / 2 + self.hb.max(self.hb_min());
        let b = 41 + 346 * (self.row_bin + 1) + 99;
        2 * u64::from(a.max(b))
    }

    /// Vertical blanking in rows: `max(VB, VB_MIN)`, VB_MIN = `max(8, SW − H) + 1`
    /// (hardware-facts.md §1.5 [U]: 9 for short exposures, longer for long ones).
    pub fn vertical_blank_rows(&self, shutter_width_rows: u32) -> u32 {
        let vb_min = 8u32.max(shutter_width_rows.saturating_sub(self.height)) + 1;
        self.vb.max(vb_min)
    }

    /// Frame time in PIXCLK in continuous mode: `(H + max(VB, VB_MIN)) t_ROW`.
    pub fn frame_pixclk(&self, shutter_width_rows: u32) -> u64 {
        u64::from(self.height + self.vertical_blank_rows(shutter_width_rows)) * self.row_pixclk()
    }
}

/// Exposure in PIXCLK: `SW t_ROW − 2 SO` (hardware-facts.md §0 item 2), 0 where the formula
/// goes negative (a shutter delay far too large: the sources call the result nonsense).
pub fn exposure_pixclk(
    geometry: &FrameGeometry,
    shutter_width_rows: u32,
    shutter_delay_reg: u16,
    variant: ShutterOverhead,
) -> u64 {
    let sw = shutter_width_rows.max(1);
    let sd = i64::from(shutter_delay_reg) + 1;
    let rb = i64::from(geometry.row_bin) + 1;
    let so = match variant {
        ShutterOverhead::VariantA => {
            let sd_max = if sw < 3 { 1232 } else { 1504 };
            208 * rb + 98 + sd.min(sd_max) - 94
        }
        ShutterOverhead::VariantB => {
            let sd_max = if sw < 3 { 1315 } else { 1604 };
            346 * rb + 98 + sd.min(sd_max) + 166
        }
    };
    let t = i64::from(sw) * geometry.row_pixclk() as i64 - 2 * so;
    t.max(0) as u64
}

/// The shutter width (rows) whose exposure is closest to `exposure_pixclk` without going
/// below 1 row or above the 20-bit register.
pub fn shutter_width_for(
    geometry: &FrameGeometry,
    exposure_pixclk_wanted: u64,
    shutter_delay_reg: u16,
    variant: ShutterOverhead,
) -> u32 {
    let row = geometry.row_pixclk();
    // 2 SO, exact for SW >= 3 (the overhead does not depend on SW above that).
    let overhead = 3 * row - exposure_pixclk(geometry, 3, shutter_delay_reg, variant).min(3 * row);
    let sw = (exposure_pixclk_wanted + overhead + row / 2) / row;
    sw.clamp(1, (1 << 20) - 1) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The figures hardware-facts.md §0 item 1 and §1.5 compute from the formulas (and that two
    /// camera manuals, S20 and S21, confirm for the row time).
    #[test]
    fn default_registers_give_the_published_row_frame_and_exposure_figures() {
        let r = Registers::default();
        let g = FrameGeometry::from_registers(&r);
        assert_eq!((g.width, g.height), (2592, 1944));
        assert_eq!(g.row_pixclk(), 3492);
        assert_eq!(g.frame_pixclk(1), 6_879_240);
        assert_eq!(exposure_pixclk(&g, 1, 0, ShutterOverhead::VariantA), 3066);
        assert_eq!(exposure_pixclk(&g, 1, 0, ShutterOverhead::VariantB), 2270);
        let mut narrow = r.clone();
        narrow.write(addr::COLUMN_SIZE, 1);
        assert_eq!(FrameGeometry::from_registers(&narrow).row_pixclk(), 972);
    }

    #[test]
    fn skipping_and_binning_change_size_and_row_time() {
        let mut r = Registers::default();
        r.write(addr::COLUMN_ADDRESS_MODE, 0x0011);
        r.write(addr::ROW_ADDRESS_MODE, 0x0011);
        let g = FrameGeometry::from_registers(&r);
        assert_eq!((g.width, g.height), (1296, 972));
        // HB_MIN = 346·2 + 64 + 20 = 776 (the S5/S7 table).
        assert_eq!(g.hb_min(), 776);
        assert_eq!(g.row_pixclk(), 2 * (648 + 776));
    }

    #[test]
    fn shutter_width_for_inverts_the_exposure_formula() {
        let g = FrameGeometry::from_registers(&Registers::default());
        for variant in [ShutterOverhead::VariantA, ShutterOverhead::VariantB] {
            for sw in [3u32, 10, 1000, 100_000] {
                let t = exposure_pixclk(&g, sw, 0, variant);
                assert_eq!(shutter_width_for(&g, t, 0, variant), sw, "{variant:?} {sw}");
            }
        }
        // An absurd shutter delay gives 0, never a negative or wrapped exposure.
        let narrow = FrameGeometry { width: 2, ..g };
        assert_eq!(
            exposure_pixclk(&narrow, 1, 8000, ShutterOverhead::VariantB),
            0
        );
    }
}
