//! The MT9P031's two-wire target, cycle by cycle against a master's SCL and SDA on an
//! open-drain bus (hardware-facts.md §1.3: address 0x5D, 8-bit register pointer, 16-bit data
//! MSB first, the pointer auto-increments after each word).

use super::registers::{Registers, WriteEffect};

/// The sensor's 7-bit address (S_ADDR low; hardware-facts.md §1.3).
pub const MT9P031_ADDRESS: u8 = 0x5D;

/// The level of an open-drain line: high (pull-up) unless some device pulls it low.
pub fn wired_and(pulls_low: &[bool]) -> bool {
    !pulls_low.iter().any(|&low| low)
}

/// Injected faults.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum I2cFault {
    #[default]
    None,
    /// No device on the bus: nothing is ever acknowledged.
    Absent,
    /// The device acknowledges its address but refuses (NACKs) the register address byte.
    NackRegister,
    /// The device holds SDA low permanently.
    SdaStuckLow,
    /// The device holds SCL low permanently (endless clock stretching).
    SclStuckLow,
}

/// What the target does to the lines (true: pulls low).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub struct TargetDrive {
    pub scl_low: bool,
    pub sda_low: bool,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Phase {
    /// Waiting for START (also after an address that is not ours).
    Idle,
    /// Receiving a byte from the master (bits so far).
    Receive,
    /// Our ACK (or NACK) slot after a received byte.
    AckOut,
    /// Sending a byte to the master.
    Send,
    /// The master's ACK slot after a sent byte.
    AckIn,
}

/// Counters a test can check.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct TargetStats {
    pub starts: u32,
    pub stops: u32,
    pub register_writes: u32,
    pub register_reads: u32,
}

/// A register-protocol I2C target stepped once per sample of the bus.
#[derive(Clone, Debug)]
pub struct I2cTarget {
    pub address: u8,
    pub fault: I2cFault,
    /// Sample periods the target holds SCL low after each byte's ACK slot (clock stretching).
    pub stretch_cycles: u32,
    pub stats: TargetStats,
    phase: Phase,
    prev_scl: bool,
    prev_sda: bool,
    shift: u8,
    bits: u8,
    /// Byte index within the transfer after the address byte.
    byte_index: u32,
    reading: bool,
    ack_this: bool,
    pointer: u8,
    high_byte: u8,
    out_word: u16,
    stretch_left: u32,
    drive: TargetDrive,
    /// Effects of completed register writes, for the sensor to act on.
    pending: Vec<(u8, WriteEffect)>,
}

impl Default for I2cTarget {
    fn default() -> Self {
        Self::new(MT9P031_ADDRESS)
    }
}

impl I2cTarget {
    pub fn new(address: u8) -> Self {
        Self {
            address,
            fault: I2cFault::None,
            stretch_cycles: 0,
            stats: TargetStats::default(),
            phase: Phase::Idle,
            prev_scl: true,
            prev_sda: true,
            shift: 0,
            bits: 0,
            byte_index: 0,
            reading: false,
            ack_this: false,
            pointer: 0,
            high_byte: 0,
            out_word: 0,
            stretch_left: 0,
            drive: TargetDrive::default(),
            pending: vec![],
        }
    }

    /// What the target drives now.
    pub fn drive(&self) -> TargetDrive {
        match self.fault {
            I2cFault::SdaStuckLow => TargetDrive {
                scl_low: false,
                sda_low: true,
            },
            I2cFault::SclStuckLow => TargetDrive {
                scl_low: true,
                sda_low: false,
            },
            I2cFault::Absent => TargetDrive::default(),
            _ => self.drive,
        }
    }

    /// Register writes completed since the last call, with their effects.
    pub fn take_writes(&mut self) -> Vec<(u8, WriteEffect)> {
        std::mem::take(&mut self.pending)
    }

    fn bit_out(&self) -> bool {
        // The current bit of the word being sent: high byte first, MSB first.
        let byte = if self.byte_index.is_multiple_of(2) {
            (self.out_word >> 8) as u8
        } else {
            self.out_word as u8
        };
        byte & (0x80 >> self.bits) != 0
    }

    /// One sample of the bus levels (`scl`, `sda`: the wired-AND levels, including this
    /// target's own drive). Updates what the target drives.
    pub fn step(&mut self, scl: bool, sda: bool, registers: &mut Registers) {
        let (rise, fall) = (scl && !self.prev_scl, !scl && self.prev_scl);
        let start = scl && self.prev_scl && self.prev_sda && !sda;
        let stop = scl && self.prev_scl && !self.prev_sda && sda;
        self.prev_scl = scl;
        self.prev_sda = sda;
        if self.stretch_left > 0 {
            self.stretch_left -= 1;
            self.drive.scl_low = self.stretch_left > 0;
        }
        if start {
            self.stats.starts += 1;
            self.phase = Phase::Receive;
            self.shift = 0;
            self.bits = 0;
            self.drive.sda_low = false;
            self.reading = false;
            self.ack_this = false;
            // Marker: the next byte is an address byte.
            self.byte_index = u32::MAX;
            return;
        }
        if stop {
            self.stats.stops += 1;
            self.phase = Phase::Idle;
            self.drive = TargetDrive::default();
            return;
        }
        match self.phase {
            Phase::Idle => {}
            Phase::Receive => {
                if rise {
                    self.shift = (self.shift << 1) | u8::from(sda);
                    self.bits += 1;
                } else if fall && self.bits == 8 {
                    self.received_byte(registers);
                    self.phase = Phase::AckOut;
                    self.drive.sda_low = self.ack_this;
                }
            }
            Phase::AckOut => {
                if fall {
                    self.drive.sda_low = false;
                    if !self.ack_this {
                        self.phase = Phase::Idle;
                        return;
                    }
                    if self.stretch_cycles > 0 {
                        self.stretch_left = self.stretch_cycles;
                        self.drive.scl_low = true;
                    }
                    self.bits = 0;
                    self.shift = 0;
                    if self.reading {
                        self.phase = Phase::Send;
                        self.drive.sda_low = !self.bit_out();
                    } else {
                        self.phase = Phase::Receive;
                    }
                }
            }
            Phase::Send => {
                if fall {
                    self.bits += 1;
                    if self.bits == 8 {
                        self.phase = Phase::AckIn;
                        self.drive.sda_low = false;
                    } else {
                        self.drive.sda_low = !self.bit_out();
                    }
                }
            }
            Phase::AckIn => {
                if rise {
                    // The master's ACK: low continues, high (NACK) ends the read.
                    self.ack_this = !sda;
                } else if fall {
                    if !self.ack_this {
                        self.phase = Phase::Idle;
                        self.drive.sda_low = false;
                        return;
                    }
                    self.byte_index += 1;
                    if self.byte_index.is_multiple_of(2) {
                        self.pointer = self.pointer.wrapping_add(1);
                        self.out_word = registers.read(self.pointer);
                        self.stats.register_reads += 1;
                    }
                    self.bits = 0;
                    self.phase = Phase::Send;
                    self.drive.sda_low = !self.bit_out();
                }
            }
        }
    }

    fn received_byte(&mut self, registers: &mut Registers) {
        let byte = self.shift;
        if self.byte_index == u32::MAX {
            // Address byte.
            self.ack_this = byte >> 1 == self.address;
            self.reading = byte & 1 == 1;
            self.byte_index = 0;
            if self.ack_this && self.reading {
                self.out_word = registers.read(self.pointer);
                self.stats.register_reads += 1;
            }
            return;
        }
        self.ack_this = true;
        if self.byte_index == 0 {
            if self.fault == I2cFault::NackRegister {
                self.ack_this = false;
            }
            self.pointer = byte;
        } else if self.byte_index % 2 == 1 {
            self.high_byte = byte;
        } else {
            let value = u16::from(self.high_byte) << 8 | u16::from(byte);
            let effect = registers.write(self.pointer, value);
            self.stats.register_writes += 1;
            self.pending.push((self.pointer, effect));
            self.pointer = self.pointer.wrapping_add(1);
        }
        self.byte_index += 1;
    }
}
