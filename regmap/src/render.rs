//! Renders the map for people (`docs/registers.md`) and for C code (`skylux_regs.h`, for
//! U-Boot scripts and bare-metal users). The checked-in copies are compared with these renders
//! by `cargo test -p skylux-regmap`.

use crate::{Access, Block, Register, LW_BRIDGE_PHYS_BASE, LW_BRIDGE_SPAN_BYTES, MAP};
use crate::{DESIGN_ID, READ_LATENCY_CYCLES, UNMAPPED_READ_VALUE, VERSION_MAJOR, VERSION_MINOR};
use alloc::string::String;
use core::fmt::Write;

/// Path of the rendered Markdown, relative to the repository root.
pub const MARKDOWN_PATH: &str = "docs/registers.md";
/// Path of the rendered C header, relative to the repository root.
pub const C_HEADER_PATH: &str = "regmap/include/skylux_regs.h";

fn doc_line(doc: &str) -> String {
    doc.split_whitespace()
        .collect::<alloc::vec::Vec<_>>()
        .join(" ")
}

fn bits(lsb: u32, width: u32) -> String {
    if width == 1 {
        alloc::format!("{lsb}")
    } else {
        alloc::format!("{}:{}", lsb + width - 1, lsb)
    }
}

/// The map as Markdown.
pub fn markdown() -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# Skylux register map v{VERSION_MAJOR}.{VERSION_MINOR}\n"
    );
    let _ = writeln!(
        out,
        "Generated from `regmap/src/map.rs` by `skylux-regmap`; do not edit. Regenerate with \
         `SKYLUX_BLESS=1 cargo test -p skylux-regmap`.\n"
    );
    let _ = writeln!(
        out,
        "The registers sit behind the lightweight HPS-to-FPGA bridge at physical address \
         `{LW_BRIDGE_PHYS_BASE:#010X}` ({} KiB window). Offsets below are bytes from that base. \
         All registers are 32 bits wide; byte enables are honoured. Reads have a fixed latency \
         of {READ_LATENCY_CYCLES} cycle. A read of an address with no register returns \
         `{UNMAPPED_READ_VALUE:#010X}` and sets `sys.bus_status.UNMAPPED_READ`; a write to one is \
         ignored and sets `UNMAPPED_WRITE`; both record the offset in `sys.bus_error_addr`.\n",
        LW_BRIDGE_SPAN_BYTES / 1024
    );
    let _ = writeln!(
        out,
        "Access types: **RW** read/write; **RO** driven by the fabric; **CONST** constant; \
         **W1C** sticky, set by the fabric, cleared by writing 1; **W1P** writing 1 sends a \
         one-cycle command pulse, reads as 0.\n"
    );
    let _ = writeln!(out, "The HPS checks `sys.id` = `{DESIGN_ID:#010X}` (\"SKYL\") and the major version at start-up.\n");
    let _ = writeln!(out, "| block | offset | summary |\n|---|---|---|");
    for block in MAP {
        let _ = writeln!(
            out,
            "| [`{}`](#{}) | `{:#06X}` | {} |",
            block.name,
            block.name,
            block.base,
            doc_line(block.doc)
        );
    }
    for block in MAP {
        let _ = writeln!(out, "\n## {}\n\n{}\n", block.name, doc_line(block.doc));
        let _ = writeln!(
            out,
            "| offset | register | bits | field | access | reset | description |"
        );
        let _ = writeln!(out, "|---|---|---|---|---|---|---|");
        for reg in block.registers {
            let name = if reg.count > 1 {
                alloc::format!("`{}[{}]`", reg.name, reg.count)
            } else {
                alloc::format!("`{}`", reg.name)
            };
            let offset = if reg.count > 1 {
                alloc::format!("`{:#06X}` + 4 i", reg.offset)
            } else {
                alloc::format!("`{:#06X}`", reg.offset)
            };
            let _ = writeln!(
                out,
                "| {offset} | {name} | | | | `{:#010X}` | {} |",
                reg.reset_value(),
                doc_line(reg.doc)
            );
            for field in reg.fields {
                let _ = writeln!(
                    out,
                    "| | | {} | `{}` | {} | `{:#X}` | {} |",
                    bits(field.lsb, field.width),
                    field.name,
                    field.access.code(),
                    field.reset,
                    doc_line(field.doc)
                );
            }
        }
    }
    out
}

fn c_name(block: &Block, reg: &Register) -> String {
    alloc::format!(
        "SKYLUX_{}_{}",
        block.name.to_uppercase(),
        reg.name.to_uppercase()
    )
}

/// The map as a C header.
pub fn c_header() -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "/* Skylux register map v{VERSION_MAJOR}.{VERSION_MINOR}."
    );
    let _ = writeln!(
        out,
        " * Generated from regmap/src/map.rs by skylux-regmap; do not edit."
    );
    let _ = writeln!(out, " * Offsets are bytes from SKYLUX_LW_BRIDGE_BASE. */");
    let _ = writeln!(out, "#ifndef SKYLUX_REGS_H\n#define SKYLUX_REGS_H\n");
    let _ = writeln!(
        out,
        "#define SKYLUX_LW_BRIDGE_BASE 0x{LW_BRIDGE_PHYS_BASE:08X}u"
    );
    let _ = writeln!(
        out,
        "#define SKYLUX_LW_BRIDGE_SPAN 0x{LW_BRIDGE_SPAN_BYTES:08X}u"
    );
    let _ = writeln!(out, "#define SKYLUX_DESIGN_ID 0x{DESIGN_ID:08X}u");
    let _ = writeln!(out, "#define SKYLUX_VERSION_MAJOR {VERSION_MAJOR}u");
    let _ = writeln!(out, "#define SKYLUX_VERSION_MINOR {VERSION_MINOR}u");
    let _ = writeln!(
        out,
        "#define SKYLUX_UNMAPPED_READ_VALUE 0x{UNMAPPED_READ_VALUE:08X}u"
    );
    for block in MAP {
        let _ = writeln!(out, "\n/* {}: {} */", block.name, doc_line(block.doc));
        let _ = writeln!(
            out,
            "#define SKYLUX_{}_BASE 0x{:04X}u",
            block.name.to_uppercase(),
            block.base
        );
        for reg in block.registers {
            let name = c_name(block, reg);
            if reg.count > 1 {
                let _ = writeln!(
                    out,
                    "#define {name}_OFFSET(i) (0x{:04X}u + 4u * (unsigned)(i))",
                    reg.offset
                );
                let _ = writeln!(out, "#define {name}_COUNT {}u", reg.count);
            } else {
                let _ = writeln!(out, "#define {name}_OFFSET 0x{:04X}u", reg.offset);
            }
            let _ = writeln!(out, "#define {name}_RESET 0x{:08X}u", reg.reset_value());
            for field in reg.fields {
                let fname = alloc::format!("{name}_{}", field.name);
                let _ = writeln!(out, "#define {fname}_SHIFT {}u", field.lsb);
                let _ = writeln!(out, "#define {fname}_MASK 0x{:08X}u", field.mask());
                if field.access == Access::Const {
                    let _ = writeln!(out, "#define {fname}_VALUE 0x{:X}u", field.reset);
                }
            }
        }
    }
    let _ = writeln!(out, "\n#endif /* SKYLUX_REGS_H */");
    out
}
