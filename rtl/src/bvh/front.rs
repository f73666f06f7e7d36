//! The f32 front end: a ray's four words to its grid form, the integer operations of
//! `skylux_regmap::bvh_format::grid_ray` (`origin_steps`, `inverse_mant_shift`,
//! `distance_steps`, the interval widened by `INTERVAL_WIDENING_STEPS` and saturated).
//! Combinational; the traversal registers its outputs when it takes a ray.

use rust_hdl::prelude::*;
use skylux_regmap::bvh_format::INTERVAL_WIDENING_STEPS;
use skylux_regmap::raybox_format::{COORD_BITS, MANT_BITS, MANT_MAX, SHIFT_BITS, T_BITS};

const CB: usize = COORD_BITS as usize;
const MB: usize = MANT_BITS as usize;
const SB: usize = SHIFT_BITS as usize;
const TB: usize = T_BITS as usize;
pub(crate) const CB3: usize = 3 * CB;
pub(crate) const MB3: usize = 3 * MB;
pub(crate) const SB3: usize = 3 * SB;
// The packing below is written for these widths.
const _: () = assert!(CB == 21 && MB == 25 && SB == 6 && TB == 32);

/// f32's hidden significand bit.
const HIDDEN_BIT: u64 = 1 << 23;

/// `origin_steps`: an origin coordinate in grid steps, truncated toward zero; `ok` low for
/// NaN, infinities and magnitudes of 256 m or more (exponent 135 and up).
#[derive(LogicBlock)]
pub struct OriginSteps {
    pub bits: Signal<In, Bits<32>>,
    pub steps: Signal<Out, Bits<CB>>,
    pub ok: Signal<Out, Bit>,
    exponent: Signal<Local, Bits<8>>,
    significand: Signal<Local, Bits<32>>,
    shift: Signal<Local, Bits<8>>,
    shifted: Signal<Local, Bits<32>>,
    magnitude: Signal<Local, Bits<CB>>,
    hidden: Constant<Bits<32>>,
    /// Value × 2^12 = significand × 2^(exponent - 138).
    bias: Constant<Bits<8>>,
}

impl Default for OriginSteps {
    fn default() -> Self {
        Self {
            bits: Default::default(),
            steps: Default::default(),
            ok: Default::default(),
            exponent: Default::default(),
            significand: Default::default(),
            shift: Default::default(),
            shifted: Default::default(),
            magnitude: Default::default(),
            hidden: Constant::new(HIDDEN_BIT.to_bits()),
            bias: Constant::new(138u64.to_bits()),
        }
    }
}

impl Logic for OriginSteps {
    #[hdl_gen]
    fn update(&mut self) {
        self.exponent.next = self.bits.val().get_bits::<8>(23);
        self.significand.next =
            bit_cast::<32, 23>(self.bits.val().get_bits::<23>(0)) | self.hidden.val();
        self.shift.next = self.bias.val() - self.exponent.val();
        self.shifted.next = self.significand.val() >> self.shift.val().get_bits::<5>(0);
        self.magnitude.next = 0.into();
        // Zero and subnormals are under one step; a shift of 32 or more leaves nothing.
        if self.exponent.val().any() & (self.shift.val() < 32) {
            self.magnitude.next = self.shifted.val().get_bits::<CB>(0);
        }
        self.steps.next = self.magnitude.val();
        if self.bits.val().get_bit(31) {
            self.steps.next = 0 - self.magnitude.val();
        }
        self.ok.next = self.exponent.val() < 135;
    }
}

/// `inverse_mant_shift`: `inv = mant × 2^-shift`, the significand and 150 - exponent;
/// magnitudes of 2^24 and more (infinity included) clamp to `MANT_MAX` with shift 0; `ok` low
/// for NaN, zero, subnormals and magnitudes under 2^-40.
#[derive(LogicBlock)]
pub struct InverseMantShift {
    pub bits: Signal<In, Bits<32>>,
    pub mant: Signal<Out, Bits<MB>>,
    pub shift: Signal<Out, Bits<SB>>,
    pub ok: Signal<Out, Bit>,
    exponent: Signal<Local, Bits<8>>,
    magnitude: Signal<Local, Bits<MB>>,
    right_shift: Signal<Local, Bits<8>>,
    hidden: Constant<Bits<MB>>,
    mant_max: Constant<Bits<MB>>,
    bias: Constant<Bits<8>>,
}

impl Default for InverseMantShift {
    fn default() -> Self {
        Self {
            bits: Default::default(),
            mant: Default::default(),
            shift: Default::default(),
            ok: Default::default(),
            exponent: Default::default(),
            magnitude: Default::default(),
            right_shift: Default::default(),
            hidden: Constant::new(HIDDEN_BIT.to_bits()),
            mant_max: Constant::new((MANT_MAX as u64).to_bits()),
            bias: Constant::new(150u64.to_bits()),
        }
    }
}

impl Logic for InverseMantShift {
    #[hdl_gen]
    fn update(&mut self) {
        self.exponent.next = self.bits.val().get_bits::<8>(23);
        self.right_shift.next = self.bias.val() - self.exponent.val();
        self.magnitude.next =
            bit_cast::<MB, 23>(self.bits.val().get_bits::<23>(0)) | self.hidden.val();
        self.shift.next = self.right_shift.val().get_bits::<SB>(0);
        if self.exponent.val() > 150 {
            self.magnitude.next = self.mant_max.val();
            self.shift.next = 0.into();
        }
        self.mant.next = self.magnitude.val();
        if self.bits.val().get_bit(31) {
            self.mant.next = 0 - self.magnitude.val();
        }
        self.ok.next = (self.exponent.val() >= 87)
            & !((self.exponent.val() == 255) & self.bits.val().get_bits::<23>(0).any());
    }
}

/// `distance_steps`: a distance in grid steps, truncated toward zero and saturated to 32
/// bits (infinities saturate); `ok` low for NaN.
#[derive(LogicBlock)]
pub struct DistanceSteps {
    pub bits: Signal<In, Bits<32>>,
    pub steps: Signal<Out, Bits<TB>>,
    pub ok: Signal<Out, Bit>,
    exponent: Signal<Local, Bits<8>>,
    significand: Signal<Local, Bits<32>>,
    left_shift: Signal<Local, Bits<8>>,
    right_shift: Signal<Local, Bits<8>>,
    magnitude: Signal<Local, Bits<32>>,
    hidden: Constant<Bits<32>>,
    bias: Constant<Bits<8>>,
    largest: Constant<Bits<32>>,
}

impl Default for DistanceSteps {
    fn default() -> Self {
        Self {
            bits: Default::default(),
            steps: Default::default(),
            ok: Default::default(),
            exponent: Default::default(),
            significand: Default::default(),
            left_shift: Default::default(),
            right_shift: Default::default(),
            magnitude: Default::default(),
            hidden: Constant::new(HIDDEN_BIT.to_bits()),
            bias: Constant::new(138u64.to_bits()),
            largest: Constant::new((i32::MAX as u64).to_bits()),
        }
    }
}

impl Logic for DistanceSteps {
    #[hdl_gen]
    fn update(&mut self) {
        self.exponent.next = self.bits.val().get_bits::<8>(23);
        self.significand.next =
            bit_cast::<32, 23>(self.bits.val().get_bits::<23>(0)) | self.hidden.val();
        self.left_shift.next = self.exponent.val() - self.bias.val();
        self.right_shift.next = self.bias.val() - self.exponent.val();
        // 2^31 steps or more (exponent 145 and up) saturate; 2^-20 steps and less
        // (exponent 106 and down, zero included) truncate to 0.
        if self.exponent.val() >= 145 {
            self.magnitude.next = self.largest.val();
        } else if self.exponent.val() >= 138 {
            self.magnitude.next = self.significand.val() << self.left_shift.val().get_bits::<3>(0);
        } else if self.exponent.val() <= 106 {
            self.magnitude.next = 0.into();
        } else {
            self.magnitude.next = self.significand.val() >> self.right_shift.val().get_bits::<5>(0);
        }
        self.steps.next = self.magnitude.val();
        if self.bits.val().get_bit(31) {
            self.steps.next = 0 - self.magnitude.val();
        }
        self.ok.next = !((self.exponent.val() == 255) & self.bits.val().get_bits::<23>(0).any());
    }
}

/// The whole front end: the ray's words in, its grid form out, per-axis fields packed x, y, z
/// from bit 0 as the slab lane takes them.
#[derive(LogicBlock)]
pub struct RayFrontEnd {
    pub word0: Signal<In, Bits<64>>,
    pub word1: Signal<In, Bits<64>>,
    pub word2: Signal<In, Bits<64>>,
    pub word3: Signal<In, Bits<64>>,
    pub origin: Signal<Out, Bits<CB3>>,
    pub mant: Signal<Out, Bits<MB3>>,
    pub shift: Signal<Out, Bits<SB3>>,
    pub t_min: Signal<Out, Bits<TB>>,
    pub t_max: Signal<Out, Bits<TB>>,
    /// Per axis, 21 ones where the mantissa is positive: there the entry plane is the box's
    /// lower corner (`child_test`).
    pub lower_is_entry: Signal<Out, Bits<CB3>>,
    /// Every field fits the grid (`grid_ray` is `Some`).
    pub representable: Signal<Out, Bit>,

    origin_steps: [OriginSteps; 3],
    inverse: [InverseMantShift; 3],
    t_min_steps: DistanceSteps,
    t_max_steps: DistanceSteps,
    sign: Constant<Bits<TB>>,
    widening: Constant<Bits<TB>>,
    /// The smallest `t_min` before widening that does not saturate: i32::MIN + 2.
    t_min_floor: Constant<Bits<TB>>,
    /// The largest `t_max` before widening that does not saturate: i32::MAX - 2.
    t_max_ceiling: Constant<Bits<TB>>,
    axis_mask: [Constant<Bits<CB3>>; 3],
}

impl Default for RayFrontEnd {
    fn default() -> Self {
        let w = INTERVAL_WIDENING_STEPS;
        Self {
            word0: Default::default(),
            word1: Default::default(),
            word2: Default::default(),
            word3: Default::default(),
            origin: Default::default(),
            mant: Default::default(),
            shift: Default::default(),
            t_min: Default::default(),
            t_max: Default::default(),
            lower_is_entry: Default::default(),
            representable: Default::default(),
            origin_steps: Default::default(),
            inverse: Default::default(),
            t_min_steps: Default::default(),
            t_max_steps: Default::default(),
            sign: Constant::new((1u64 << (TB - 1)).to_bits()),
            widening: Constant::new((w as u64).to_bits()),
            t_min_floor: Constant::new(((i32::MIN as i64 + w) as u32 as u64).to_bits()),
            t_max_ceiling: Constant::new(((i32::MAX as i64 - w) as u32 as u64).to_bits()),
            axis_mask: std::array::from_fn(|a| {
                Constant::new((((1u64 << CB) - 1) << (CB * a)).to_bits())
            }),
        }
    }
}

impl Logic for RayFrontEnd {
    #[hdl_gen]
    fn update(&mut self) {
        // Fields: origin x, y, z, inverse x, y, z, t_min, t_max (`ray_fields`).
        self.origin_steps[0].bits.next = self.word0.val().get_bits::<32>(0);
        self.origin_steps[1].bits.next = self.word0.val().get_bits::<32>(32);
        self.origin_steps[2].bits.next = self.word1.val().get_bits::<32>(0);
        self.inverse[0].bits.next = self.word1.val().get_bits::<32>(32);
        self.inverse[1].bits.next = self.word2.val().get_bits::<32>(0);
        self.inverse[2].bits.next = self.word2.val().get_bits::<32>(32);
        self.t_min_steps.bits.next = self.word3.val().get_bits::<32>(0);
        self.t_max_steps.bits.next = self.word3.val().get_bits::<32>(32);

        self.origin.next = bit_cast::<CB3, CB>(self.origin_steps[0].steps.val())
            | (bit_cast::<CB3, CB>(self.origin_steps[1].steps.val()) << 21)
            | (bit_cast::<CB3, CB>(self.origin_steps[2].steps.val()) << 42);
        self.mant.next = bit_cast::<MB3, MB>(self.inverse[0].mant.val())
            | (bit_cast::<MB3, MB>(self.inverse[1].mant.val()) << 25)
            | (bit_cast::<MB3, MB>(self.inverse[2].mant.val()) << 50);
        self.shift.next = bit_cast::<SB3, SB>(self.inverse[0].shift.val())
            | (bit_cast::<SB3, SB>(self.inverse[1].shift.val()) << 6)
            | (bit_cast::<SB3, SB>(self.inverse[2].shift.val()) << 12);
        self.lower_is_entry.next = 0.into();
        for a in 0..3 {
            if !self.inverse[a].mant.val().get_bit(24) {
                self.lower_is_entry.next = self.lower_is_entry.val() | self.axis_mask[a].val();
            }
        }

        // Widened by INTERVAL_WIDENING_STEPS each way, saturated (signed compares flip the
        // sign bit: rust-hdl-notes §3).
        self.t_min.next = self.t_min_steps.steps.val() - self.widening.val();
        if (self.t_min_steps.steps.val() ^ self.sign.val())
            < (self.t_min_floor.val() ^ self.sign.val())
        {
            self.t_min.next = self.sign.val();
        }
        self.t_max.next = self.t_max_steps.steps.val() + self.widening.val();
        if (self.t_max_steps.steps.val() ^ self.sign.val())
            > (self.t_max_ceiling.val() ^ self.sign.val())
        {
            self.t_max.next = !self.sign.val();
        }

        self.representable.next = self.origin_steps[0].ok.val()
            & self.origin_steps[1].ok.val()
            & self.origin_steps[2].ok.val()
            & self.inverse[0].ok.val()
            & self.inverse[1].ok.val()
            & self.inverse[2].ok.val()
            & self.t_min_steps.ok.val()
            & self.t_max_steps.ok.val();
    }
}
