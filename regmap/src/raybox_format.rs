//! The ray-box unit's memory formats and its bit-exact golden model: a hardware/software
//! contract like the register map, written here once for the RTL (`skylux_rtl::raybox`), the
//! simulator and the HPS (`skylux_hps::fpga::raybox`, `skylux_hps::engine::accel`).
//!
//! # Number format (error analysis in ARCHITECTURE.md, "Ray-box unit")
//!
//! - Coordinates: signed fixed point, [`COORD_BITS`] = 21 bits with [`COORD_FRAC_BITS`] = 12
//!   fractional bits of a metre: a grid of 2^-12 m (0.244 mm) over ±256 m, so a 100 m scene
//!   fits anywhere in the range and a 1 mm box spans 4 grid steps.
//! - Distances along the ray (`t`): signed 32 bits on the same 2^-12 grid.
//! - Inverse direction: per axis a signed 25-bit mantissa and a 6-bit right shift,
//!   `inv = mant × 2^-shift`, so the relative error is at most 2^-24 for every direction,
//!   grazing ones included (a fixed-point inverse would need about 42 bits for the same).
//!
//! The unit computes, exactly in integers, per axis
//! `entry = floor((entry_plane - origin) × mant / 2^shift)` and
//! `exit = ceil((exit_plane - origin) × mant / 2^shift)`, each saturated to 32 bits, then
//! `t_near = max(entry_x, entry_y, entry_z, t_min)`, `t_far = min(exit_x, exit_y, exit_z,
//! t_max)` and `hit = t_near <= t_far`. The HPS puts the plane the ray meets first in
//! `entry_plane` (the box minimum when the mantissa is positive, the maximum otherwise) and
//! quantises outward, so the test is conservative (see `skylux_hps::engine::accel`).
//!
//! # Work items and results in memory
//!
//! A batch is `raybox.work_count` work items of [`ITEM_WORDS`] little-endian 64-bit words at
//! `raybox.work_base`, and as many result words at `raybox.result_base`:
//!
//! ```text
//! word 0  [20:0] origin x   [41:21] origin y   [62:42] origin z   [63] 0
//! word 1  [20:0] entry x    [41:21] entry y    [62:42] entry z    [63] 0
//! word 2  [20:0] exit x     [41:21] exit y     [62:42] exit z     [63] 0
//! word 3  [24:0] mant x     [49:25] mant y     [55:50] shift x    [61:56] shift y  [63:62] 0
//! word 4  [31:0] t_min      [63:32] t_max
//! word 5  [24:0] mant z     [30:25] shift z    [55:31] 0          [63:56] ITEM_MAGIC
//!
//! result  [31:0] t_near     [55:32] item index [62:56] 0          [63] hit
//! ```
//!
//! The unit refuses an item whose magic byte is wrong (`raybox.status.BAD_DESCRIPTOR`): the
//! batch stops there, and the results of the items before it are written.

/// Width of a coordinate (signed).
pub const COORD_BITS: u32 = 21;
/// Fractional bits of a coordinate and of a distance, in metres.
pub const COORD_FRAC_BITS: u32 = 12;
/// Width of an inverse-direction mantissa (signed).
pub const MANT_BITS: u32 = 25;
/// Width of an inverse-direction shift (unsigned).
pub const SHIFT_BITS: u32 = 6;
/// Width of a distance (signed).
pub const T_BITS: u32 = 32;
/// 64-bit words per work item.
pub const ITEM_WORDS: usize = 6;
/// Bytes per work item.
pub const ITEM_BYTES: u32 = 8 * ITEM_WORDS as u32;
/// Bytes per result.
pub const RESULT_BYTES: u32 = 8;
/// The byte a valid work item carries in bits [63:56] of its last word.
pub const ITEM_MAGIC: u8 = 0xB7;
/// Version of the formats above, readable at `raybox.info.FORMAT`.
pub const FORMAT_VERSION: u32 = 1;
/// Width of the item index in a result word (and of `raybox.work_count`).
pub const INDEX_BITS: u32 = 24;

/// Smallest coordinate.
pub const COORD_MIN: i32 = -(1 << (COORD_BITS - 1));
/// Largest coordinate.
pub const COORD_MAX: i32 = (1 << (COORD_BITS - 1)) - 1;
/// Smallest mantissa.
pub const MANT_MIN: i32 = -(1 << (MANT_BITS - 1));
/// Largest mantissa.
pub const MANT_MAX: i32 = (1 << (MANT_BITS - 1)) - 1;
/// Largest shift.
pub const SHIFT_MAX: u8 = (1 << SHIFT_BITS) - 1;
/// Metres per coordinate (and distance) step.
pub const METRES_PER_STEP: f64 = 1.0 / (1u32 << COORD_FRAC_BITS) as f64;

/// Bit position of the hit flag in a result word.
pub const RESULT_HIT_BIT: u32 = 63;
/// Position of the item index in a result word.
pub const RESULT_INDEX_LSB: u32 = 32;

/// One ray-box test in integer form, exactly as the unit reads it.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct WorkItem {
    /// Ray origin, [`COORD_BITS`] signed.
    pub origin: [i32; 3],
    /// Per axis, the box plane the ray crosses first, [`COORD_BITS`] signed.
    pub entry_plane: [i32; 3],
    /// Per axis, the box plane the ray crosses last, [`COORD_BITS`] signed.
    pub exit_plane: [i32; 3],
    /// Inverse-direction mantissas, [`MANT_BITS`] signed.
    pub mant: [i32; 3],
    /// Inverse-direction right shifts, [`SHIFT_BITS`] unsigned.
    pub shift: [u8; 3],
    /// Interval of interest along the ray.
    pub t_min: i32,
    pub t_max: i32,
}

/// The unit's answer for one item.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct TestResult {
    pub hit: bool,
    /// Entry distance (`max` of the entry distances and `t_min`), on the 2^-12 m grid.
    pub t_near: i32,
}

pub(crate) const fn mask(bits: u32) -> u64 {
    (1u64 << bits) - 1
}

/// Sign-extends the low `bits` bits of `v`.
pub(crate) const fn sext(v: u64, bits: u32) -> i32 {
    (((v & mask(bits)) << (64 - bits)) as i64 >> (64 - bits)) as i32
}

pub(crate) const fn three(v: [i32; 3]) -> u64 {
    (v[0] as u64 & mask(COORD_BITS))
        | ((v[1] as u64 & mask(COORD_BITS)) << COORD_BITS)
        | ((v[2] as u64 & mask(COORD_BITS)) << (2 * COORD_BITS))
}

pub(crate) const fn unthree(w: u64) -> [i32; 3] {
    [
        sext(w, COORD_BITS),
        sext(w >> COORD_BITS, COORD_BITS),
        sext(w >> (2 * COORD_BITS), COORD_BITS),
    ]
}

impl WorkItem {
    /// The item's six memory words. Every field is truncated to its width, so any value packs
    /// (an out-of-range value wraps; `unpack(pack(x)) == x` for in-range fields).
    pub const fn pack(&self) -> [u64; ITEM_WORDS] {
        let m = mask(MANT_BITS);
        let s = mask(SHIFT_BITS);
        [
            three(self.origin),
            three(self.entry_plane),
            three(self.exit_plane),
            (self.mant[0] as u64 & m)
                | ((self.mant[1] as u64 & m) << 25)
                | ((self.shift[0] as u64 & s) << 50)
                | ((self.shift[1] as u64 & s) << 56),
            (self.t_min as u32 as u64) | ((self.t_max as u32 as u64) << 32),
            (self.mant[2] as u64 & m)
                | ((self.shift[2] as u64 & s) << 25)
                | ((ITEM_MAGIC as u64) << 56),
        ]
    }

    /// Reads an item from its words, as the unit does; `None` when the magic byte is wrong.
    pub const fn unpack(words: &[u64; ITEM_WORDS]) -> Option<WorkItem> {
        if (words[5] >> 56) as u8 != ITEM_MAGIC {
            return None;
        }
        let s = mask(SHIFT_BITS);
        Some(WorkItem {
            origin: unthree(words[0]),
            entry_plane: unthree(words[1]),
            exit_plane: unthree(words[2]),
            mant: [
                sext(words[3], MANT_BITS),
                sext(words[3] >> 25, MANT_BITS),
                sext(words[5], MANT_BITS),
            ],
            shift: [
                ((words[3] >> 50) & s) as u8,
                ((words[3] >> 56) & s) as u8,
                ((words[5] >> 25) & s) as u8,
            ],
            t_min: words[4] as u32 as i32,
            t_max: (words[4] >> 32) as u32 as i32,
        })
    }
}

/// Saturates to the 32-bit distance range.
const fn saturate(v: i64) -> i32 {
    if v > i32::MAX as i64 {
        i32::MAX
    } else if v < i32::MIN as i64 {
        i32::MIN
    } else {
        v as i32
    }
}

/// `(plane - origin) × mant`: below 2^45 in magnitude for in-range fields, so exact in i64.
pub const fn plane_product(plane: i32, origin: i32, mant: i32) -> i64 {
    (plane as i64 - origin as i64) * mant as i64
}

/// The distance to an entry plane: the product shifted right, rounded down, saturated.
pub const fn entry_distance(product: i64, shift: u8) -> i32 {
    saturate(product >> (shift & SHIFT_MAX))
}

/// The distance to an exit plane: the product shifted right, rounded up, saturated.
pub const fn exit_distance(product: i64, shift: u8) -> i32 {
    saturate(-((-product) >> (shift & SHIFT_MAX)))
}

/// The golden model: what the unit answers for one item, bit for bit.
pub const fn test(item: &WorkItem) -> TestResult {
    let mut t_near = item.t_min;
    let mut t_far = item.t_max;
    let mut axis = 0;
    while axis < 3 {
        let e = entry_distance(
            plane_product(item.entry_plane[axis], item.origin[axis], item.mant[axis]),
            item.shift[axis],
        );
        let x = exit_distance(
            plane_product(item.exit_plane[axis], item.origin[axis], item.mant[axis]),
            item.shift[axis],
        );
        if e > t_near {
            t_near = e;
        }
        if x < t_far {
            t_far = x;
        }
        axis += 1;
    }
    TestResult {
        hit: t_near <= t_far,
        t_near,
    }
}

/// Packs a result word.
pub const fn pack_result(index: u32, result: TestResult) -> u64 {
    (result.t_near as u32 as u64)
        | (((index as u64) & mask(INDEX_BITS)) << RESULT_INDEX_LSB)
        | ((result.hit as u64) << RESULT_HIT_BIT)
}

/// Reads a result word: (item index, result).
pub const fn unpack_result(word: u64) -> (u32, TestResult) {
    (
        ((word >> RESULT_INDEX_LSB) & mask(INDEX_BITS)) as u32,
        TestResult {
            hit: (word >> RESULT_HIT_BIT) & 1 == 1,
            t_near: word as u32 as i32,
        },
    )
}

/// The result word the unit writes for item `index` given its memory words, or `None` for a
/// refused item (wrong magic byte).
pub const fn result_word(index: u32, words: &[u64; ITEM_WORDS]) -> Option<u64> {
    match WorkItem::unpack(words) {
        Some(item) => Some(pack_result(index, test(&item))),
        None => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn item() -> WorkItem {
        WorkItem {
            origin: [COORD_MIN, -1, COORD_MAX],
            entry_plane: [5, COORD_MAX, -7],
            exit_plane: [0, 1, COORD_MIN],
            mant: [MANT_MIN, MANT_MAX, -3],
            shift: [0, SHIFT_MAX, 17],
            t_min: i32::MIN,
            t_max: 123_456,
        }
    }

    #[test]
    fn pack_round_trip_and_magic() {
        let i = item();
        let mut w = i.pack();
        assert_eq!(WorkItem::unpack(&w), Some(i));
        assert_eq!(w[5] >> 56, 0xB7);
        assert_eq!(w[0] >> 63, 0, "reserved bit");
        w[5] ^= 1 << 60;
        assert_eq!(WorkItem::unpack(&w), None);
        assert_eq!(result_word(3, &w), None);
    }

    #[test]
    fn hand_computed_axis_aligned_hit() {
        // Origin 0, direction +x (mant 2^23, shift 23: inv = 1), box x in [4, 8], y, z in
        // [-1, 1] steps: the ray enters at 4 and leaves at 8.
        let one = (1 << 23, 23u8);
        let big = (MANT_MAX, 0u8); // y and z: direction ~0, inverse clamped
        let i = WorkItem {
            origin: [0, 0, 0],
            entry_plane: [4, -1, -1],
            exit_plane: [8, 1, 1],
            mant: [one.0, big.0, big.0],
            shift: [one.1, big.1, big.1],
            t_min: 0,
            t_max: 1000,
        };
        assert_eq!(
            test(&i),
            TestResult {
                hit: true,
                t_near: 4
            }
        );
        // Beyond t_max, or with the origin moved off the slab in y: a miss.
        assert!(!test(&WorkItem { t_max: 3, ..i }).hit);
        assert!(
            !test(&WorkItem {
                origin: [0, 2, 0],
                ..i
            })
            .hit
        );
    }

    #[test]
    fn rounding_is_outward_and_saturates() {
        // 7 × 1 / 2 = 3.5: entry rounds down to 3, exit up to 4; negative: -3.5 -> -4, -3.
        assert_eq!(entry_distance(7, 1), 3);
        assert_eq!(exit_distance(7, 1), 4);
        assert_eq!(entry_distance(-7, 1), -4);
        assert_eq!(exit_distance(-7, 1), -3);
        assert_eq!(entry_distance(1 << 40, 0), i32::MAX);
        assert_eq!(exit_distance(-(1 << 40), 0), i32::MIN);
        assert_eq!(entry_distance(-1, 63), -1);
        assert_eq!(exit_distance(-1, 63), 0);
    }

    #[test]
    fn result_round_trip() {
        let r = TestResult {
            hit: true,
            t_near: -5,
        };
        let w = pack_result(0x12_3456, r);
        assert_eq!(w, 0x8012_3456_FFFF_FFFB);
        assert_eq!(unpack_result(w), (0x12_3456, r));
    }
}
