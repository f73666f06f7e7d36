//! The I2C register-transaction master (`i2c.*`, `skylux_rtl::i2c::I2cMaster`) as whole
//! transactions: the outcome is decided at START from what the sensor's two-wire target would
//! do (its address, its injected `I2cFault`, RESET_BAR), and the status is raised when the
//! transaction would have ended on the wire. Needed so the drivers' I2C polling, NACK, stuck
//! bus and watchdog paths run against the hardware's timing and status bits.

use super::FabricModel;
use crate::mt9p031::registers::WriteEffect;
use crate::mt9p031::{I2cFault, MT9P031_ADDRESS};
use skylux_regmap::{i2c, sys};

/// Flip-flops between the pins and the master's logic: a released SCL is seen high this many
/// clocks late, which the master treats as stretching (`skylux_rtl::i2c::master::SYNC_STAGES`).
const SYNC_STAGES: u64 = 2;
/// Bits on the wire (START, bytes with their acknowledge, repeated START, STOP) of: a register
/// write `S {dev,W} A reg A hi A lo A P`; a read `S {dev,W} A reg A Sr {dev,R} A hi A lo N P`;
/// an address NACK `S {dev} N P`; a register-byte NACK `S {dev} A reg N P`
/// (hardware-facts.md §1.3).
const WRITE_BITS: u64 = 1 + 4 * 9 + 1;
const READ_BITS: u64 = 1 + 2 * 9 + 1 + 3 * 9 + 1;
const ADDRESS_NACK_BITS: u64 = 1 + 9 + 1;
const REGISTER_NACK_BITS: u64 = 1 + 2 * 9 + 1;

/// Who started a transaction.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Client {
    Hps,
    Sequencer,
}

/// How a transaction ends.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    Ok,
    Nack,
    Timeout,
    BusStuck,
}

/// A transaction on the wire.
#[derive(Copy, Clone, Debug)]
pub struct I2cJob {
    pub client: Client,
    pub done_at: u64,
    pub reg: u8,
    /// `None`: a read.
    pub write: Option<u16>,
    pub outcome: Outcome,
}

/// The master's state.
#[derive(Clone, Debug, Default)]
pub struct I2cMaster {
    pub job: Option<I2cJob>,
    /// Injected: the sensor does not acknowledge this register-address byte.
    pub nack_register: Option<u8>,
    /// `i2c.read_data`: the last read's value.
    pub read_data: u16,
    /// Transactions completed, by outcome, for tests.
    pub completed: u64,
    pub failed: u64,
    /// The sensor is released from reset (`i2c.sensor_pins.RESET_N`).
    pub reset_released: bool,
}

impl I2cMaster {
    pub fn next_event(&self) -> Option<u64> {
        self.job.map(|j| j.done_at)
    }

    pub fn busy(&self) -> bool {
        self.job.is_some()
    }
}

impl FabricModel {
    /// Starts a transaction for `client` now (the master must be idle). Returns false when
    /// it is busy (the START is ignored, as in the RTL).
    pub(super) fn i2c_begin(&mut self, client: Client, reg: u8, write: Option<u16>) -> bool {
        if self.i2c.busy() {
            return false;
        }
        let half = i2c::clock_div::HALF_PERIOD.get(self.stored(i2c::clock_div::REG.offset));
        let timeout = u64::from(i2c::timeout::CYCLES.get(self.stored(i2c::timeout::REG.offset)));
        let device = i2c::target::ADDR7.get(self.stored(i2c::target::REG.offset)) as u8;
        // Every bit is four quarters of `half / 2` clocks (at least 1), stretched by the
        // synchroniser delay when SCL is released.
        let bit = 4 * u64::from((half / 2).max(1)) + SYNC_STAGES;
        let answers = self.i2c.reset_released
            && device == MT9P031_ADDRESS
            && self.sensor.i2c.address == MT9P031_ADDRESS;
        let (outcome, duration) = match self.sensor.i2c.fault {
            I2cFault::SdaStuckLow => (Outcome::BusStuck, bit / 4 + 1),
            I2cFault::SclStuckLow => (Outcome::Timeout, timeout),
            I2cFault::Absent => (Outcome::Nack, ADDRESS_NACK_BITS * bit),
            _ if !answers => (Outcome::Nack, ADDRESS_NACK_BITS * bit),
            I2cFault::NackRegister => (Outcome::Nack, REGISTER_NACK_BITS * bit),
            _ if self.i2c.nack_register == Some(reg) => (Outcome::Nack, REGISTER_NACK_BITS * bit),
            _ if write.is_some() => (Outcome::Ok, WRITE_BITS * bit),
            _ => (Outcome::Ok, READ_BITS * bit),
        };
        // The watchdog ends anything still running `timeout` clocks after START.
        let (outcome, duration) = if duration > timeout {
            (Outcome::Timeout, timeout)
        } else {
            (outcome, duration)
        };
        self.i2c.job = Some(I2cJob {
            client,
            done_at: self.now + duration.max(1),
            reg,
            write,
            outcome,
        });
        true
    }

    /// `i2c.ctrl.START` from the HPS.
    pub(super) fn hps_i2c_start(&mut self) {
        if self.seq.owns_i2c() {
            self.regs
                .set_bits(i2c::status::REG.offset, i2c::status::REFUSED.mask());
            return;
        }
        let ctrl = self.stored(i2c::ctrl::REG.offset);
        let reg = i2c::reg_addr::ADDR.get(self.stored(i2c::reg_addr::REG.offset)) as u8;
        let write = (i2c::ctrl::READ.get(ctrl) == 0)
            .then(|| i2c::write_data::DATA.get(self.stored(i2c::write_data::REG.offset)) as u16);
        self.i2c_begin(Client::Hps, reg, write);
    }

    /// A transaction that ends now.
    pub(super) fn i2c_events(&mut self) {
        let Some(job) = self.i2c.job.filter(|j| j.done_at <= self.now) else {
            return;
        };
        self.i2c.job = None;
        use i2c::status as st;
        let mut bits = st::DONE.mask();
        match job.outcome {
            Outcome::Ok => {
                self.i2c.completed += 1;
                match job.write {
                    Some(v) => {
                        let effect = self.sensor.registers.write(job.reg, v);
                        self.sensor_register_written(effect);
                    }
                    None => self.i2c.read_data = self.sensor.registers.read(job.reg),
                }
            }
            Outcome::Nack => bits |= st::NACK.mask(),
            Outcome::Timeout => bits |= st::TIMEOUT.mask(),
            Outcome::BusStuck => bits |= st::BUS_STUCK.mask(),
        }
        if job.outcome != Outcome::Ok {
            self.i2c.failed += 1;
        }
        self.regs.set_bits(st::REG.offset, bits);
        self.irq(&sys::irq_status::I2C_DONE);
        if job.client == Client::Sequencer {
            self.sequencer_write_done(job.outcome == Outcome::Ok);
        }
    }

    /// What a completed register write does to the sensor besides storing the value.
    fn sensor_register_written(&mut self, effect: WriteEffect) {
        match effect {
            WriteEffect::SoftwareTrigger => self.sensor_trigger(),
            WriteEffect::SoftReset => self.sensor_reset(),
            WriteEffect::Stored | WriteEffect::Ignored => {}
        }
    }

    /// RESET_BAR: low resets the sensor (registers to power-up values, no frame); the sensor
    /// answers on the bus only while released.
    pub(super) fn sensor_pins_written(&mut self, released: bool) {
        if !released && self.i2c.reset_released {
            self.sensor.registers = Default::default();
            self.sensor_reset();
        }
        if released {
            self.log.reset_released = true;
        }
        self.i2c.reset_released = released;
    }

    pub(super) fn i2c_inputs(&mut self) {
        let busy = i2c::status::BUSY.word(self.i2c.busy().into());
        self.regs
            .fabric_inputs
            .insert(i2c::status::REG.offset, busy);
        self.regs.fabric_inputs.insert(
            i2c::read_data::REG.offset,
            i2c::read_data::DATA.word(self.i2c.read_data.into()),
        );
    }
}
