//! Cycle-accurate tests of the generated register file, driven through the Avalon-MM host
//! model: reset values, writes with byte enables, read-only and constant fields, write-1-to-
//! clear status, command pulses, interrupts and unmapped addresses. Then random transfer
//! sequences against the behavioural model.

use rand::{Rng, SeedableRng};
use skylux_regmap::*;
use skylux_rtl::RegisterFile;
use skylux_sim::{AvalonHost, RegisterFileModel};

fn host() -> AvalonHost<RegisterFile> {
    AvalonHost::new(RegisterFile::default())
}

fn word(reg: &Register, index: u32) -> u32 {
    reg.word_address(index)
}

#[test]
fn every_register_reads_its_reset_value() {
    let mut h = host();
    for (offset, value) in reset_image() {
        assert_eq!(
            h.read(offset / 4).unwrap(),
            value,
            "{:?} at {offset:#x}",
            locate(offset).unwrap().register.name
        );
    }
}

#[test]
fn writes_honour_byte_enables_and_read_only_fields() {
    let mut h = host();
    let scratch = word(&sys::scratch::REG, 0);
    h.write(scratch, 0x1122_3344, 0xF).unwrap();
    h.write(scratch, 0xAABB_CCDD, 0b0101).unwrap();
    assert_eq!(h.read(scratch).unwrap(), 0x11BB_33DD);
    h.write(scratch, 0xFFFF_FFFF, 0).unwrap();
    assert_eq!(
        h.read(scratch).unwrap(),
        0x11BB_33DD,
        "all-zero byte enables write nothing"
    );

    // Constant registers ignore writes.
    h.write(word(&sys::id::REG, 0), 0, 0xF).unwrap();
    assert_eq!(h.read(word(&sys::id::REG, 0)).unwrap(), DESIGN_ID);
    // Read-only fields show what the fabric drives, and only that.
    h.driver.dut.i2c_read_data_data.next = 0x1801.into();
    h.driver.dut.i2c_status_busy.next = true;
    h.write(word(&i2c::read_data::REG, 0), 0xFFFF, 0xF).unwrap();
    assert_eq!(h.read(word(&i2c::read_data::REG, 0)).unwrap(), 0x1801);
    assert_eq!(
        h.read(word(&i2c::status::REG, 0)).unwrap() & i2c::status::BUSY.mask(),
        i2c::status::BUSY.mask()
    );
    // A RW field next to a W1P field: the command bit does not stick.
    h.write(
        word(&i2c::ctrl::REG, 0),
        i2c::ctrl::READ.mask() | i2c::ctrl::START.mask(),
        0xF,
    )
    .unwrap();
    assert_eq!(
        h.read(word(&i2c::ctrl::REG, 0)).unwrap(),
        i2c::ctrl::READ.mask()
    );
    assert!(h.driver.dut.i2c_ctrl_read.val());
}

#[test]
fn register_arrays_are_independent() {
    let mut h = host();
    for i in 0..seq::exp_shutter_width::REG.count {
        h.write(word(&seq::exp_shutter_width::REG, i), 1000 * (i + 1), 0xF)
            .unwrap();
    }
    for i in 0..seq::exp_shutter_width::REG.count {
        assert_eq!(
            h.read(word(&seq::exp_shutter_width::REG, i)).unwrap(),
            1000 * (i + 1)
        );
        assert_eq!(
            h.driver.dut.seq_exp_shutter_width_rows[i as usize]
                .val()
                .to_u64(),
            1000 * (i as u64 + 1)
        );
    }
    // Bits above the field's width are not stored.
    h.write(word(&seq::exp_gain::REG, 2), 0xFFFF_FFFF, 0xF)
        .unwrap();
    assert_eq!(h.read(word(&seq::exp_gain::REG, 2)).unwrap(), 0xFFFF);
}

#[test]
fn write_one_to_clear_status_keeps_events() {
    let mut h = host();
    let status = word(&dma::status::REG, 0);
    let done = dma::status::FRAME_DONE.mask();
    let oow = dma::status::OUT_OF_WINDOW.mask();
    // The fabric pulses two causes.
    h.driver.dut.dma_status_frame_done_set.next = true;
    h.driver.dut.dma_status_out_of_window_set.next = true;
    h.idle(1).unwrap();
    h.driver.dut.dma_status_frame_done_set.next = false;
    h.driver.dut.dma_status_out_of_window_set.next = false;
    h.idle(3).unwrap();
    assert_eq!(
        h.read(status).unwrap() & (done | oow),
        done | oow,
        "sticky after the pulse"
    );
    h.write(status, 0, 0xF).unwrap();
    assert_eq!(
        h.read(status).unwrap() & (done | oow),
        done | oow,
        "writing 0 clears nothing"
    );
    h.write(status, done, 0xF).unwrap();
    assert_eq!(
        h.read(status).unwrap() & (done | oow),
        oow,
        "writing 1 clears only that bit"
    );
    // A new event in the very cycle software clears the bit is not lost.
    h.driver.dut.dma_status_out_of_window_set.next = true;
    h.write(status, oow, 0xF).unwrap();
    h.driver.dut.dma_status_out_of_window_set.next = false;
    assert_eq!(h.read(status).unwrap() & oow, oow);
}

#[test]
fn commands_are_one_cycle_pulses() {
    let mut h = host();
    h.write(word(&seq::ctrl::REG, 0), seq::ctrl::START.mask(), 0xF)
        .unwrap();
    // The write's rising edge has passed: the pulse is high now, for exactly one cycle.
    h.driver.settle().unwrap();
    assert!(h.driver.dut.seq_ctrl_start.val());
    h.idle(1).unwrap();
    assert!(!h.driver.dut.seq_ctrl_start.val());
    assert_eq!(
        h.read(word(&seq::ctrl::REG, 0)).unwrap() & seq::ctrl::START.mask(),
        0,
        "reads as 0"
    );
    // A byte enable that excludes the command's byte sends nothing.
    h.write(word(&seq::ctrl::REG, 0), seq::ctrl::START.mask(), 0b1110)
        .unwrap();
    h.driver.settle().unwrap();
    assert!(!h.driver.dut.seq_ctrl_start.val());
}

#[test]
fn interrupt_follows_enabled_causes() {
    let mut h = host();
    h.driver.dut.sys_irq_status_raybox_done_set.next = true;
    h.idle(1).unwrap();
    h.driver.dut.sys_irq_status_raybox_done_set.next = false;
    h.idle(1).unwrap();
    assert!(!h.driver.dut.irq.val(), "cause set but not enabled");
    h.write(
        word(&sys::irq_enable::REG, 0),
        sys::irq_enable::RAYBOX_DONE.mask(),
        0xF,
    )
    .unwrap();
    h.idle(1).unwrap();
    assert!(h.driver.dut.irq.val());
    h.write(
        word(&sys::irq_status::REG, 0),
        sys::irq_status::RAYBOX_DONE.mask(),
        0xF,
    )
    .unwrap();
    h.idle(1).unwrap();
    assert!(!h.driver.dut.irq.val(), "cleared");
}

#[test]
fn unmapped_addresses_answer_and_are_flagged() {
    let mut h = host();
    let hole = 0x0FF0 / 4; // inside the sys page, no register
    let far = (LW_BRIDGE_SPAN_BYTES - 4) / 4; // last word of the window
    assert_eq!(h.read(hole).unwrap(), UNMAPPED_READ_VALUE);
    let bus_status = h.read(word(&sys::bus_status::REG, 0)).unwrap();
    assert_eq!(bus_status, sys::bus_status::UNMAPPED_READ.mask());
    assert_eq!(
        h.read(word(&sys::bus_error_addr::REG, 0)).unwrap(),
        hole * 4
    );
    h.write(far, 0x1234_5678, 0xF).unwrap();
    assert_eq!(
        h.read(word(&sys::bus_status::REG, 0)).unwrap(),
        sys::bus_status::UNMAPPED_READ.mask() | sys::bus_status::UNMAPPED_WRITE.mask()
    );
    assert_eq!(h.read(word(&sys::bus_error_addr::REG, 0)).unwrap(), far * 4);
    // The bus keeps working, and the flags clear.
    h.write(word(&sys::bus_status::REG, 0), 0b11, 0xF).unwrap();
    assert_eq!(h.read(word(&sys::bus_status::REG, 0)).unwrap(), 0);
    assert_eq!(h.read(word(&sys::id::REG, 0)).unwrap(), DESIGN_ID);
}

/// Random transfers to random registers (and holes) with random byte enables: the RTL and the
/// behavioural model read the same values throughout.
#[test]
fn random_transfers_match_the_behavioural_model() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(0x5C1_10C);
    let offsets: Vec<u32> = reset_image()
        .into_iter()
        .map(|(o, _)| o)
        .chain([0x0FF0, 0x9000, 0x1F_FFFC])
        .collect();
    let mut h = host();
    let mut model = RegisterFileModel::default();
    for step in 0..3000 {
        let offset = offsets[rng.gen_range(0..offsets.len())];
        if rng.gen_bool(0.5) {
            let (data, be) = (rng.gen::<u32>(), rng.gen_range(0..16u8));
            h.write(offset / 4, data, be).unwrap();
            model.write(offset, data, be);
        } else {
            let (rtl, golden) = (h.read(offset / 4).unwrap(), model.read(offset));
            assert_eq!(rtl, golden, "step {step}: read of {offset:#x}");
        }
    }
}
