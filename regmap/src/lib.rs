//! The Skylux register map: the one place where a register offset, a field position, an access
//! type or a reset value is written.
//!
//! Everything else derives from it:
//! - `skylux-rtl` generates the rust-hdl register file (and so its Verilog) from [`MAP`] in its
//!   build script;
//! - the HPS drivers and the simulator address registers through the constants here
//!   (`skylux_regmap::sys::id::REG.offset`, `skylux_regmap::seq::ctrl::START.mask()`);
//! - [`render::markdown`] and [`render::c_header`] render `docs/registers.md` and
//!   `regmap/include/skylux_regs.h`; a test fails when the checked-in copies are stale.
//!
//! The map sits behind the Cyclone V lightweight HPS-to-FPGA bridge
//! (hardware-facts.md §0 item 4: 0xFF200000-0xFF3FFFFF, 2 MB, 32-bit). Each block owns a
//! 4 KiB page so that a driver could map one block alone.

#![no_std]
#![forbid(unsafe_code)]

extern crate alloc;

pub mod bvh_format;
pub mod descriptor;
pub mod hdr_values;
mod map;
pub mod raybox_format;
pub mod render;
pub mod sun_values;
mod validate;
pub mod words;

pub use map::*;
pub use validate::{validate, validate_blocks, LayoutError};

/// Physical base of the lightweight HPS-to-FPGA bridge window
/// (Cyclone V HPS TRM "MPU Address Space"; hardware-facts.md §3.1).
pub const LW_BRIDGE_PHYS_BASE: u32 = 0xFF20_0000;
/// Size of the lightweight bridge window in bytes (2 MB, 21-bit byte address).
pub const LW_BRIDGE_SPAN_BYTES: u32 = 0x0020_0000;
/// Width of the Avalon-MM agent's word address: the whole 2 MB window in 32-bit words, so that
/// every address the bridge can emit is decoded (unmapped ones included).
pub const AVALON_WORD_ADDRESS_BITS: usize = 19;
/// Each register block owns one page of this many bytes.
pub const BLOCK_SPAN_BYTES: u32 = 0x1000;
/// What a read of an unmapped address returns. The access also sets `sys.bus_status`.
pub const UNMAPPED_READ_VALUE: u32 = 0xDEAD_BEEF;
/// Read latency of the register file's Avalon-MM agent, in clock cycles (`readLatency` in the
/// Platform Designer component). Fixed, so the bus can never hang on a register read.
pub const READ_LATENCY_CYCLES: usize = 1;
/// Nominal frequency of the fabric's system clock, the clock of the register file, the DMA
/// engine and the ray-box unit (also readable at `sys.clock_hz`).
pub const SYS_CLOCK_HZ: u32 = 100_000_000;

/// How software and hardware may access a field.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Access {
    /// Read/write by software; the fabric sees the current value.
    RW,
    /// Read-only for software; the fabric drives the value.
    RO,
    /// Read-only constant: always reads as its reset value.
    Const,
    /// Sticky status: the fabric sets bits with a one-cycle pulse, software clears a bit by
    /// writing 1 to it. Writing 0 has no effect.
    W1C,
    /// Command: writing 1 gives the fabric a one-cycle pulse. Reads as 0.
    W1P,
}

impl Access {
    /// Short name used in documentation and the C header.
    pub const fn code(self) -> &'static str {
        match self {
            Access::RW => "RW",
            Access::RO => "RO",
            Access::Const => "CONST",
            Access::W1C => "W1C",
            Access::W1P => "W1P",
        }
    }
    /// Whether a software write can change what the field holds.
    pub const fn is_writable(self) -> bool {
        matches!(self, Access::RW | Access::W1C | Access::W1P)
    }
}

/// A bit field of a register.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Field {
    pub name: &'static str,
    /// Position of the least-significant bit.
    pub lsb: u32,
    /// Width in bits (1 to 32).
    pub width: u32,
    pub access: Access,
    /// Value after power-up (and the constant value of [`Access::Const`] fields).
    pub reset: u32,
    pub doc: &'static str,
}

impl Field {
    /// Mask of the field's bits at their position in the register.
    pub const fn mask(&self) -> u32 {
        self.value_mask() << self.lsb
    }
    /// Mask of the field's value when right-aligned.
    pub const fn value_mask(&self) -> u32 {
        if self.width >= 32 {
            u32::MAX
        } else {
            (1u32 << self.width) - 1
        }
    }
    /// The field's value in a register word.
    pub const fn get(&self, register: u32) -> u32 {
        (register >> self.lsb) & self.value_mask()
    }
    /// `register` with this field replaced by `value` (truncated to the field's width).
    pub const fn set(&self, register: u32, value: u32) -> u32 {
        (register & !self.mask()) | ((value & self.value_mask()) << self.lsb)
    }
    /// A register word holding only this field at `value`.
    pub const fn word(&self, value: u32) -> u32 {
        self.set(0, value)
    }
    /// Whether `value` fits in the field.
    pub const fn fits(&self, value: u32) -> bool {
        value & !self.value_mask() == 0
    }
}

/// A 32-bit register, or an array of `count` registers at consecutive word offsets.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Register {
    pub name: &'static str,
    /// Byte offset of the (first) register in the lightweight bridge window.
    pub offset: u32,
    /// Number of registers in the array (1 for a plain register). Element `i` is at
    /// `offset + 4 i`.
    pub count: u32,
    pub fields: &'static [Field],
    pub doc: &'static str,
}

impl Register {
    /// Byte offset of array element `index` in the lightweight bridge window, or `None` when
    /// the index is out of range.
    pub const fn offset_of(&self, index: u32) -> Option<u32> {
        if index < self.count {
            Some(self.offset + 4 * index)
        } else {
            None
        }
    }
    /// Word address (as the Avalon-MM agent sees it) of element `index`.
    pub const fn word_address(&self, index: u32) -> u32 {
        (self.offset + 4 * index) / 4
    }
    /// Value of the whole register after reset.
    pub const fn reset_value(&self) -> u32 {
        let mut value = 0;
        let mut i = 0;
        while i < self.fields.len() {
            value = self.fields[i].set(value, self.fields[i].reset);
            i += 1;
        }
        value
    }
    /// Bits that software can change by writing.
    pub const fn writable_mask(&self) -> u32 {
        let mut mask = 0;
        let mut i = 0;
        while i < self.fields.len() {
            if self.fields[i].access.is_writable() {
                mask |= self.fields[i].mask();
            }
            i += 1;
        }
        mask
    }
    /// Looks a field up by name.
    pub fn field(&self, name: &str) -> Option<&'static Field> {
        self.fields.iter().find(|f| f.name == name)
    }
}

/// A block of registers owning one [`BLOCK_SPAN_BYTES`] page.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Block {
    pub name: &'static str,
    /// Byte offset of the block's page in the lightweight bridge window.
    pub base: u32,
    pub registers: &'static [Register],
    pub doc: &'static str,
}

impl Block {
    /// Looks a register up by name.
    pub fn register(&self, name: &str) -> Option<&'static Register> {
        self.registers.iter().find(|r| r.name == name)
    }
}

/// Where a byte offset in the window lands.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Location {
    pub block: &'static Block,
    pub register: &'static Register,
    /// Array element (0 for a plain register).
    pub index: u32,
}

/// Finds the register at a byte offset of the lightweight bridge window, if any.
pub fn locate(offset: u32) -> Option<Location> {
    if !offset.is_multiple_of(4) {
        return None;
    }
    MAP.iter().find_map(|block| {
        block.registers.iter().find_map(|register| {
            let end = register.offset + 4 * register.count;
            (offset >= register.offset && offset < end).then(|| Location {
                block,
                register,
                index: (offset - register.offset) / 4,
            })
        })
    })
}

/// Every register (array element by element) with its value after reset, in offset order.
/// A file written from this image is a faithful snapshot of a freshly configured device.
pub fn reset_image() -> alloc::vec::Vec<(u32, u32)> {
    let mut image = alloc::vec::Vec::new();
    for block in MAP {
        for register in block.registers {
            for index in 0..register.count {
                image.push((register.offset + 4 * index, register.reset_value()));
            }
        }
    }
    image.sort_unstable();
    image
}

/// Defines one register block as nested modules of constants:
/// `block::BASE`, `block::BLOCK`, `block::register::REG` and `block::register::FIELD`.
macro_rules! register_block {
    (
        $(#[doc = $bdoc:literal])*
        $blk:ident @ $base:literal {
            $(
                $(#[doc = $rdoc:literal])*
                $reg:ident $([$count:literal])? @ $off:literal {
                    $(
                        $(#[doc = $fdoc:literal])*
                        $fld:ident [$lsb:literal +: $width:literal] $acc:ident = $reset:expr;
                    )*
                }
            )*
        }
    ) => {
        $(#[doc = $bdoc])*
        pub mod $blk {
            #[allow(unused_imports)]
            use $crate::{Access, Block, Field, Register};
            /// Byte offset of this block's page in the lightweight bridge window.
            pub const BASE: u32 = $base;
            $(
                $(#[doc = $rdoc])*
                pub mod $reg {
                    #[allow(unused_imports)]
                    use super::*;
                    $(
                        $(#[doc = $fdoc])*
                        pub const $fld: Field = Field {
                            name: stringify!($fld),
                            lsb: $lsb,
                            width: $width,
                            access: Access::$acc,
                            reset: $reset,
                            doc: concat!($($fdoc),*),
                        };
                    )*
                    /// The register itself.
                    pub const REG: Register = Register {
                        name: stringify!($reg),
                        offset: BASE + $off,
                        count: { #[allow(unused_variables)] let c: u32 = 1; $(let c: u32 = $count;)? c },
                        fields: &[$($fld),*],
                        doc: concat!($($rdoc),*),
                    };
                }
            )*
            /// The block with all its registers.
            pub const BLOCK: Block = Block {
                name: stringify!($blk),
                base: BASE,
                registers: &[$($reg::REG),*],
                doc: concat!($($bdoc),*),
            };
        }
    };
}
pub(crate) use register_block;
