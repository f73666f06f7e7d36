//! The same HPS driver code runs against the cycle-accurate fabric (through the Avalon-MM bus
//! model) and against the memory-mapped backend over a file, and behaves the same.

use skylux_bus::{RegisterAccess, RegisterBus};
use skylux_hps::fpga::{BringUpError, ExposureError, ExposureSlot, Fabric};
use skylux_regmap::{bayer, sys, DESIGN_ID, VERSION_MAJOR, VERSION_MINOR};
use skylux_rtl::RegisterFile;
use skylux_sim::SimRegisterBus;

/// The driver test both backends must pass.
fn driver_test<B: RegisterBus>(bus: B) -> B {
    let mut fabric = Fabric::bring_up(bus).expect("bring-up");
    assert_eq!(fabric.info().version_major, VERSION_MAJOR);
    assert_eq!(fabric.info().version_minor, VERSION_MINOR);
    assert_eq!(fabric.info().sys_clock_hz, skylux_regmap::SYS_CLOCK_HZ);

    // A five-exposure HDR table, 1 row to the 20-bit maximum, read back exactly.
    let slots: Vec<ExposureSlot> = [1u32, 30, 900, 27_000, (1 << 20) - 1]
        .iter()
        .enumerate()
        .map(|(i, &rows)| ExposureSlot {
            shutter_width_rows: rows,
            shutter_delay: i as u32,
            gain_code: 8 + i as u32,
        })
        .collect();
    fabric.set_exposures(&slots).unwrap();
    assert_eq!(fabric.exposures().unwrap(), slots);

    // Refused tables change nothing.
    let too_wide = ExposureSlot {
        shutter_width_rows: 1 << 20,
        shutter_delay: 0,
        gain_code: 8,
    };
    assert!(matches!(
        fabric.set_exposures(&[too_wide]),
        Err(ExposureError::OutOfRange {
            field: "shutter_width_rows",
            ..
        })
    ));
    assert!(matches!(
        fabric.set_exposures(&[slots[0]; 9]),
        Err(ExposureError::Count(9))
    ));
    assert!(matches!(
        fabric.set_exposures(&[]),
        Err(ExposureError::Count(0))
    ));
    assert_eq!(fabric.exposures().unwrap(), slots);

    // Field access keeps the register's other fields.
    let bus = fabric.bus();
    bus.write_field(&bayer::valid::REG, 0, &bayer::valid::MIN, 40)
        .unwrap();
    bus.write_field(&bayer::valid::REG, 0, &bayer::valid::MAX, 3100)
        .unwrap();
    assert_eq!(
        bus.read_field(&bayer::valid::REG, 0, &bayer::valid::MIN)
            .unwrap(),
        40
    );
    assert_eq!(
        bus.read_field(&bayer::valid::REG, 0, &bayer::valid::MAX)
            .unwrap(),
        3100
    );
    fabric.into_bus()
}

#[test]
fn driver_on_the_cycle_accurate_fabric() {
    let bus = driver_test(SimRegisterBus::new(RegisterFile::default()));
    assert!(
        bus.host.cycles() > 100,
        "every access went through the cycle-accurate model"
    );
}

#[test]
fn driver_on_the_memory_mapped_backend() {
    let (file, window) = skylux_tests::register_window_file();
    drop(driver_test(window));
    // The writes reached the file through the mapping.
    let bytes = std::fs::read(file.path()).unwrap();
    let at = |offset: u32| {
        u32::from_le_bytes(
            bytes[offset as usize..offset as usize + 4]
                .try_into()
                .unwrap(),
        )
    };
    assert_eq!(bayer::valid::MAX.get(at(bayer::valid::REG.offset)), 3100);
    assert_eq!(at(sys::id::REG.offset), DESIGN_ID);
}

#[test]
fn bring_up_refuses_a_dead_bridge_or_another_design() {
    let (file, mut window) = skylux_tests::register_window_file();
    window.write_reg(&sys::id::REG, 0, 0).unwrap();
    match Fabric::bring_up(&mut window) {
        Err(e @ BringUpError::WrongId { found: 0, .. }) => {
            assert!(e.to_string().contains("bridge is disabled"))
        }
        other => panic!("expected WrongId, got {:?}", other.err()),
    }
    window.write_reg(&sys::id::REG, 0, DESIGN_ID).unwrap();
    window
        .write_reg(
            &sys::version::REG,
            0,
            sys::version::MAJOR.word(VERSION_MAJOR + 1),
        )
        .unwrap();
    assert!(matches!(
        Fabric::bring_up(&mut window),
        Err(BringUpError::WrongVersion { .. })
    ));
    drop(file);
}
