//! The FPGA-to-SDRAM port as the fabric's DMA sees it: an Avalon-MM write agent of a chosen
//! width with random and bursty waitrequest, over a byte-addressed memory, which the HPS
//! reads through `skylux_bus::DmaMemory` as it would read the reserved buffer on the board.
//!
//! The model also checks the host: every beat must fall inside the window the test allows
//! (the DMA window), bursts must follow the Avalon-MM rules the f2sdram port relies on
//! (burstcount 1 to 128, address and burstcount held through the burst, full byte enables),
//! and anything else is recorded as a [`Violation`] rather than written.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use skylux_bus::{check_access, BusError, DmaMemory};

/// Largest burst of the f2sdram port's 8-bit burstcount (hardware-facts.md §3.2, §4).
pub const MAX_BURST_BEATS: u32 = 128;

/// When the agent stalls the host.
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

/// What the host did wrong (or where it wrote that it must not).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Violation {
    /// A beat addressed bytes outside the allowed window (it was not written).
    OutsideWindow { address: u64, bytes: u32 },
    /// A beat addressed bytes the memory does not have (it was not written).
    OutsideMemory { address: u64, bytes: u32 },
    /// burstcount 0 or above [`MAX_BURST_BEATS`].
    BadBurstCount { burstcount: u32 },
    /// Address or burstcount changed inside a burst.
    BurstChanged { beat: u32 },
    /// A beat without every byte enabled.
    PartialByteEnable { byteenable: u32 },
    /// An address not aligned to the port's width.
    Unaligned { address: u64 },
}

/// The host's outputs in one cycle.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct HostSignals {
    pub write: bool,
    /// Byte address.
    pub address: u64,
    pub burstcount: u32,
    pub writedata: u64,
    pub byteenable: u32,
}

#[derive(Copy, Clone, Debug)]
struct Burst {
    address: u64,
    burstcount: u32,
    beat: u32,
}

/// The f2sdram port and the SDRAM behind it.
#[derive(Clone, Debug)]
pub struct F2sdramModel {
    phys_base: u64,
    memory: Vec<u8>,
    width_bytes: u32,
    window: (u64, u64),
    policy: WaitPolicy,
    rng: StdRng,
    waitrequest: bool,
    stall_left: u64,
    burst: Option<Burst>,
    cycle: u64,
    pub violations: Vec<Violation>,
    /// Beats written.
    pub beats: u64,
    /// Cycles in which the host wanted to write and was stalled.
    pub stall_cycles: u64,
}

impl F2sdramModel {
    /// A memory of `len_bytes` at physical `phys_base`, a port of `width_bytes` (a power of
    /// two, 1 to 32), writes allowed in the window [`window_base`, `window_base + window_bytes`).
    pub fn new(
        phys_base: u64,
        len_bytes: usize,
        width_bytes: u32,
        window_base: u64,
        window_bytes: u64,
        policy: WaitPolicy,
        seed: u64,
    ) -> Self {
        assert!(
            width_bytes.is_power_of_two() && width_bytes <= 32,
            "port width {width_bytes} bytes: not a power of two up to 32"
        );
        F2sdramModel {
            phys_base,
            memory: vec![0; len_bytes],
            width_bytes,
            window: (window_base, window_base.saturating_add(window_bytes)),
            policy,
            rng: StdRng::seed_from_u64(seed),
            waitrequest: false,
            stall_left: 0,
            burst: None,
            cycle: 0,
            violations: vec![],
            beats: 0,
            stall_cycles: 0,
        }
    }

    /// Changes the waitrequest policy from the next cycle on.
    pub fn set_policy(&mut self, policy: WaitPolicy) {
        self.policy = policy;
    }

    /// waitrequest for the coming cycle.
    pub fn waitrequest(&self) -> bool {
        self.waitrequest
    }

    /// Clock cycles seen.
    pub fn cycles(&self) -> u64 {
        self.cycle
    }

    /// Whether a burst is in progress.
    pub fn in_burst(&self) -> bool {
        self.burst.is_some()
    }

    /// One rising clock edge: takes the beat if `write && !waitrequest`, then draws
    /// waitrequest for the next cycle.
    pub fn clock_edge(&mut self, host: &HostSignals) {
        if host.write {
            if self.waitrequest {
                self.stall_cycles += 1;
            } else {
                self.take_beat(host);
            }
        }
        self.cycle += 1;
        let p = self.policy;
        let held = self.cycle >= p.hold_from_cycle
            && self.cycle < p.hold_from_cycle.saturating_add(p.hold_cycles);
        if self.stall_left > 0 {
            self.stall_left -= 1;
        } else if p.stall_start > 0.0 && self.rng.gen_bool(p.stall_start.min(1.0)) {
            self.stall_left = p.stall_cycles;
        }
        let random = p.random > 0.0 && self.rng.gen_bool(p.random.min(1.0));
        self.waitrequest = held || self.stall_left > 0 || random;
    }

    fn take_beat(&mut self, host: &HostSignals) {
        let burst = match self.burst {
            Some(b) => {
                if b.address != host.address || b.burstcount != host.burstcount {
                    self.violations
                        .push(Violation::BurstChanged { beat: b.beat });
                }
                b
            }
            None => {
                if host.burstcount == 0 || host.burstcount > MAX_BURST_BEATS {
                    self.violations.push(Violation::BadBurstCount {
                        burstcount: host.burstcount,
                    });
                }
                if !host.address.is_multiple_of(u64::from(self.width_bytes)) {
                    self.violations.push(Violation::Unaligned {
                        address: host.address,
                    });
                }
                Burst {
                    address: host.address,
                    burstcount: host.burstcount.max(1),
                    beat: 0,
                }
            }
        };
        let full = if self.width_bytes >= 32 {
            u32::MAX
        } else {
            (1u32 << self.width_bytes) - 1
        };
        if host.byteenable & full != full {
            self.violations.push(Violation::PartialByteEnable {
                byteenable: host.byteenable,
            });
        }
        let address = burst.address + u64::from(burst.beat) * u64::from(self.width_bytes);
        self.write_beat(address, host.writedata);
        self.beats += 1;
        let beat = burst.beat + 1;
        self.burst = (beat < burst.burstcount).then_some(Burst { beat, ..burst });
    }

    fn write_beat(&mut self, address: u64, data: u64) {
        let bytes = self.width_bytes;
        let end = address.saturating_add(u64::from(bytes));
        if address < self.window.0 || end > self.window.1 {
            self.violations
                .push(Violation::OutsideWindow { address, bytes });
            return;
        }
        let Some(offset) = address.checked_sub(self.phys_base) else {
            self.violations
                .push(Violation::OutsideMemory { address, bytes });
            return;
        };
        let offset = offset as usize;
        if offset + bytes as usize > self.memory.len() {
            self.violations
                .push(Violation::OutsideMemory { address, bytes });
            return;
        }
        // Beats wider than 64 bits repeat the 64-bit pattern (the frame DMA is 64 bits wide).
        for i in 0..bytes as usize {
            self.memory[offset + i] = data.to_le_bytes()[i % 8];
        }
    }
}

impl DmaMemory for F2sdramModel {
    fn phys_base(&self) -> u64 {
        self.phys_base
    }
    fn len_bytes(&self) -> u64 {
        self.memory.len() as u64
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        check_access(offset, buf.len() as u64, self.len_bytes(), 1)?;
        let o = offset as usize;
        buf.copy_from_slice(&self.memory[o..o + buf.len()]);
        Ok(())
    }
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        check_access(offset, data.len() as u64, self.len_bytes(), 1)?;
        let o = offset as usize;
        self.memory[o..o + data.len()].copy_from_slice(data);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn beat(address: u64, burstcount: u32, writedata: u64) -> HostSignals {
        HostSignals {
            write: true,
            address,
            burstcount,
            writedata,
            byteenable: 0xFF,
        }
    }

    #[test]
    fn burst_lands_at_consecutive_addresses_and_stalls_hold() {
        let mut m = F2sdramModel::new(0x1000, 256, 8, 0x1000, 256, WaitPolicy::random(0.5), 7);
        let mut written = 0;
        let mut cycles = 0;
        while written < 4 {
            let stalled = m.waitrequest();
            m.clock_edge(&beat(0x1010, 4, 0x1111 * (written + 1)));
            if !stalled {
                written += 1;
            }
            cycles += 1;
        }
        assert!(m.violations.is_empty(), "{:?}", m.violations);
        assert_eq!(m.beats, 4);
        assert_eq!(m.stall_cycles, cycles - 4);
        let mut buf = [0u8; 8];
        m.read_bytes(0x10 + 3 * 8, &mut buf).unwrap();
        assert_eq!(u64::from_le_bytes(buf), 0x4444);
        assert!(!m.in_burst());
    }

    #[test]
    fn writes_outside_the_window_are_refused_and_recorded() {
        let mut m = F2sdramModel::new(0, 256, 8, 64, 64, WaitPolicy::NONE, 1);
        m.clock_edge(&beat(120, 2, 5));
        m.clock_edge(&beat(120, 2, 6));
        assert_eq!(
            m.violations,
            vec![Violation::OutsideWindow {
                address: 128,
                bytes: 8
            }]
        );
        let mut buf = [0u8; 16];
        m.read_bytes(120, &mut buf).unwrap();
        assert_eq!(buf[0], 5);
        assert_eq!(buf[8], 0);
        m.clock_edge(&beat(64, 0, 0));
        assert!(m
            .violations
            .contains(&Violation::BadBurstCount { burstcount: 0 }));
        m.clock_edge(&beat(72, 3, 0));
        m.clock_edge(&beat(80, 3, 0));
        assert!(m.violations.contains(&Violation::BurstChanged { beat: 1 }));
    }
}
