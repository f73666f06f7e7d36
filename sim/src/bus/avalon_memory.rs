//! An Avalon-MM memory agent model standing in for SDRAM behind an f2sdram port: byte-addressed
//! storage, a configurable data width, read and write bursts, variable-latency pipelined reads
//! (`readdatavalid`, in order), and random `waitrequest` from a seed (Avalon Interface
//! Specifications §3.5 to §3.7; hardware-facts.md §4).
//!
//! It is signal-agnostic: each cycle the harness asks [`AvalonMemory::begin_cycle`] for the
//! agent's outputs, drives them into the host, samples the host's command, and hands it to
//! [`AvalonMemory::end_cycle`] at the rising edge. Protocol violations by the host are
//! recorded, never panicked on, so a test can assert there were none.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::collections::VecDeque;

/// How the host's `address` counts.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum AddressUnit {
    /// Byte addresses (an Avalon host behind Platform Designer's interconnect).
    Bytes,
    /// Word addresses of the data width (the HPS f2sdram conduit, hardware-facts.md §3.2).
    Words,
}

/// The model's configuration.
#[derive(Clone, Debug)]
pub struct AvalonMemoryConfig {
    /// Data width in bytes (1 to 16, a power of two).
    pub width_bytes: usize,
    pub address_unit: AddressUnit,
    /// Physical address of the first byte of the storage.
    pub base: u64,
    /// Storage size in bytes.
    pub size_bytes: usize,
    /// Probability that waitrequest is high in a cycle.
    pub waitrequest_probability: f64,
    /// Cycles from an accepted read command to its first data beat (at least 1).
    pub read_latency_cycles: usize,
    /// Probability that a due read beat is held back one more cycle.
    pub read_gap_probability: f64,
    /// Largest burst accepted (Avalon: 2^(n-1) for an n-bit burstcount).
    pub max_burst: u32,
    pub seed: u64,
}

impl Default for AvalonMemoryConfig {
    /// A 64-bit f2sdram-like port: word addresses, bursts up to 128, no stalls.
    fn default() -> Self {
        Self {
            width_bytes: 8,
            address_unit: AddressUnit::Words,
            base: 0,
            size_bytes: 1 << 16,
            waitrequest_probability: 0.0,
            read_latency_cycles: 4,
            read_gap_probability: 0.0,
            max_burst: 128,
            seed: 1,
        }
    }
}

/// What the host drives in a cycle (sampled just before the rising edge).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct HostCommand {
    pub address: u64,
    pub read: bool,
    pub write: bool,
    pub burstcount: u32,
    /// Little-endian data, `width_bytes` of it used.
    pub writedata: u128,
    pub byteenable: u32,
}

/// What the agent drives in a cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct AgentOutputs {
    pub waitrequest: bool,
    pub readdatavalid: bool,
    pub readdata: u128,
}

/// One accepted burst, for checking where a host went.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Access {
    pub write: bool,
    /// Physical byte address of the first beat.
    pub address: u64,
    pub bytes: u64,
}

/// A protocol violation or an access the storage does not hold.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Violation {
    ReadAndWrite {
        cycle: u64,
    },
    BadBurstCount {
        cycle: u64,
        burstcount: u32,
    },
    ReadDuringWriteBurst {
        cycle: u64,
    },
    WriteBurstChanged {
        cycle: u64,
    },
    Unaligned {
        cycle: u64,
        address: u64,
    },
    OutOfRange {
        cycle: u64,
        address: u64,
        bytes: u64,
    },
    CommandDroppedUnderWaitrequest {
        cycle: u64,
    },
}

struct WriteBurst {
    next_byte: u64,
    beats_left: u32,
    burstcount: u32,
}

/// The memory agent model.
pub struct AvalonMemory {
    pub config: AvalonMemoryConfig,
    bytes: Vec<u8>,
    rng: StdRng,
    cycle: u64,
    outputs: AgentOutputs,
    /// Read beats due: (cycle from which it may be returned, physical byte address).
    pending_reads: VecDeque<(u64, u64)>,
    write_burst: Option<WriteBurst>,
    /// The command the host held under waitrequest last cycle, if any.
    stalled: Option<HostCommand>,
    pub accesses: Vec<Access>,
    pub violations: Vec<Violation>,
    /// Cycles in which waitrequest was high.
    pub waitrequest_cycles: u64,
    /// When set, waitrequest stays high from this cycle on (a hung port).
    pub hang_from_cycle: Option<u64>,
}

impl AvalonMemory {
    pub fn new(config: AvalonMemoryConfig) -> Self {
        let w = config.width_bytes.clamp(1, 16).next_power_of_two();
        let config = AvalonMemoryConfig {
            width_bytes: w,
            read_latency_cycles: config.read_latency_cycles.max(1),
            ..config
        };
        Self {
            bytes: vec![0; config.size_bytes],
            rng: StdRng::seed_from_u64(config.seed),
            config,
            cycle: 0,
            outputs: AgentOutputs::default(),
            pending_reads: VecDeque::new(),
            write_burst: None,
            stalled: None,
            accesses: vec![],
            violations: vec![],
            waitrequest_cycles: 0,
            hang_from_cycle: None,
        }
    }

    /// Cycles run so far.
    pub fn cycles(&self) -> u64 {
        self.cycle
    }

    /// Read beats still to be returned.
    pub fn reads_pending(&self) -> usize {
        self.pending_reads.len()
    }

    /// The storage's bytes at physical `address`, if it holds them all.
    pub fn slice(&self, address: u64, len: usize) -> Option<&[u8]> {
        let off = address.checked_sub(self.config.base)? as usize;
        self.bytes.get(off..off.checked_add(len)?)
    }

    /// Mutable storage at physical `address`, if it holds it all.
    pub fn slice_mut(&mut self, address: u64, len: usize) -> Option<&mut [u8]> {
        let off = address.checked_sub(self.config.base)? as usize;
        self.bytes.get_mut(off..off.checked_add(len)?)
    }

    fn byte_address(&self, address: u64) -> u64 {
        match self.config.address_unit {
            AddressUnit::Bytes => address,
            AddressUnit::Words => address * self.config.width_bytes as u64,
        }
    }

    fn in_range(&self, address: u64, bytes: u64) -> bool {
        self.slice(address, bytes as usize).is_some()
    }

    /// The agent's outputs for this cycle: waitrequest (random, or a hang) and the next read
    /// beat if one is due.
    pub fn begin_cycle(&mut self) -> AgentOutputs {
        let hung = self.hang_from_cycle.is_some_and(|c| self.cycle >= c);
        let waitrequest = hung || self.rng.gen_bool(self.config.waitrequest_probability);
        let mut out = AgentOutputs {
            waitrequest,
            ..Default::default()
        };
        if let Some(&(due, address)) = self.pending_reads.front() {
            if !hung && due <= self.cycle && !self.rng.gen_bool(self.config.read_gap_probability) {
                self.pending_reads.pop_front();
                out.readdatavalid = true;
                let w = self.config.width_bytes;
                let mut le = [0u8; 16];
                if let Some(s) = self.slice(address, w) {
                    le[..w].copy_from_slice(s);
                }
                out.readdata = u128::from_le_bytes(le);
            }
        }
        self.outputs = out;
        out
    }

    /// The rising edge: the host's command as sampled just before it.
    pub fn end_cycle(&mut self, cmd: &HostCommand) {
        let cycle = self.cycle;
        self.cycle += 1;
        if self.outputs.waitrequest {
            self.waitrequest_cycles += 1;
        }
        if let Some(prev) = self.stalled.take() {
            if !(cmd.read || cmd.write) || cmd.read != prev.read || cmd.address != prev.address {
                self.violations
                    .push(Violation::CommandDroppedUnderWaitrequest { cycle });
            }
        }
        if cmd.read && cmd.write {
            self.violations.push(Violation::ReadAndWrite { cycle });
            return;
        }
        if !(cmd.read || cmd.write) {
            return;
        }
        if self.outputs.waitrequest {
            self.stalled = Some(*cmd);
            return;
        }
        let w = self.config.width_bytes as u64;
        if cmd.read {
            if self.write_burst.is_some() {
                self.violations
                    .push(Violation::ReadDuringWriteBurst { cycle });
                return;
            }
            if cmd.burstcount == 0 || cmd.burstcount > self.config.max_burst {
                self.violations.push(Violation::BadBurstCount {
                    cycle,
                    burstcount: cmd.burstcount,
                });
                return;
            }
            let address = self.byte_address(cmd.address);
            let bytes = w * cmd.burstcount as u64;
            if !address.is_multiple_of(w) {
                self.violations
                    .push(Violation::Unaligned { cycle, address });
            }
            if !self.in_range(address, bytes) {
                self.violations.push(Violation::OutOfRange {
                    cycle,
                    address,
                    bytes,
                });
            }
            self.accesses.push(Access {
                write: false,
                address,
                bytes,
            });
            let first = self.cycle + self.config.read_latency_cycles as u64 - 1;
            for k in 0..cmd.burstcount as u64 {
                self.pending_reads.push_back((first, address + k * w));
            }
            return;
        }
        // A write beat: the first of a burst carries address and burstcount.
        let mut burst = match self.write_burst.take() {
            Some(b) => {
                if cmd.burstcount != b.burstcount {
                    self.violations.push(Violation::WriteBurstChanged { cycle });
                }
                b
            }
            None => {
                if cmd.burstcount == 0 || cmd.burstcount > self.config.max_burst {
                    self.violations.push(Violation::BadBurstCount {
                        cycle,
                        burstcount: cmd.burstcount,
                    });
                    return;
                }
                let address = self.byte_address(cmd.address);
                let bytes = w * cmd.burstcount as u64;
                if !address.is_multiple_of(w) {
                    self.violations
                        .push(Violation::Unaligned { cycle, address });
                }
                if !self.in_range(address, bytes) {
                    self.violations.push(Violation::OutOfRange {
                        cycle,
                        address,
                        bytes,
                    });
                }
                self.accesses.push(Access {
                    write: true,
                    address,
                    bytes,
                });
                WriteBurst {
                    next_byte: address,
                    beats_left: cmd.burstcount,
                    burstcount: cmd.burstcount,
                }
            }
        };
        let data = cmd.writedata.to_le_bytes();
        let (address, enables) = (burst.next_byte, cmd.byteenable);
        if let Some(s) = self.slice_mut(address, w as usize) {
            for (i, b) in s.iter_mut().enumerate() {
                if enables & (1 << i) != 0 {
                    *b = data[i];
                }
            }
        }
        burst.next_byte += w;
        burst.beats_left -= 1;
        if burst.beats_left > 0 {
            self.write_burst = Some(burst);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scripted host: one read burst and one write burst of 3 beats through random stalls.
    #[test]
    fn bursts_through_random_waitrequest() {
        let mut m = AvalonMemory::new(AvalonMemoryConfig {
            waitrequest_probability: 0.4,
            read_gap_probability: 0.3,
            size_bytes: 256,
            seed: 7,
            ..Default::default()
        });
        for (i, b) in m.slice_mut(0, 256).unwrap().iter_mut().enumerate() {
            *b = i as u8;
        }
        // Write words 4, 5, 6 with 0x11.., 0x22.., 0x33.. (byte 1 of the middle one masked).
        let mut beat = 0;
        while beat < 3 {
            let out = m.begin_cycle();
            let cmd = HostCommand {
                address: 4,
                write: true,
                burstcount: 3,
                writedata: 0x1111_1111_1111_1111u128 * (beat + 1),
                byteenable: if beat == 1 { 0xFD } else { 0xFF },
                ..Default::default()
            };
            m.end_cycle(&cmd);
            if !out.waitrequest {
                beat += 1;
            }
        }
        // Read words 3..7 back as one burst.
        loop {
            let out = m.begin_cycle();
            m.end_cycle(&HostCommand {
                address: 3,
                read: true,
                burstcount: 4,
                ..Default::default()
            });
            if !out.waitrequest {
                break;
            }
        }
        let mut got = vec![];
        for _ in 0..100 {
            let out = m.begin_cycle();
            m.end_cycle(&HostCommand::default());
            if out.readdatavalid {
                got.push(out.readdata as u64);
            }
        }
        let word3 = u64::from_le_bytes(core::array::from_fn(|i| 24 + i as u8));
        assert_eq!(
            got,
            vec![
                word3,
                0x1111_1111_1111_1111,
                0x2222_2222_2222_2222 & !0xFF00 | (41u64 << 8),
                0x3333_3333_3333_3333
            ]
        );
        assert!(m.violations.is_empty(), "{:?}", m.violations);
        assert!(m.waitrequest_cycles > 0);
        assert_eq!(
            m.accesses,
            vec![
                Access {
                    write: true,
                    address: 32,
                    bytes: 24
                },
                Access {
                    write: false,
                    address: 24,
                    bytes: 32
                }
            ]
        );
    }

    #[test]
    fn violations_are_recorded() {
        let mut m = AvalonMemory::new(AvalonMemoryConfig {
            size_bytes: 64,
            address_unit: AddressUnit::Bytes,
            ..Default::default()
        });
        m.begin_cycle();
        m.end_cycle(&HostCommand {
            address: 60,
            read: true,
            burstcount: 1,
            ..Default::default()
        });
        m.begin_cycle();
        m.end_cycle(&HostCommand {
            address: 0,
            read: true,
            write: true,
            burstcount: 1,
            ..Default::default()
        });
        m.begin_cycle();
        m.end_cycle(&HostCommand {
            address: 0,
            write: true,
            burstcount: 0,
            ..Default::default()
        });
        assert_eq!(
            m.violations,
            vec![
                Violation::Unaligned {
                    cycle: 0,
                    address: 60
                },
                Violation::OutOfRange {
                    cycle: 0,
                    address: 60,
                    bytes: 8
                },
                Violation::ReadAndWrite { cycle: 1 },
                Violation::BadBurstCount {
                    cycle: 2,
                    burstcount: 0
                },
            ]
        );
    }
}
