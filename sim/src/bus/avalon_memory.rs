//! The Avalon-MM memory agent model: SDRAM behind an f2sdram port, as every host in the fabric
//! sees it. Byte-addressed storage, a configurable data width, word or byte addresses, read
//! and write bursts, variable-latency pipelined reads (`readdatavalid`, in order), and
//! `waitrequest` from a seeded [`WaitPolicy`]: random, long stalls, and one deterministic hold
//! (Avalon Interface Specifications §3.5 to §3.7; hardware-facts.md §4).
//!
//! It is the only model of that port. The frame DMA (`capture_path`, `core_rig` port 0) and
//! the ray-box unit (`raybox`, `core_rig` port 1) are checked by the same code, so a protocol
//! rule or a kind of back-pressure added for one host holds for all of them, and a host that
//! passes in one harness cannot break the rules in another. (The capture path once had a
//! write-only model of its own, `f2sdram.rs`; this one absorbed it.)
//!
//! It is signal-agnostic: each cycle the harness asks [`AvalonMemory::begin_cycle`] for the
//! agent's outputs, drives them into the host, samples the host's command, and hands it to
//! [`AvalonMemory::end_cycle`] at the rising edge. Protocol violations by the host, and writes
//! outside the allowed window, are recorded as [`Violation`]s, never panicked on, so a test
//! can assert there were none. The HPS reads the storage through `skylux_bus::DmaMemory`, as
//! it reads the reserved buffer on the board.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use skylux_bus::{check_access, BusError, DmaMemory};
use std::collections::VecDeque;

/// Largest burst of the f2sdram port's 8-bit burstcount (hardware-facts.md §3.2, §4).
pub const MAX_BURST_BEATS: u32 = 128;

/// How the host's `address` counts.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum AddressUnit {
    /// Byte addresses (an Avalon host behind Platform Designer's interconnect).
    Bytes,
    /// Word addresses of the data width (the HPS f2sdram conduit, hardware-facts.md §3.2).
    Words,
}

/// When the agent stalls the host (`AvalonMemoryConfig::wait`).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct WaitPolicy {
    /// Probability of waitrequest in any cycle.
    pub random: f64,
    /// Probability that a long stall starts in a cycle, and its length (a refresh, another
    /// port's burst).
    pub stall_start: f64,
    pub stall_cycles: u64,
    /// One deterministic stall: from this cycle, for this many cycles (back-pressure tests).
    pub hold_from_cycle: u64,
    pub hold_cycles: u64,
}

impl WaitPolicy {
    /// Never stalls.
    pub const NONE: WaitPolicy = WaitPolicy {
        random: 0.0,
        stall_start: 0.0,
        stall_cycles: 0,
        hold_from_cycle: 0,
        hold_cycles: 0,
    };

    /// waitrequest in a random `fraction` of cycles.
    pub fn random(fraction: f64) -> Self {
        WaitPolicy {
            random: fraction,
            ..Self::NONE
        }
    }
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
    /// When waitrequest is high.
    pub wait: WaitPolicy,
    /// Physical byte range `(base, bytes)` the host may write. A write beat outside it is
    /// recorded as [`Violation::OutsideWindow`] and not written. `None`: all of the storage.
    pub write_window: Option<(u64, u64)>,
    /// Every write beat must enable every byte (the frame DMA's rule). Avalon itself allows
    /// partial byte enables, and the model honours them either way.
    pub require_full_byteenable: bool,
    /// Cycles from an accepted read command to its first data beat (at least 1).
    pub read_latency_cycles: usize,
    /// Probability that a due read beat is held back one more cycle.
    pub read_gap_probability: f64,
    /// Largest burst accepted (Avalon: 2^(n-1) for an n-bit burstcount).
    pub max_burst: u32,
    pub seed: u64,
}

impl Default for AvalonMemoryConfig {
    /// A 64-bit f2sdram-like port: word addresses, bursts up to 128, no stalls, no window.
    fn default() -> Self {
        Self {
            width_bytes: 8,
            address_unit: AddressUnit::Words,
            base: 0,
            size_bytes: 1 << 16,
            wait: WaitPolicy::NONE,
            write_window: None,
            require_full_byteenable: false,
            read_latency_cycles: 4,
            read_gap_probability: 0.0,
            max_burst: MAX_BURST_BEATS,
            seed: 1,
        }
    }
}

impl AvalonMemoryConfig {
    /// This configuration with `policy` as its waitrequest policy.
    pub fn with_wait_policy(self, policy: WaitPolicy) -> Self {
        Self {
            wait: policy,
            ..self
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

/// A protocol violation, an access the storage does not hold, or a write it must not take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Violation {
    ReadAndWrite {
        cycle: u64,
    },
    /// burstcount 0 or above the port's largest burst (the command is ignored).
    BadBurstCount {
        cycle: u64,
        burstcount: u32,
    },
    ReadDuringWriteBurst {
        cycle: u64,
    },
    /// Address or burstcount changed inside a write burst (the f2sdram hosts keep them
    /// constant through the burst).
    WriteBurstChanged {
        cycle: u64,
    },
    /// An address not aligned to the data width.
    Unaligned {
        cycle: u64,
        address: u64,
    },
    /// A command reaching bytes the storage does not have (those bytes are not written).
    OutOfRange {
        cycle: u64,
        address: u64,
        bytes: u64,
    },
    CommandDroppedUnderWaitrequest {
        cycle: u64,
    },
    /// A write beat without every byte enabled, where the configuration requires them all.
    PartialByteEnable {
        cycle: u64,
        byteenable: u32,
    },
    /// A write beat outside the allowed write window (it was not written).
    OutsideWindow {
        cycle: u64,
        address: u64,
        bytes: u64,
    },
}

#[derive(Clone, Debug)]
struct WriteBurst {
    /// The first beat's `address` and `burstcount`, as the host drove them.
    address: u64,
    burstcount: u32,
    next_byte: u64,
    beats_left: u32,
}

/// The memory agent model.
#[derive(Clone, Debug)]
pub struct AvalonMemory {
    pub config: AvalonMemoryConfig,
    bytes: Vec<u8>,
    rng: StdRng,
    cycle: u64,
    outputs: AgentOutputs,
    /// Cycles left in the current long stall.
    stall_left: u64,
    /// Read beats due: (cycle from which it may be returned, physical byte address).
    pending_reads: VecDeque<(u64, u64)>,
    write_burst: Option<WriteBurst>,
    /// The command the host held under waitrequest last cycle, if any.
    stalled: Option<HostCommand>,
    pub accesses: Vec<Access>,
    pub violations: Vec<Violation>,
    /// Cycles in which waitrequest was high.
    pub waitrequest_cycles: u64,
    /// Cycles in which the host drove a command and waitrequest held it off.
    pub stall_cycles: u64,
    /// Write beats taken (including beats refused outside the write window).
    pub beats: u64,
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
            stall_left: 0,
            pending_reads: VecDeque::new(),
            write_burst: None,
            stalled: None,
            accesses: vec![],
            violations: vec![],
            waitrequest_cycles: 0,
            stall_cycles: 0,
            beats: 0,
            hang_from_cycle: None,
        }
    }

    /// Changes the waitrequest policy from the next cycle on.
    pub fn set_wait_policy(&mut self, policy: WaitPolicy) {
        self.config.wait = policy;
    }

    /// Cycles run so far.
    pub fn cycles(&self) -> u64 {
        self.cycle
    }

    /// Read beats still to be returned.
    pub fn reads_pending(&self) -> usize {
        self.pending_reads.len()
    }

    /// Whether a write burst is in progress.
    pub fn in_write_burst(&self) -> bool {
        self.write_burst.is_some()
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

    fn in_write_window(&self, address: u64, bytes: u64) -> bool {
        self.config.write_window.is_none_or(|(base, size)| {
            address >= base && address.saturating_add(bytes) <= base.saturating_add(size)
        })
    }

    /// The agent's outputs for this cycle: waitrequest (a hang, the hold, a long stall or a
    /// random stall) and the next read beat if one is due.
    pub fn begin_cycle(&mut self) -> AgentOutputs {
        let c = &self.config;
        let hung = self.hang_from_cycle.is_some_and(|h| self.cycle >= h);
        let w = &c.wait;
        let held = self.cycle >= w.hold_from_cycle
            && self.cycle < w.hold_from_cycle.saturating_add(w.hold_cycles);
        // A long stall runs its length; the cycle after it, none starts.
        if self.stall_left > 0 {
            self.stall_left -= 1;
        } else if w.stall_start > 0.0 && self.rng.gen_bool(w.stall_start.min(1.0)) {
            self.stall_left = w.stall_cycles;
        }
        let random = !hung && self.rng.gen_bool(w.random.min(1.0));
        let mut out = AgentOutputs {
            waitrequest: hung || held || self.stall_left > 0 || random,
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
            self.stall_cycles += 1;
            return;
        }
        if cmd.read {
            self.read_command(cycle, cmd);
        } else {
            self.write_beat(cycle, cmd);
        }
    }

    /// The checks every command makes when it starts a transfer (a read, or a write burst's
    /// first beat): burstcount, alignment and range. Logs the access and returns its physical
    /// byte address, or `None` when the burstcount makes it no transfer at all.
    fn check_command(&mut self, cycle: u64, cmd: &HostCommand) -> Option<u64> {
        if cmd.burstcount == 0 || cmd.burstcount > self.config.max_burst {
            self.violations.push(Violation::BadBurstCount {
                cycle,
                burstcount: cmd.burstcount,
            });
            return None;
        }
        let w = self.config.width_bytes as u64;
        let address = self.byte_address(cmd.address);
        let bytes = w * u64::from(cmd.burstcount);
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
            write: cmd.write,
            address,
            bytes,
        });
        Some(address)
    }

    fn read_command(&mut self, cycle: u64, cmd: &HostCommand) {
        if self.write_burst.is_some() {
            self.violations
                .push(Violation::ReadDuringWriteBurst { cycle });
            return;
        }
        let Some(address) = self.check_command(cycle, cmd) else {
            return;
        };
        let w = self.config.width_bytes as u64;
        let first = self.cycle + self.config.read_latency_cycles as u64 - 1;
        for k in 0..u64::from(cmd.burstcount) {
            self.pending_reads.push_back((first, address + k * w));
        }
    }

    /// A write beat: the first of a burst carries address and burstcount.
    fn write_beat(&mut self, cycle: u64, cmd: &HostCommand) {
        let mut burst = match self.write_burst.take() {
            Some(b) => {
                if cmd.address != b.address || cmd.burstcount != b.burstcount {
                    self.violations.push(Violation::WriteBurstChanged { cycle });
                }
                b
            }
            None => {
                let Some(address) = self.check_command(cycle, cmd) else {
                    return;
                };
                WriteBurst {
                    address: cmd.address,
                    burstcount: cmd.burstcount,
                    next_byte: address,
                    beats_left: cmd.burstcount,
                }
            }
        };
        let w = self.config.width_bytes;
        let full = (1u32 << w) - 1;
        if self.config.require_full_byteenable && cmd.byteenable & full != full {
            self.violations.push(Violation::PartialByteEnable {
                cycle,
                byteenable: cmd.byteenable,
            });
        }
        self.beats += 1;
        let address = burst.next_byte;
        if !self.in_write_window(address, w as u64) {
            self.violations.push(Violation::OutsideWindow {
                cycle,
                address,
                bytes: w as u64,
            });
        } else if let Some(s) = self.slice_mut(address, w) {
            let data = cmd.writedata.to_le_bytes();
            for (i, b) in s.iter_mut().enumerate() {
                if cmd.byteenable & (1 << i) != 0 {
                    *b = data[i];
                }
            }
        }
        burst.next_byte += w as u64;
        burst.beats_left -= 1;
        if burst.beats_left > 0 {
            self.write_burst = Some(burst);
        }
    }
}

/// The storage as the HPS sees its DMA buffer: offsets from `config.base`.
impl DmaMemory for AvalonMemory {
    fn phys_base(&self) -> u64 {
        self.config.base
    }
    fn len_bytes(&self) -> u64 {
        self.bytes.len() as u64
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        check_access(offset, buf.len() as u64, self.len_bytes(), 1)?;
        let o = offset as usize;
        buf.copy_from_slice(&self.bytes[o..o + buf.len()]);
        Ok(())
    }
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        check_access(offset, data.len() as u64, self.len_bytes(), 1)?;
        let o = offset as usize;
        self.bytes[o..o + data.len()].copy_from_slice(data);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scripted host: one read burst and one write burst of 3 beats through random stalls.
    #[test]
    fn bursts_through_random_waitrequest() {
        let mut m = AvalonMemory::new(AvalonMemoryConfig {
            wait: WaitPolicy::random(0.4),
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

    fn write(address: u64, burstcount: u32, writedata: u128) -> HostCommand {
        HostCommand {
            address,
            write: true,
            burstcount,
            writedata,
            byteenable: 0xFF,
            ..Default::default()
        }
    }

    /// One cycle of a harness that drives every command until it is taken; returns whether
    /// it was (waitrequest low).
    fn cycle(m: &mut AvalonMemory, cmd: &HostCommand) -> bool {
        let out = m.begin_cycle();
        m.end_cycle(cmd);
        !out.waitrequest
    }

    /// The frame DMA's port: byte addresses, full byte enables, a window inside the storage.
    fn frame_port(policy: WaitPolicy) -> AvalonMemory {
        AvalonMemory::new(
            AvalonMemoryConfig {
                address_unit: AddressUnit::Bytes,
                base: 0,
                size_bytes: 256,
                write_window: Some((64, 64)),
                require_full_byteenable: true,
                seed: 7,
                ..Default::default()
            }
            .with_wait_policy(policy),
        )
    }

    #[test]
    fn write_burst_counts_beats_and_stalls_and_reads_back_through_dma_memory() {
        let mut m = frame_port(WaitPolicy::random(0.5));
        let (mut written, mut cycles) = (0u64, 0u64);
        while written < 4 {
            if cycle(&mut m, &write(80, 4, 0x1111 * u128::from(written + 1))) {
                written += 1;
            }
            cycles += 1;
        }
        assert!(m.violations.is_empty(), "{:?}", m.violations);
        assert!(!m.in_write_burst());
        assert_eq!(m.beats, 4);
        assert_eq!(m.stall_cycles, cycles - 4);
        assert_eq!(m.stall_cycles, m.waitrequest_cycles);
        assert!(m.stall_cycles > 0);
        let mut buf = [0u8; 8];
        m.read_bytes(80 + 3 * 8, &mut buf).unwrap();
        assert_eq!(u64::from_le_bytes(buf), 0x4444);
        assert_eq!((m.phys_base(), m.len_bytes()), (0, 256));
        m.write_bytes(0, &[9]).unwrap();
        assert_eq!(m.slice(0, 1), Some(&[9u8][..]));
        assert!(m.read_bytes(250, &mut buf).is_err());
    }

    #[test]
    fn writes_outside_the_window_are_refused_and_recorded() {
        let mut m = frame_port(WaitPolicy::NONE);
        // A burst from inside the window across its end: the second beat is refused.
        cycle(&mut m, &write(120, 2, 5));
        cycle(&mut m, &write(120, 2, 6));
        assert_eq!(
            m.violations,
            vec![Violation::OutsideWindow {
                cycle: 1,
                address: 128,
                bytes: 8
            }]
        );
        assert_eq!(m.beats, 2);
        assert_eq!(m.slice(120, 1), Some(&[5u8][..]));
        assert_eq!(m.slice(128, 1), Some(&[0u8][..]));
        m.violations.clear();
        // No transfer at all: nothing written, nothing counted.
        cycle(&mut m, &write(64, 0, 1));
        assert_eq!(
            m.violations,
            vec![Violation::BadBurstCount {
                cycle: 2,
                burstcount: 0
            }]
        );
        assert_eq!(m.beats, 2);
        m.violations.clear();
        // The address changes inside a burst, then the burstcount; then a partial byte enable.
        cycle(&mut m, &write(72, 3, 1));
        cycle(&mut m, &write(80, 3, 2));
        cycle(&mut m, &write(72, 2, 3));
        assert!(!m.in_write_burst());
        cycle(
            &mut m,
            &HostCommand {
                byteenable: 0x0F,
                ..write(64, 1, u128::MAX)
            },
        );
        assert_eq!(
            m.violations,
            vec![
                Violation::WriteBurstChanged { cycle: 4 },
                Violation::WriteBurstChanged { cycle: 5 },
                Violation::PartialByteEnable {
                    cycle: 6,
                    byteenable: 0x0F
                },
            ]
        );
        // The enabled bytes were written, the others kept.
        assert_eq!(
            m.slice(64, 8),
            Some(&[0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0][..])
        );
    }

    #[test]
    fn long_stalls_and_the_hold_drive_waitrequest() {
        // The hold: cycles 3 to 5 exactly, and nothing else.
        let mut m = frame_port(WaitPolicy {
            hold_from_cycle: 3,
            hold_cycles: 3,
            ..WaitPolicy::NONE
        });
        let waits: Vec<bool> = (0..10)
            .map(|_| !cycle(&mut m, &HostCommand::default()))
            .collect();
        let want: Vec<bool> = (0..10).map(|c| (3..6).contains(&c)).collect();
        assert_eq!(waits, want);
        // Long stalls: runs of exactly their length, each followed by a free cycle.
        let mut m = frame_port(WaitPolicy {
            stall_start: 0.2,
            stall_cycles: 5,
            ..WaitPolicy::NONE
        });
        let waits: Vec<bool> = (0..2000)
            .map(|_| !cycle(&mut m, &HostCommand::default()))
            .collect();
        let runs: Vec<usize> = waits
            .split(|w| !w)
            .map(<[bool]>::len)
            .filter(|&n| n > 0)
            .collect();
        // (The last may be cut short by the end of the run.)
        let (last, whole) = runs.split_last().unwrap();
        assert!(whole.len() > 50, "{} stalls", whole.len());
        assert!(whole.iter().all(|&n| n == 5) && *last <= 5, "{runs:?}");
        assert_eq!(m.waitrequest_cycles, runs.iter().sum::<usize>() as u64);
        assert_eq!(m.stall_cycles, 0, "no command was stalled");
    }
}
