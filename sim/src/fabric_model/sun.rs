//! The sun accumulators (`sun.*`, `skylux_rtl::sun`, issue 22 item 2) per frame. A frame the
//! ingest takes for the DMA in grouped mode is armed when, as it opens, `sun.ctrl.ENABLE` is
//! set and its exposure index (the sequencer's tag, as its descriptor carries it) is
//! `sun.ctrl.EXPOSURE_INDEX`. The words the ingest took (after any FIFO loss: the block sits
//! behind the ingest) are summed by the RTL's golden model
//! ([`skylux_rtl::sun::golden::accumulate`]) with the threshold, the window and
//! `capture.window.WIDTH` as they stand; the sums replace the last armed frame's and
//! `sun.frames` counts the frame. A frame without words never begins, as in the RTL (its first
//! word arms it). Needed so `skyluxd`'s fabric source reads the sun from the registers here
//! as it would from the hardware.

use super::FabricModel;
use skylux_regmap::{capture, sun};
use skylux_rtl::sun::golden::{accumulate, SunConfig, SunSums};

/// A fault of the accumulators, for the daemon's fallback to the HPS's own sun search.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum SunFault {
    /// Every result register but `sun.frames` reads all ones (a block that answers garbage):
    /// sums no frame can give.
    Garbage,
    /// Armed frames are not accumulated: the sums and `sun.frames` keep the last frame's.
    Stale,
}

/// The block's state.
#[derive(Clone, Debug, Default)]
pub struct SunBlock {
    /// The last armed frame's sums.
    pub sums: SunSums,
    /// `sun.frames`: armed frames begun (wraps).
    pub frames: u16,
    pub fault: Option<SunFault>,
}

/// The exposure index field of a frame's tag (3 bits, as `taken_exposure_index` in the RTL).
const EXPOSURE_INDEX_BITS: u32 = 0x7;

impl FabricModel {
    /// Whether a frame opening now (raw or not, with the sequencer's `tag_index`) is armed.
    pub(super) fn sun_armed(&mut self, raw: bool, tag_index: u32) -> bool {
        let ctrl = self.stored(sun::ctrl::REG.offset);
        sun::ctrl::ENABLE.get(ctrl) != 0
            && !raw
            && tag_index & EXPOSURE_INDEX_BITS == sun::ctrl::EXPOSURE_INDEX.get(ctrl)
    }

    /// The accumulators' settings as the registers hold them now.
    fn sun_config(&mut self) -> SunConfig {
        let window = self.stored(capture::window::REG.offset);
        let x = self.stored(sun::window_x::REG.offset);
        let y = self.stored(sun::window_y::REG.offset);
        SunConfig {
            // `capture.window.WIDTH` bits 11:1, as the RTL wires it.
            groups_per_line: ((capture::window::WIDTH.get(window) >> 1) & 0x7FF) as u16,
            threshold_q14: sun::threshold::Q14.get(self.stored(sun::threshold::REG.offset)),
            x_min: sun::window_x::MIN.get(x) as u16,
            x_max: sun::window_x::MAX.get(x) as u16,
            y_min: sun::window_y::MIN.get(y) as u16,
            y_max: sun::window_y::MAX.get(y) as u16,
        }
    }

    /// An armed frame's taken words: its sums replace the last armed frame's.
    pub(super) fn sun_frame(&mut self, words: &[u32]) {
        if words.is_empty() || self.sun.fault == Some(SunFault::Stale) {
            return;
        }
        let config = self.sun_config();
        self.sun.sums = accumulate(&config, words);
        self.sun.frames = self.sun.frames.wrapping_add(1);
    }

    /// The RO registers of `sun.*` as they are now.
    pub(super) fn sun_inputs(&mut self) {
        let s = self.sun.sums;
        let lo = |v: u64| v as u32;
        let hi = |v: u64| (v >> 32) as u32;
        let mut inputs = vec![
            (sun::count::REG.offset, sun::count::GROUPS.word(s.count)),
            (
                sun::over_count::REG.offset,
                sun::over_count::GROUPS.word(s.over_count),
            ),
            (sun::sum_l_lo::REG.offset, lo(s.sum_l)),
            (sun::sum_l_hi::REG.offset, hi(s.sum_l)),
            (sun::sum_xl_lo::REG.offset, lo(s.sum_xl)),
            (sun::sum_xl_hi::REG.offset, hi(s.sum_xl)),
            (sun::sum_yl_lo::REG.offset, lo(s.sum_yl)),
            (sun::sum_yl_hi::REG.offset, hi(s.sum_yl)),
            (sun::max_l::REG.offset, sun::max_l::Q14.word(s.max_l)),
            (
                sun::box_x::REG.offset,
                sun::box_x::MIN.word(s.min_x.into()) | sun::box_x::MAX.word(s.max_x.into()),
            ),
            (
                sun::box_y::REG.offset,
                sun::box_y::MIN.word(s.min_y.into()) | sun::box_y::MAX.word(s.max_y.into()),
            ),
        ];
        if self.sun.fault == Some(SunFault::Garbage) {
            for (_, v) in &mut inputs {
                *v = u32::MAX;
            }
        }
        inputs.push((
            sun::frames::REG.offset,
            sun::frames::COUNT.word(self.sun.frames.into()),
        ));
        for (o, v) in inputs {
            self.regs.fabric_inputs.insert(o, v);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{FabricModel, FabricModelConfig, HardwareFault};
    use super::*;
    use skylux_regmap::words::grouped;

    fn model() -> FabricModel {
        FabricModel::new(
            crate::mt9p031::Mt9p031::new(Box::new(crate::mt9p031::RampSource), 96e6),
            FabricModelConfig::new(4096),
        )
    }

    /// The registers as the HPS writes them: a 4-group-wide window, threshold 100 Q14, the
    /// accumulators armed for exposure 2.
    fn armed(m: &mut FabricModel) {
        m.write_register(
            capture::window::REG.offset,
            capture::window::WIDTH.word(8) | capture::window::HEIGHT.word(8),
        );
        m.write_register(sun::threshold::REG.offset, sun::threshold::Q14.word(100));
        m.write_register(
            sun::window_x::REG.offset,
            sun::window_x::MIN.word(1) | sun::window_x::MAX.word(3),
        );
        m.write_register(
            sun::window_y::REG.offset,
            sun::window_y::MIN.word(0) | sun::window_y::MAX.word(3),
        );
        m.write_register(
            sun::ctrl::REG.offset,
            sun::ctrl::ENABLE.word(1) | sun::ctrl::EXPOSURE_INDEX.word(2),
        );
    }

    fn words() -> Vec<u32> {
        (0..16u32)
            .map(|i| grouped::pack(50 * i, false, i == 9))
            .collect()
    }

    /// What the HPS reads back, through the register file as the bus sees it.
    fn read_sums(m: &mut FabricModel) -> (SunSums, u32) {
        let r = |m: &mut FabricModel, reg: &skylux_regmap::Register| m.read_register(reg.offset);
        let wide = |m: &mut FabricModel, lo, hi| u64::from(r(m, hi)) << 32 | u64::from(r(m, lo));
        let (bx, by) = (r(m, &sun::box_x::REG), r(m, &sun::box_y::REG));
        let sums = SunSums {
            count: r(m, &sun::count::REG),
            over_count: r(m, &sun::over_count::REG),
            sum_l: wide(m, &sun::sum_l_lo::REG, &sun::sum_l_hi::REG),
            sum_xl: wide(m, &sun::sum_xl_lo::REG, &sun::sum_xl_hi::REG),
            sum_yl: wide(m, &sun::sum_yl_lo::REG, &sun::sum_yl_hi::REG),
            max_l: r(m, &sun::max_l::REG),
            min_x: sun::box_x::MIN.get(bx) as u16,
            max_x: sun::box_x::MAX.get(bx) as u16,
            min_y: sun::box_y::MIN.get(by) as u16,
            max_y: sun::box_y::MAX.get(by) as u16,
        };
        (sums, r(m, &sun::frames::REG))
    }

    #[test]
    fn an_armed_grouped_frame_is_the_golden_sums_and_others_leave_them() {
        let mut m = model();
        armed(&mut m);
        // Another exposure, a raw frame of the right one: not armed.
        assert!(!m.sun_armed(false, 1));
        assert!(!m.sun_armed(true, 2));
        assert!(m.sun_armed(false, 2));
        // The tag's index is three bits wide, as the descriptor's.
        assert!(m.sun_armed(false, 8 + 2));
        m.sun_frame(&words());
        let expected = accumulate(&m.sun_config(), &words());
        assert!(
            expected.count > 0 && expected.over_count == 1,
            "{expected:?}"
        );
        assert_eq!(read_sums(&mut m), (expected, 1));
        // A frame without words never begins: nothing changes.
        m.sun_frame(&[]);
        assert_eq!(read_sums(&mut m), (expected, 1));
    }

    #[test]
    fn faults_show_garbage_or_keep_the_last_frame() {
        let mut m = model();
        armed(&mut m);
        m.sun_frame(&words());
        let first = read_sums(&mut m);
        m.inject(HardwareFault::SunStale);
        m.sun_frame(&words()[..8]);
        assert_eq!(
            read_sums(&mut m),
            first,
            "stale: neither sums nor count move"
        );
        m.clear_faults();
        m.inject(HardwareFault::SunGarbage);
        let (garbage, frames) = read_sums(&mut m);
        assert_eq!(frames, 1);
        assert_eq!(garbage.count, sun::count::GROUPS.get(u32::MAX));
        assert_eq!(garbage.sum_l, u64::MAX);
        m.clear_faults();
        assert_eq!(read_sums(&mut m), first);
    }
}
