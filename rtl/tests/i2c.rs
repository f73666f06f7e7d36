//! The I2C master at the pin level, without a sensor model (the MT9P031 model tests it in
//! `tests/tests/sensor_control.rs`): the bits it puts on the wire, START/STOP, SCL timing,
//! and its three failure flags.

use rust_hdl::prelude::*;
use skylux_rtl::drive::Driver;
use skylux_rtl::i2c::I2cMaster;

fn clock(d: &mut I2cMaster) -> &mut Signal<In, Clock> {
    &mut d.clock
}

/// What a bus monitor saw.
#[derive(Debug, Default)]
struct Seen {
    starts: usize,
    stops: usize,
    /// Bytes with the ACK bit that followed each (true: acknowledged).
    bytes: Vec<(u8, bool)>,
    done: bool,
    nack: bool,
    timeout: bool,
    stuck: bool,
    cycles: u64,
    scl_edges: usize,
    /// Shortest SCL high and low runs, in cycles.
    min_high: u64,
    min_low: u64,
}

/// A bus with pull-ups, the master, and a test device that can acknowledge the first bytes
/// (the ones the master sends), hold SDA low, or hold SCL low.
struct Bus {
    d: Driver<I2cMaster>,
    ack_first: usize,
    sda_stuck: bool,
    scl_stuck: bool,
}

impl Bus {
    fn new(half_period: u64, timeout: u64) -> Self {
        let mut d = Driver::new(I2cMaster::default());
        d.dut.half_period.next = half_period.into();
        d.dut.timeout_cycles.next = timeout.into();
        d.dut.device.next = 0x5D.into();
        d.dut.scl_in.next = true;
        d.dut.sda_in.next = true;
        Bus {
            d,
            ack_first: 0,
            sda_stuck: false,
            scl_stuck: false,
        }
    }

    /// Runs one transaction to completion and decodes the wire.
    fn transaction(&mut self, read: bool, reg: u8, data: u16, max_cycles: u64) -> Seen {
        let mut seen = Seen {
            min_high: u64::MAX,
            min_low: u64::MAX,
            ..Default::default()
        };
        let dut = &mut self.d.dut;
        dut.read.next = read;
        dut.reg_addr.next = u64::from(reg).into();
        dut.write_data.next = u64::from(data).into();
        dut.start.next = true;
        self.d.cycle(clock).unwrap();
        self.d.dut.start.next = false;
        let (mut scl, mut sda) = (true, true);
        let (mut bits, mut shift, mut acking, mut run) = (0u32, 0u8, false, 0u64);
        let mut in_byte = false;
        for _ in 0..max_cycles {
            self.d.cycle(clock).unwrap();
            seen.cycles += 1;
            let m = &self.d.dut;
            if m.done.val() {
                seen.done = true;
                seen.nack = m.nack.val();
                seen.timeout = m.timeout.val();
                seen.stuck = m.bus_stuck.val();
                break;
            }
            let new_scl = !(m.scl_low.val() || self.scl_stuck);
            let device_sda_low = self.sda_stuck || acking;
            let new_sda = !(m.sda_low.val() || device_sda_low);
            if scl && new_scl && sda && !new_sda {
                seen.starts += 1;
                in_byte = true;
                bits = 0;
                shift = 0;
            }
            if scl && new_scl && !sda && new_sda {
                seen.stops += 1;
                in_byte = false;
            }
            if !scl && new_scl && in_byte {
                // Rising edge: sample.
                if bits < 8 {
                    shift = (shift << 1) | u8::from(new_sda);
                } else {
                    seen.bytes.push((shift, !new_sda));
                }
                bits += 1;
            }
            if scl && !new_scl && in_byte {
                // Falling edge: the device acknowledges the 8th bit, then lets go.
                if bits == 8 && seen.bytes.len() < self.ack_first {
                    acking = true;
                } else if bits == 9 {
                    acking = false;
                    bits = 0;
                    shift = 0;
                }
            }
            if new_scl != scl {
                seen.scl_edges += 1;
                if seen.scl_edges > 2 {
                    if scl {
                        seen.min_high = seen.min_high.min(run);
                    } else {
                        seen.min_low = seen.min_low.min(run);
                    }
                }
                run = 0;
            }
            run += 1;
            scl = new_scl;
            sda = !(m.sda_low.val() || self.sda_stuck || acking);
            let dut = &mut self.d.dut;
            dut.scl_in.next = scl;
            dut.sda_in.next = sda;
        }
        seen
    }
}

#[test]
fn a_register_write_puts_the_mt9p031_protocol_on_the_wire() {
    let mut bus = Bus::new(8, 100_000);
    bus.ack_first = 4;
    let seen = bus.transaction(false, 0x09, 0xA5C3, 100_000);
    assert!(
        seen.done && !seen.nack && !seen.timeout && !seen.stuck,
        "{seen:?}"
    );
    assert_eq!((seen.starts, seen.stops), (1, 1));
    assert_eq!(
        seen.bytes,
        vec![(0xBA, true), (0x09, true), (0xA5, true), (0xC3, true)]
    );
    // Quarter = 4 clocks: SCL low for two quarters, high for two (plus the synchroniser).
    assert_eq!(seen.min_low, 8, "{seen:?}");
    assert!((8..=11).contains(&seen.min_high), "{seen:?}");
}

#[test]
fn a_register_read_sends_the_pointer_then_a_repeated_start() {
    let mut bus = Bus::new(4, 100_000);
    bus.ack_first = 3;
    let seen = bus.transaction(true, 0x00, 0, 100_000);
    assert!(seen.done && !seen.nack, "{seen:?}");
    assert_eq!((seen.starts, seen.stops), (2, 1));
    // Address+W, pointer, address+R, then two data bytes (the device sends nothing here, so
    // they read 0xFF): ACK after the first, NACK after the last.
    assert_eq!(
        seen.bytes,
        vec![
            (0xBA, true),
            (0x00, true),
            (0xBB, true),
            (0xFF, true),
            (0xFF, false)
        ]
    );
    assert_eq!(bus.d.dut.read_data.val().index(), 0xFFFF);
}

#[test]
fn no_device_is_a_nack_then_a_stop() {
    let mut bus = Bus::new(4, 100_000);
    let seen = bus.transaction(false, 0x01, 0x1234, 100_000);
    assert!(
        seen.done && seen.nack && !seen.timeout && !seen.stuck,
        "{seen:?}"
    );
    assert_eq!(seen.bytes, vec![(0xBA, false)], "stops after the address");
    assert_eq!(seen.stops, 1);
    assert!(!bus.d.dut.busy.val());
}

#[test]
fn sda_held_low_is_flagged_as_a_stuck_bus_without_clocking() {
    let mut bus = Bus::new(4, 100_000);
    bus.sda_stuck = true;
    let seen = bus.transaction(false, 0x01, 0x1234, 100_000);
    assert!(
        seen.done && seen.stuck && !seen.nack && !seen.timeout,
        "{seen:?}"
    );
    assert_eq!(seen.scl_edges, 0);
    assert!(seen.cycles < 20, "{seen:?}");
    // Released, the bus works again.
    bus.sda_stuck = false;
    bus.ack_first = 4;
    let seen = bus.transaction(false, 0x01, 0x1234, 100_000);
    assert!(seen.done && !seen.stuck && !seen.nack, "{seen:?}");
}

#[test]
fn scl_held_low_times_out_after_the_programmed_cycles() {
    for timeout in [50u64, 300] {
        let mut bus = Bus::new(4, timeout);
        bus.scl_stuck = true;
        let seen = bus.transaction(false, 0x01, 0x1234, 100_000);
        assert!(seen.done && seen.timeout && !seen.nack, "{seen:?}");
        // `done` comes `timeout` clocks after the START was taken, plus the output flop.
        assert_eq!(seen.cycles, timeout + 1, "{seen:?}");
        assert!(
            !bus.d.dut.scl_low.val() && !bus.d.dut.sda_low.val(),
            "lines released"
        );
    }
}

#[test]
fn start_while_busy_is_ignored() {
    let mut bus = Bus::new(4, 100_000);
    bus.d.dut.read.next = false;
    bus.d.dut.reg_addr.next = 0x22.into();
    bus.d.dut.write_data.next = 0x0011.into();
    bus.d.dut.start.next = true;
    bus.d.cycle(clock).unwrap();
    // A second START while busy must not start another transaction.
    bus.d.dut.reg_addr.next = 0x77.into();
    bus.d.cycle(clock).unwrap();
    assert!(bus.d.dut.busy.val());
    bus.d.dut.start.next = false;
    let mut dones = 0;
    for _ in 0..5_000 {
        bus.d.cycle(clock).unwrap();
        if bus.d.dut.done.val() {
            dones += 1;
        }
        let (scl_low, sda_low) = (bus.d.dut.scl_low.val(), bus.d.dut.sda_low.val());
        bus.d.dut.scl_in.next = !scl_low;
        bus.d.dut.sda_in.next = !sda_low;
    }
    assert_eq!(dones, 1);
}
