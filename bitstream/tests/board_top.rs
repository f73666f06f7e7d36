//! Checks of the DE1-SoC board top that run without Quartus: the hand-written top lints
//! cleanly against the black-box stubs of `soc_system` and `skylux_core`, every board pin of
//! the top has a location in `skylux.qsf`, the D5M pins are the Terasic ones, and the Linux
//! device-tree overlay compiles.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

use skylux_bitstream::xcheck::{self, Tool};

fn quartus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("quartus")
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The TRDB-D5M pins on GPIO_1, copied from hardware-facts.md section 1.8, which takes them
/// from the Terasic DE1_SoC_CAMERA demo (source S12, DE1_SoC_CAMERA.qsf).
const D5M_PINS: &[(&str, &str)] = &[
    ("D5M_PIXLCLK", "AB17"),
    ("D5M_D[11]", "AA21"),
    ("D5M_D[10]", "AC23"),
    ("D5M_D[9]", "AD24"),
    ("D5M_D[8]", "AE23"),
    ("D5M_D[7]", "AE24"),
    ("D5M_D[6]", "AF25"),
    ("D5M_D[5]", "AF26"),
    ("D5M_D[4]", "AG25"),
    ("D5M_D[3]", "AG26"),
    ("D5M_D[2]", "AH24"),
    ("D5M_D[1]", "AH27"),
    ("D5M_D[0]", "AJ27"),
    ("D5M_XCLKIN", "AK27"),
    ("D5M_RESET_N", "AJ26"),
    ("D5M_TRIGGER", "AH25"),
    ("D5M_STROBE", "AJ25"),
    ("D5M_LVAL", "AJ24"),
    ("D5M_FVAL", "AK24"),
    ("D5M_SDATA", "AG23"),
    ("D5M_SCLK", "AK23"),
];

/// The ports of the first module in `verilog`, one entry per bit (`NAME[i]` for vectors).
/// Handles ANSI port lists (`input wire [11:0] D5M_D,`) as `skylux_top.v` writes them.
fn port_bits(verilog: &str) -> Vec<String> {
    let start = verilog.find("module ").expect("no module");
    let open = start + verilog[start..].find('(').expect("no port list");
    let close = open + verilog[open..].find(");").expect("unterminated port list");
    let mut bits = Vec::new();
    for line in verilog[open + 1..close].lines() {
        let code = line
            .split("//")
            .next()
            .unwrap()
            .trim()
            .trim_end_matches(',');
        let mut words = code.split_whitespace().peekable();
        match words.peek() {
            Some(&"input") | Some(&"output") | Some(&"inout") => {}
            _ => continue,
        }
        let rest: Vec<&str> = words
            .skip(1)
            .filter(|w| *w != "wire" && *w != "reg")
            .collect();
        let (range, name) = match rest.as_slice() {
            [name] => (None, *name),
            [range, name] => (Some(*range), *name),
            other => panic!("unexpected port declaration {other:?}"),
        };
        match range {
            None => bits.push(name.to_string()),
            Some(r) => {
                let r = r.trim_start_matches('[').trim_end_matches(']');
                let (hi, lo) = r.split_once(':').expect("range");
                let (hi, lo): (u32, u32) = (hi.parse().unwrap(), lo.parse().unwrap());
                for i in lo.min(hi)..=hi.max(lo) {
                    bits.push(format!("{name}[{i}]"));
                }
            }
        }
    }
    bits
}

/// `set_location_assignment PIN_xx -to NAME` lines of a .qsf: NAME -> xx.
fn locations(qsf: &str) -> BTreeMap<String, String> {
    let mut map = BTreeMap::new();
    for line in qsf.lines() {
        let line = line.split('#').next().unwrap().trim();
        let w: Vec<&str> = line.split_whitespace().collect();
        if let ["set_location_assignment", pin, "-to", name] = w.as_slice() {
            let pin = pin.strip_prefix("PIN_").expect("PIN_ prefix");
            let old = map.insert(name.to_string(), pin.to_string());
            assert!(old.is_none(), "{name} assigned twice in skylux.qsf");
        }
    }
    map
}

/// HPS pins are placed by the HPS and constrained by Platform Designer's scripts, not by
/// location assignments in skylux.qsf.
fn is_hps_pin(bit: &str) -> bool {
    bit.starts_with("HPS_")
}

#[test]
fn board_top_lints_with_the_black_boxes() {
    if !xcheck::require(&[Tool::Verilator]) {
        return;
    }
    let dir = quartus_dir();
    // -Wall with no -Wno: the stubs switch off UNUSED and DECLFILENAME for themselves only
    // (they are empty on purpose and their file names end in _blackbox); the top must be
    // clean as written.
    let out = Command::new("verilator")
        .current_dir(&dir)
        .args([
            "--lint-only",
            "-Wall",
            "--top-module",
            "skylux_top",
            "skylux_top.v",
            "soc_system_blackbox.v",
            "skylux_core_blackbox.v",
        ])
        .output()
        .expect("verilator runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.status.success() && !text.contains("%Warning"),
        "verilator lint of skylux_top failed:\n{text}"
    );
}

#[test]
fn every_board_pin_of_the_top_has_a_location() {
    let top = read(&quartus_dir().join("skylux_top.v"));
    let qsf = read(&quartus_dir().join("skylux.qsf"));
    let bits = port_bits(&top);
    assert!(
        bits.len() > 100,
        "port list parse found only {} bits",
        bits.len()
    );
    let locs = locations(&qsf);

    let board: BTreeSet<&String> = bits.iter().filter(|b| !is_hps_pin(b)).collect();
    let missing: Vec<_> = board.iter().filter(|b| !locs.contains_key(**b)).collect();
    assert!(
        missing.is_empty(),
        "board pins without a location in skylux.qsf: {missing:?}"
    );
    let stray: Vec<_> = locs.keys().filter(|n| !board.contains(n)).collect();
    assert!(
        stray.is_empty(),
        "skylux.qsf places signals skylux_top does not have: {stray:?}"
    );

    let mut by_pin: BTreeMap<&String, &String> = BTreeMap::new();
    for (name, pin) in &locs {
        if let Some(other) = by_pin.insert(pin, name) {
            panic!("PIN_{pin} assigned to both {other} and {name}");
        }
    }
    for b in &board {
        assert!(
            qsf.contains(&format!("IO_STANDARD \"3.3-V LVTTL\" -to {b}"))
                || qsf.contains(&format!(
                    "IO_STANDARD \"3.3-V LVTTL\" -to {}[*]",
                    b.split('[').next().unwrap()
                )),
            "{b} has no 3.3-V LVTTL I/O standard in skylux.qsf"
        );
    }
}

#[test]
fn d5m_pins_match_hardware_facts() {
    let locs = locations(&read(&quartus_dir().join("skylux.qsf")));
    for (name, pin) in D5M_PINS {
        assert_eq!(
            locs.get(*name).map(String::as_str),
            Some(*pin),
            "{name} must be PIN_{pin} (hardware-facts.md section 1.8)"
        );
    }
    let d5m_in_qsf = locs.keys().filter(|n| n.starts_with("D5M_")).count();
    assert_eq!(d5m_in_qsf, D5M_PINS.len(), "D5M pins in skylux.qsf");
}

/// Like `xcheck::require`, for the device-tree compiler (apt: device-tree-compiler).
fn require_dtc() -> bool {
    skylux_hps::prerequisite::available_or_skip(
        Command::new("dtc").arg("--version").output().is_ok(),
        skylux_hps::prerequisite::REQUIRE_EDA,
        "overlay check: dtc not installed (apt-get install device-tree-compiler)",
    )
}

#[test]
fn device_tree_overlay_compiles() {
    overlay_compiles(
        "skylux-overlay.dts",
        &[
            "compatible = \"generic-uio\"",
            "reg = <0xff200000 0x00200000>",
            "interrupts = <0 40 4>",
            "no-map",
            "bridge-enable = <1>",
        ],
    );
}

/// The variant with the frame buffer through u-dma-buf, cached (hardware.dma_device).
#[test]
fn device_tree_overlay_for_udmabuf_compiles() {
    overlay_compiles(
        "skylux-overlay-udmabuf.dts",
        &[
            "compatible = \"generic-uio\"",
            "compatible = \"ikwzm,u-dma-buf\"",
            "device-name = \"udmabuf0\"",
            "compatible = \"shared-dma-pool\"",
            "reg = <0x38000000 0x08000000>",
            "memory-region = <&skylux_dma>",
            "bridge-enable = <1>",
        ],
    );
}

fn overlay_compiles(file: &str, needles: &[&str]) {
    if !require_dtc() {
        return;
    }
    let dts = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("linux")
        .join(file);
    let text = read(&dts);
    for needle in needles {
        assert!(text.contains(needle), "{file} lacks `{needle}`");
    }
    let out_file = std::env::temp_dir().join(format!("{file}-{}.dtbo", std::process::id()));
    let out = Command::new("dtc")
        .args(["-@", "-I", "dts", "-O", "dtb", "-o"])
        .arg(&out_file)
        .arg(&dts)
        .output()
        .expect("dtc runs");
    let log = String::from_utf8_lossy(&out.stderr);
    let _ = std::fs::remove_file(&out_file);
    assert!(out.status.success(), "dtc failed:\n{log}");
    assert!(!log.contains("Warning"), "dtc warnings:\n{log}");
}

#[test]
fn the_checked_in_core_is_current() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join(skylux_bitstream::blocks::CORE_VERILOG_PATH);
    let fresh = skylux_bitstream::blocks::core_verilog();
    if std::env::var_os("SKYLUX_BLESS").is_some() {
        std::fs::write(&path, &fresh).unwrap();
    }
    let checked_in = read(&path);
    assert!(
        checked_in == fresh,
        "{} is stale: run `cargo run -p skylux-bitstream -- verilog`",
        path.display()
    );
    // Deterministic: a second export is identical.
    assert_eq!(fresh, skylux_bitstream::blocks::core_verilog());
}

#[test]
fn board_top_lints_with_the_real_core() {
    if !xcheck::require(&[Tool::Verilator]) {
        return;
    }
    let dir = quartus_dir();
    // The generated core needs the waivers of every rust-hdl block (rust-hdl-notes §5: 32-bit
    // literals, one always block per module); port names and widths between the top and the
    // core are checked in full (a missing or extra pin is an error, a width mismatch a
    // warning that fails this test).
    let out = Command::new("verilator")
        .current_dir(&dir)
        .args([
            "--lint-only",
            "-Wall",
            "-Wno-UNOPTFLAT",
            "-Wno-DECLFILENAME",
            "-Wno-UNUSED",
            "-Wno-PINCONNECTEMPTY",
            "-Wno-fatal",
            "--top-module",
            "skylux_top",
            "skylux_top.v",
            "soc_system_blackbox.v",
            "core/skylux_core.v",
        ])
        .output()
        .expect("verilator runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    // WIDTH warnings inside the generated core are rust-hdl's 32-bit literals; a width
    // warning on the instance in skylux_top.v is a real port mismatch.
    let real: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("%Warning") || l.starts_with("%Error"))
        .filter(|l| !(l.contains("WIDTH") && l.contains("core/skylux_core.v")))
        .collect();
    assert!(
        out.status.success() || real.is_empty() && !text.contains("%Error"),
        "verilator lint of skylux_top with the real core failed:\n{}",
        real.join("\n")
    );
    assert!(real.is_empty(), "lint warnings:\n{}", real.join("\n"));
}
