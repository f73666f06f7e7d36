//! The two arithmetic leaf cells of a slab lane, written in Verilog with a plain-Rust
//! simulation model (rust-hdl's `*` only exists for 16x16; rust-hdl-notes §2, `SubMul`).
//! Ports are unsigned `Bits` holding two's-complement values, so the simulation never goes
//! through rust-hdl's slow `Signed` arithmetic; the Verilog reinterprets them with `$signed`.

use rust_hdl::prelude::*;
use skylux_regmap::raybox_format::{
    entry_distance, exit_distance, plane_product, COORD_BITS, MANT_BITS, SHIFT_BITS, T_BITS,
};

/// Width of a plane product: a 22-bit difference times a 25-bit mantissa.
pub const PRODUCT_BITS: usize = 48;

const CB: usize = COORD_BITS as usize;
const MB: usize = MANT_BITS as usize;
const SB: usize = SHIFT_BITS as usize;
const TB: usize = T_BITS as usize;

fn sext(v: u64, bits: usize) -> i64 {
    ((v << (64 - bits)) as i64) >> (64 - bits)
}

fn bits_u64<const N: usize>(v: Bits<N>) -> u64 {
    v.to_u64()
}

/// `product = (plane - origin) × mant`, combinational: one 22x25 multiply, which yosys maps
/// to a Cyclone V DSP block (`MISTRAL_MUL27X27`).
#[derive(LogicBlock, Default)]
pub struct PlaneProduct {
    pub plane: Signal<In, Bits<CB>>,
    pub origin: Signal<In, Bits<CB>>,
    pub mant: Signal<In, Bits<MB>>,
    pub product: Signal<Out, Bits<PRODUCT_BITS>>,
}

impl Logic for PlaneProduct {
    fn update(&mut self) {
        let p = plane_product(
            sext(bits_u64(self.plane.val()), CB) as i32,
            sext(bits_u64(self.origin.val()), CB) as i32,
            sext(bits_u64(self.mant.val()), MB) as i32,
        );
        let m = (1u64 << PRODUCT_BITS) - 1;
        self.product.next = ((p as u64) & m).to_bits();
    }
    fn connect(&mut self) {
        self.product.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "wire signed [{d}:0] diff = $signed(plane) - $signed(origin);\n\
             wire signed [{p}:0] full = diff * $signed(mant);\n\
             always @(*) product = full;",
            d = CB,
            p = PRODUCT_BITS - 1,
        ))
    }
}

/// `t = saturate(product / 2^shift)`, rounded down (`CEIL = 0`, entry planes) or up
/// (`CEIL = 1`, exit planes), saturated to 32 bits. Combinational.
#[derive(LogicBlock, Default)]
pub struct PlaneDistance<const CEIL: usize> {
    pub product: Signal<In, Bits<PRODUCT_BITS>>,
    pub shift: Signal<In, Bits<SB>>,
    pub t: Signal<Out, Bits<TB>>,
}

impl<const CEIL: usize> Logic for PlaneDistance<CEIL> {
    fn update(&mut self) {
        let p = sext(bits_u64(self.product.val()), PRODUCT_BITS);
        let s = bits_u64(self.shift.val()) as u8;
        let t = if CEIL == 1 {
            exit_distance(p, s)
        } else {
            entry_distance(p, s)
        };
        self.t.next = (t as u32 as u64).to_bits();
    }
    fn connect(&mut self) {
        self.t.connect();
    }
    fn hdl(&self) -> Verilog {
        // Negating before and after an arithmetic (flooring) shift gives the ceiling. The
        // product is below 2^46 in magnitude, so the negation cannot overflow 48 bits.
        let shifted = if CEIL == 1 {
            "-((-$signed(product)) >>> shift)"
        } else {
            "$signed(product) >>> shift"
        };
        Verilog::Custom(format!(
            "wire signed [{p}:0] q = {shifted};\n\
             always @(*) begin\n\
             \x20 if (q > $signed({p1}'h7fffffff)) t = 32'h7fffffff;\n\
             \x20 else if (q < -$signed({p1}'h80000000)) t = 32'h80000000;\n\
             \x20 else t = q[31:0];\n\
             end",
            p = PRODUCT_BITS - 1,
            p1 = PRODUCT_BITS,
        ))
    }
}
