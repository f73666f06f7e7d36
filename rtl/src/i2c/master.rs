//! The I2C register-transaction master.

use rust_hdl::prelude::*;

/// Flip-flops between the SCL/SDA pins and the logic (metastability). A released line is
/// therefore seen high this many clocks late, which the master treats as clock stretching.
pub const SYNC_STAGES: usize = 2;

// `kind` of a step (literals in the kernel: a named constant would reach the Verilog as an
// undeclared identifier): 0 START, 1 repeated START, 2 byte (8 bits and the ACK slot), 3 STOP.

/// One register transaction of the MT9P031 protocol per `start` pulse:
///
/// - write: `S, {dev,W} A, reg A, data[15:8] A, data[7:0] A, P`;
/// - read: `S, {dev,W} A, reg A, Sr, {dev,R} A, data[15:8] (master ACK), data[7:0] (master
///   NACK), P`.
///
/// Every bit takes four quarters of `half_period / 2` clocks (at least 1): SCL low with SDA
/// held, SCL low with SDA set, SCL released, SCL released; SDA is sampled at the end of the
/// fourth. While SCL is released but still seen low (a target stretching it, or the
/// synchroniser delay) the quarter does not advance, so SCL runs a few clocks slower than
/// `clock / (2 half_period)`. SDA never changes in the quarter where SCL falls, so a bit
/// change can never look like START or STOP.
///
/// Outcome, as one-cycle pulses with `done` (status `i2c.status.*`):
/// - `nack`: the target did not acknowledge a byte it was sent (absent device: the address
///   byte); the master then sends STOP.
/// - `bus_stuck`: SDA was low when the master released it (before START, before a repeated
///   START, or on a 1 bit it sent): the transaction is abandoned and both lines released.
/// - `timeout`: the transaction was still running `timeout_cycles` clocks after `start` (SCL
///   held low); both lines are released. 0 times every transaction out at once.
///
/// `start` is ignored while `busy`. Inputs are latched at `start`. `read_data` holds the last
/// read's value until the next read starts. Pins: `scl_low`/`sda_low` high pull the line low
/// (open drain: `assign SCL = scl_low ? 1'b0 : 1'bz;`), `scl_in`/`sda_in` are the line levels.
#[derive(LogicBlock)]
pub struct I2cMaster {
    pub clock: Signal<In, Clock>,
    pub start: Signal<In, Bit>,
    /// 1: read the register; 0: write it.
    pub read: Signal<In, Bit>,
    /// `i2c.target.ADDR7`.
    pub device: Signal<In, Bits<7>>,
    /// `i2c.reg_addr.ADDR`.
    pub reg_addr: Signal<In, Bits<8>>,
    /// `i2c.write_data.DATA`.
    pub write_data: Signal<In, Bits<16>>,
    /// `i2c.clock_div.HALF_PERIOD`.
    pub half_period: Signal<In, Bits<16>>,
    /// `i2c.timeout.CYCLES`.
    pub timeout_cycles: Signal<In, Bits<24>>,
    pub scl_in: Signal<In, Bit>,
    pub sda_in: Signal<In, Bit>,
    pub scl_low: Signal<Out, Bit>,
    pub sda_low: Signal<Out, Bit>,
    /// `i2c.status.BUSY`.
    pub busy: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    pub nack: Signal<Out, Bit>,
    pub timeout: Signal<Out, Bit>,
    pub bus_stuck: Signal<Out, Bit>,
    /// `i2c.read_data.DATA`.
    pub read_data: Signal<Out, Bits<16>>,

    scl_sync0: DFFWithInit<Bit>,
    scl_sync1: DFFWithInit<Bit>,
    sda_sync0: DFFWithInit<Bit>,
    sda_sync1: DFFWithInit<Bit>,
    scl_r: DFFWithInit<Bit>,
    sda_r: DFFWithInit<Bit>,
    busy_r: DFF<Bit>,
    rd: DFF<Bit>,
    dev: DFF<Bits<8>>,
    ra: DFF<Bits<8>>,
    wd: DFF<Bits<16>>,
    quarter_len: DFF<Bits<16>>,
    step: DFF<Bits<4>>,
    bit_no: DFF<Bits<4>>,
    quarter: DFF<Bits<2>>,
    count: DFF<Bits<16>>,
    watchdog: DFF<Bits<24>>,
    failed_nack: DFF<Bit>,
    rdata: DFF<Bits<16>>,
    done_r: DFF<Bit>,
    nack_r: DFF<Bit>,
    timeout_r: DFF<Bit>,
    stuck_r: DFF<Bit>,

    kind: Signal<Local, Bits<2>>,
    tx: Signal<Local, Bits<8>>,
    tx_shifted: Signal<Local, Bits<8>>,
    rx: Signal<Local, Bit>,
    ack_level: Signal<Local, Bit>,
    last_step: Signal<Local, Bits<4>>,
    level: Signal<Local, Bit>,
    want_scl: Signal<Local, Bit>,
    want_sda: Signal<Local, Bit>,
    count_next: Signal<Local, Bits<16>>,
    step_next: Signal<Local, Bits<4>>,
    bit_next: Signal<Local, Bits<4>>,
    half_in: Signal<Local, Bits<16>>,
}

impl Default for I2cMaster {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            start: Default::default(),
            read: Default::default(),
            device: Default::default(),
            reg_addr: Default::default(),
            write_data: Default::default(),
            half_period: Default::default(),
            timeout_cycles: Default::default(),
            scl_in: Default::default(),
            sda_in: Default::default(),
            scl_low: Default::default(),
            sda_low: Default::default(),
            busy: Default::default(),
            done: Default::default(),
            nack: Default::default(),
            timeout: Default::default(),
            bus_stuck: Default::default(),
            read_data: Default::default(),
            // The bus idles high (pull-ups); the synchronisers start there too.
            scl_sync0: DFFWithInit::new(true),
            scl_sync1: DFFWithInit::new(true),
            sda_sync0: DFFWithInit::new(true),
            sda_sync1: DFFWithInit::new(true),
            scl_r: DFFWithInit::new(true),
            sda_r: DFFWithInit::new(true),
            busy_r: Default::default(),
            rd: Default::default(),
            dev: Default::default(),
            ra: Default::default(),
            wd: Default::default(),
            quarter_len: Default::default(),
            step: Default::default(),
            bit_no: Default::default(),
            quarter: Default::default(),
            count: Default::default(),
            watchdog: Default::default(),
            failed_nack: Default::default(),
            rdata: Default::default(),
            done_r: Default::default(),
            nack_r: Default::default(),
            timeout_r: Default::default(),
            stuck_r: Default::default(),
            kind: Default::default(),
            tx: Default::default(),
            tx_shifted: Default::default(),
            rx: Default::default(),
            ack_level: Default::default(),
            last_step: Default::default(),
            level: Default::default(),
            want_scl: Default::default(),
            want_sda: Default::default(),
            count_next: Default::default(),
            step_next: Default::default(),
            bit_next: Default::default(),
            half_in: Default::default(),
        }
    }
}

impl Logic for I2cMaster {
    // Match guards are dropped from the Verilog (rust-hdl-notes §6 item 4): never collapse.
    #[allow(clippy::collapsible_match)]
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            scl_sync0,
            scl_sync1,
            sda_sync0,
            sda_sync1,
            scl_r,
            sda_r,
            busy_r,
            rd,
            dev,
            ra,
            wd,
            quarter_len,
            step,
            bit_no,
            quarter,
            count,
            watchdog,
            failed_nack,
            rdata,
            done_r,
            nack_r,
            timeout_r,
            stuck_r
        );
        self.scl_sync0.d.next = self.scl_in.val();
        self.scl_sync1.d.next = self.scl_sync0.q.val();
        self.sda_sync0.d.next = self.sda_in.val();
        self.sda_sync1.d.next = self.sda_sync0.q.val();
        self.done_r.d.next = false;
        self.nack_r.d.next = false;
        self.timeout_r.d.next = false;
        self.stuck_r.d.next = false;

        // What the current step sends.
        self.kind.next = 2.into();
        self.tx.next = 0.into();
        self.rx.next = false;
        self.ack_level.next = true;
        if self.rd.q.val() {
            self.last_step.next = 7.into();
        } else {
            self.last_step.next = 5.into();
        }
        match self.step.q.val().index() {
            0 => {
                self.kind.next = 0.into();
            }
            1 => {
                self.tx.next = self.dev.q.val() << 1;
            }
            2 => {
                self.tx.next = self.ra.q.val();
            }
            3 => {
                if self.rd.q.val() {
                    self.kind.next = 1.into();
                } else {
                    self.tx.next = self.wd.q.val().get_bits::<8>(8);
                }
            }
            4 => {
                if self.rd.q.val() {
                    self.tx.next = (self.dev.q.val() << 1) | 1;
                } else {
                    self.tx.next = self.wd.q.val().get_bits::<8>(0);
                }
            }
            5 => {
                if self.rd.q.val() {
                    self.rx.next = true;
                    self.ack_level.next = false;
                } else {
                    self.kind.next = 3.into();
                }
            }
            6 => {
                self.rx.next = true;
            }
            _ => {
                self.kind.next = 3.into();
            }
        }
        self.tx_shifted.next = self.tx.val() << self.bit_no.q.val();
        // SDA level of the current bit slot: data bits MSB first, then the ACK slot.
        self.level.next = true;
        if self.bit_no.q.val() == 8 {
            if self.rx.val() {
                self.level.next = self.ack_level.val();
            }
        } else if !self.rx.val() {
            self.level.next = self.tx_shifted.val().get_bit(7);
        }
        // Line levels per quarter (see the type's doc): SDA is kept in the quarter where SCL
        // falls.
        self.want_scl.next = false;
        self.want_sda.next = self.sda_r.q.val();
        match self.kind.val().index() {
            0 => {
                self.want_scl.next = self.quarter.q.val() != 3;
                self.want_sda.next = self.quarter.q.val() < 2;
            }
            1 => {
                self.want_scl.next = self.quarter.q.val() >= 2;
                if self.quarter.q.val() == 1 {
                    self.want_sda.next = true;
                }
                if self.quarter.q.val() == 3 {
                    self.want_sda.next = false;
                }
            }
            2 => {
                self.want_scl.next = self.quarter.q.val() >= 2;
                if self.quarter.q.val() != 0 {
                    self.want_sda.next = self.level.val();
                }
            }
            _ => {
                self.want_scl.next = self.quarter.q.val() >= 2;
                if self.quarter.q.val() == 1 {
                    self.want_sda.next = false;
                }
                if self.quarter.q.val() == 3 {
                    self.want_sda.next = true;
                }
            }
        }

        self.count_next.next = self.count.q.val() + 1;
        self.step_next.next = self.step.q.val() + 1;
        self.bit_next.next = self.bit_no.q.val() + 1;
        self.half_in.next = self.half_period.val() >> 1;

        if self.busy_r.q.val() {
            self.watchdog.d.next = self.watchdog.q.val() + 1;
            self.scl_r.d.next = self.want_scl.val();
            self.sda_r.d.next = self.want_sda.val();
            if self.watchdog.q.val() >= self.timeout_cycles.val() {
                self.busy_r.d.next = false;
                self.done_r.d.next = true;
                self.timeout_r.d.next = true;
                self.scl_r.d.next = true;
                self.sda_r.d.next = true;
            } else if self.scl_r.q.val() & !self.scl_sync1.q.val() {
                // SCL released but still low: stretched (or not yet through the synchroniser).
            } else if self.count_next.val() < self.quarter_len.q.val() {
                self.count.d.next = self.count_next.val();
            } else {
                self.count.d.next = 0.into();
                self.quarter.d.next = self.quarter.q.val() + 1;
                if (self.sda_r.q.val() & !self.sda_sync1.q.val())
                    & (((self.kind.val() == 0) & (self.quarter.q.val() == 1))
                        | ((self.kind.val() == 1) & (self.quarter.q.val() == 2))
                        | (((self.kind.val() == 2) & (self.quarter.q.val() == 3))
                            & (!self.rx.val() & (self.bit_no.q.val() != 8))))
                {
                    // A device holds SDA low where this master released it.
                    self.busy_r.d.next = false;
                    self.done_r.d.next = true;
                    self.stuck_r.d.next = true;
                    self.scl_r.d.next = true;
                    self.sda_r.d.next = true;
                } else if self.quarter.q.val() == 3 {
                    if self.kind.val() == 3 {
                        self.busy_r.d.next = false;
                        self.done_r.d.next = true;
                        self.nack_r.d.next = self.failed_nack.q.val();
                    } else if self.kind.val() == 2 {
                        if self.bit_no.q.val() == 8 {
                            self.bit_no.d.next = 0.into();
                            if !self.rx.val() & self.sda_sync1.q.val() {
                                self.failed_nack.d.next = true;
                                self.step.d.next = self.last_step.val();
                            } else {
                                self.step.d.next = self.step_next.val();
                            }
                        } else {
                            self.bit_no.d.next = self.bit_next.val();
                            if self.rx.val() {
                                self.rdata.d.next = (self.rdata.q.val() << 1)
                                    | bit_cast::<16, 1>(self.sda_sync1.q.val().into());
                            }
                        }
                    } else {
                        self.step.d.next = self.step_next.val();
                    }
                }
            }
        } else if self.start.val() {
            self.busy_r.d.next = true;
            self.rd.d.next = self.read.val();
            self.dev.d.next = bit_cast::<8, 7>(self.device.val());
            self.ra.d.next = self.reg_addr.val();
            self.wd.d.next = self.write_data.val();
            if self.half_in.val() == 0 {
                self.quarter_len.d.next = 1.into();
            } else {
                self.quarter_len.d.next = self.half_in.val();
            }
            self.step.d.next = 0.into();
            self.bit_no.d.next = 0.into();
            self.quarter.d.next = 0.into();
            self.count.d.next = 0.into();
            self.watchdog.d.next = 0.into();
            self.failed_nack.d.next = false;
            if self.read.val() {
                self.rdata.d.next = 0.into();
            }
        }

        self.scl_low.next = !self.scl_r.q.val();
        self.sda_low.next = !self.sda_r.q.val();
        self.busy.next = self.busy_r.q.val();
        self.done.next = self.done_r.q.val();
        self.nack.next = self.nack_r.q.val();
        self.timeout.next = self.timeout_r.q.val();
        self.bus_stuck.next = self.stuck_r.q.val();
        self.read_data.next = self.rdata.q.val();
    }
}
