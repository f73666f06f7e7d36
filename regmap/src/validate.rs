//! Checks that the map is self-consistent: the register file generator and every consumer rely
//! on these invariants.

use crate::{Block, BLOCK_SPAN_BYTES, LW_BRIDGE_SPAN_BYTES, MAP};
use alloc::{format, string::String, vec::Vec};

/// A rule of the layout that the map breaks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutError(pub String);

impl core::fmt::Display for LayoutError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Validates [`MAP`]: every error found, not just the first.
pub fn validate() -> Result<(), Vec<LayoutError>> {
    validate_blocks(MAP)
}

/// Validates any list of blocks (used on deliberately broken maps in tests).
pub fn validate_blocks(blocks: &[Block]) -> Result<(), Vec<LayoutError>> {
    let mut errors = Vec::new();
    let mut fail = |message: String| errors.push(LayoutError(message));
    for (i, block) in blocks.iter().enumerate() {
        if block.base % BLOCK_SPAN_BYTES != 0 || block.base >= LW_BRIDGE_SPAN_BYTES {
            fail(format!(
                "block {} base {:#x} is not a page inside the window",
                block.name, block.base
            ));
        }
        if blocks[..i]
            .iter()
            .any(|b| b.name == block.name || b.base == block.base)
        {
            fail(format!(
                "block {} repeats the name or base of another block",
                block.name
            ));
        }
        for (j, reg) in block.registers.iter().enumerate() {
            let end = reg.offset as u64 + 4 * reg.count as u64;
            if reg.offset % 4 != 0 {
                fail(format!(
                    "{}.{} offset {:#x} is not word aligned",
                    block.name, reg.name, reg.offset
                ));
            }
            if reg.count == 0 {
                fail(format!("{}.{} has an empty array", block.name, reg.name));
            }
            if reg.offset < block.base || end > (block.base + BLOCK_SPAN_BYTES) as u64 {
                fail(format!(
                    "{}.{} lies outside its block's page",
                    block.name, reg.name
                ));
            }
            for other in &block.registers[..j] {
                let other_end = other.offset as u64 + 4 * other.count as u64;
                if (reg.offset as u64) < other_end && (other.offset as u64) < end {
                    fail(format!(
                        "{}.{} overlaps {}.{}",
                        block.name, reg.name, block.name, other.name
                    ));
                }
                if other.name == reg.name {
                    fail(format!("{}.{} is defined twice", block.name, reg.name));
                }
            }
            if reg.fields.is_empty() {
                fail(format!("{}.{} has no field", block.name, reg.name));
            }
            let mut used = 0u64;
            for (k, field) in reg.fields.iter().enumerate() {
                let name = format!("{}.{}.{}", block.name, reg.name, field.name);
                if field.width == 0 || field.lsb + field.width > 32 {
                    fail(format!("{name} does not fit in 32 bits"));
                    continue;
                }
                if used & field.mask() as u64 != 0 {
                    fail(format!("{name} overlaps another field"));
                }
                used |= field.mask() as u64;
                if !field.fits(field.reset) {
                    fail(format!(
                        "{name} reset value {:#x} does not fit its width",
                        field.reset
                    ));
                }
                if reg.fields[..k].iter().any(|f| f.name == field.name) {
                    fail(format!("{name} is defined twice"));
                }
            }
        }
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors)
    }
}
