//! A cost model of the DE1-SoC's Cortex-A9 (the Cyclone V HPS) for the cycle budget
//! (`skyluxd --bench-cycle`, BENCHMARKS.md "skyluxd cycle budget"). It replaces the flat
//! "one x86 core is ten A9 cores" factor with bytes and instructions counted per stage and the
//! A9's published rates. Its figures are **modelled**, not measured: no board has run them.
//!
//! # How a stage is estimated
//!
//! A stage is a sequence of [`Pass`]es: loops that run one after another.
//! - **Memory time** of a pass: the bytes it moves, by kind ([`Bytes`]), over the rate of that
//!   kind: reads of the uncached DMA ring, cached streaming traffic to and from the DDR3
//!   (bytes read plus bytes written), and zero-filling (memset-like writes).
//! - **Compute time** of a pass: iterations × cycles per iteration ÷ [`CLOCK_HZ`], the cycles
//!   per iteration being the binding one of four bounds ([`Ops::cycles`]).
//! - **Pass time = max(memory, compute)**: each pass is one loop walking its data in order, so
//!   the A9's data prefetcher and its outstanding linefills overlap the two; the sum is the
//!   other extreme and is reported beside it ([`Stage::memory_s`] + [`Stage::compute_s`]).
//!   Within a pass nothing waits on the other part's result except through the data stream.
//! - **Stage time = sum of its passes** (they run in sequence).
//! - **Two cores**: a pass that rayon spreads over threads ([`Pass::parallel`]: the merge's
//!   rows, the daylight coefficients' sensors) divides its compute by the cores; its memory
//!   time does not shrink (one DDR3 port, one L2), so it is not divided.
//!
//! # What is left out (so the model is optimistic)
//!
//! Branch mispredictions, L1/L2 misses other than the streams counted, TLB misses, page faults,
//! other processes, and rayon's scheduling. The instruction counts assume the loop bodies listed
//! beside each constant, taken from `cargo rustc --release -p skylux-hps --lib --target
//! armv7-unknown-linux-gnueabihf -- --emit=asm` with rustc 1.95.0 (the ring reader's loops from
//! the same expressions compiled alone, since they live in the daemon). That target generates
//! no NEON code (its feature set has NEON off, and even `-C target-cpu=cortex-a9` does not
//! vectorise an f32 or u32 loop: checked on this machine), so every f64 operation below is a
//! scalar VFPv3 instruction and the NEON figure is given for completeness only.
//!
//! # Sources
//!
//! - **\[A1\]** HPS clock 925 MHz: Terasic DE1-SoC manual, as recorded in
//!   `shared/docs/hardware-facts.md` §2 (S17), which notes that the preloader may set less.
//! - **\[A2\]** Issue and ports: the Cortex-A9 pipeline models that ARM Ltd. contributed to GCC
//!   (`gcc/config/arm/cortex-a9.md`: "a dual issue pipeline", "The Load/Store, VFP and Neon
//!   issue pipeline are multiplexed", `exclusion_set "cortex_a9_ls" "ca9_issue_vfp_neon"`) and
//!   LLVM's (`llvm/lib/Target/ARM/ARMScheduleA9.td`: `IssueWidth = 2`; every load, store, VFP
//!   and NEON itinerary takes `A9_MUX0`, the "AGU + NEON/FPU multiplexer", for one cycle).
//!   Both transcribe the Cortex-A9 TRM (ARM DDI 0388) and the Cortex-A9 FPU TRM (ARM DDI 0408,
//!   §2.3 "Instruction throughput and latency"); the TRM tables themselves were not readable
//!   here, only their definitions page.
//! - **\[A3\]** VFPv3 timings (throughput = cycles the pipeline is held, latency):
//!   `ARMScheduleA9.td` itineraries `IIC_fpALU64` (VADD/VSUB.F64: 1, 4), `IIC_fpMUL64` (2, 6),
//!   `IIC_fpMAC64` (VMLA.F64: 2, 9), `IIC_fpDIV64` (20, 25), `IIC_fpSQRT64` (28, 32),
//!   `IIC_fpCVT*` (1, 4), `IIC_fpCMP64` (1); GCC's `cortex-a9.md` agrees (fadd 4, fmuld 5 with
//!   the multiplier held 2 cycles, fmacd 9, fdivd 25).
//! - **\[A4\]** NEON single precision: `ARMScheduleA9.td` `IIC_VBINQ` (VADD.F32 on a Q
//!   register: NEON pipe held 2 cycles for 4 lanes) → 2 lanes per cycle; the Cortex-A9 NEON MPE
//!   TRM (ARM DDI 0409) describes the 64-bit datapath. Not used by this build.
//! - **\[A5\]** DDR3 peak: the Cyclone V HPS SDRAM controller runs "up to 400 MHz (800 Mbps
//!   data rate)" (Cyclone V Device Overview, "HPS SDRAM Controller Subsystem"; Intel 683648
//!   "HPS SDRAM Controller Subsystem Differences": "8, 16, or 32 bits, up to 400 MHz"), and the
//!   DE1-SoC's is 32 bits wide (hardware-facts.md §2): 3.2 GB/s. For scale only: one A9 reaches
//!   a small fraction of it.
//! - **\[A6\]** Cached streaming: TI Processor SDK Linux AM437x 08.02 Performance Guide
//!   (<https://software-dl.ti.com/processor-sdk-linux/esd/AM437X/08_02_00_24/exports/docs/devices/AM437X/linux/Release_Specific_Performance_Guide.html>):
//!   AM437x GP EVM, Cortex-A9 at 1000 MHz, DDR3-400 (800 MT/s), LMBench `bw_mem-bcopy-16mb` =
//!   193.85 MB/s, i.e. 387.7 MB/s of bytes read plus written. It transfers: the same core and
//!   the same L2 controller family (PL310) on a 32-bit DDR3-800 bus like the DE1-SoC's, and a
//!   single A9's stream is bound by its outstanding misses and the memory latency, far below
//!   the bus peak (387.7 MB/s is 12 % of 3.2 GB/s). Corroboration: a Zedboard
//!   (Zynq-7020, A9 at 667 MHz, DDR3-1066) copies about 256 MB/s between cached buffers
//!   (<https://github.com/bmartini/zynq-xdma/issues/10>), 512 MB/s of traffic.
//! - **\[A7\]** Zero-filling: ikwzm/udmabuf `Readme.md`, Table 2 (`clear_buf`, Cortex-A9
//!   Zynq, cache on): 99 memsets of 10 MiB in 0.713 s = 1.456 GB/s
//!   (<https://github.com/ikwzm/udmabuf>).
//! - **\[A8\]** Uncached reads: bmartini/zynq-xdma issue 10 (Zedboard, A9 at 667 MHz): memcpy
//!   out of the driver's non-cached DMA buffer about 64 MB/s, against 256 MB/s between cached
//!   buffers (<https://github.com/bmartini/zynq-xdma/issues/10>). Corroboration: udmabuf
//!   Table 1 (`check_buf`, a byte loop over 10 MB): 22.83 s with the cache off (strongly
//!   ordered), 16.56 s write-combining, 4.34 s cached. Our ring is the strongly ordered kind
//!   (`/dev/mem` with `O_SYNC` on a `no-map` region, hardware-facts.md §3.4), which that table
//!   shows slower than write-combining, so 64 MB/s is if anything optimistic; the DE1-SoC's
//!   faster clock shortens only the core's share of each access, not the DDR3 round trip.
//! - **\[A9\]** `fmin`/`fmax`: `f64::min`/`max` compile to calls on this target (VFPv3 has no
//!   VMINNM); glibc 2.36 armhf `libm.so.6` (Debian, the cross toolchain here) disassembled:
//!   8 instructions when the first argument wins, 11 otherwise, with `push`, `vpush {d8-d9}`,
//!   `vpop`, `pop {pc}`. The board's C library may differ.
//! - **\[A10\]** Integer division: the compiled code calls `__aeabi_uidiv` (the A9 has no
//!   divide instruction); its cost, about 45 instructions for a quotient of 10 to 11 bits
//!   (libgcc's shift-and-subtract), is an **estimate**.
//! - **\[A11\]** Cache maintenance before a cached read of the DMA buffer (u-dma-buf's
//!   `sync_for_cpu`, which Linux's ARM `dma_sync_single_for_cpu` turns into invalidation by
//!   address of every 32-byte line of the range in the L1 and in the PL310 L2): an
//!   **estimate** of 40 core cycles a line (the PL310's by-address operation is a register
//!   write and a wait on the outer controller, which runs slower than the core); no figure
//!   for it was found published.
//! - **\[A12\]** A register access over the lightweight HPS-to-FPGA bridge: an **estimate** of
//!   1 µs. The access is a strongly ordered load (or store) that crosses the L3 interconnect
//!   and the bridge (`l4_mp_clk` on the HPS side, `h2f_lw_axi_clk` on the fabric's; Cyclone V
//!   HPS TRM 683126 §9.3.4, hardware-facts.md §3.1) to the register file's Avalon port
//!   (`READ_LATENCY_CYCLES` at 100 MHz), and the core waits for it. The TRM gives no latency;
//!   1 µs is the figure the daemon's fabric model charges a read
//!   (`skyluxd::fabric_model_source::READ_CYCLES`), not measured on the board.

/// The A9's clock, Hz \[A1\].
pub const CLOCK_HZ: f64 = 925e6;
/// Instructions issued per cycle at most (dual issue) \[A2\].
pub const ISSUE_INSTRUCTIONS_PER_CYCLE: f64 = 2.0;
/// Slots per cycle of the issue port that loads, stores and VFP/NEON instructions share
/// \[A2\]: one. A load or store multiple takes one slot per pair of core registers or per
/// double register.
pub const LS_FP_SLOTS_PER_CYCLE: f64 = 1.0;
/// VFP pipeline cycles per instruction (throughput) \[A3\].
pub const VADD_F64_CYCLES: f64 = 1.0;
pub const VMUL_F64_CYCLES: f64 = 2.0;
pub const VMLA_F64_CYCLES: f64 = 2.0;
pub const VDIV_F64_CYCLES: f64 = 20.0;
pub const VSQRT_F64_CYCLES: f64 = 28.0;
/// VFP result latencies, cycles \[A3\].
pub const VADD_F64_LATENCY_CYCLES: f64 = 4.0;
pub const VMLA_F64_LATENCY_CYCLES: f64 = 9.0;
pub const VDIV_F64_LATENCY_CYCLES: f64 = 25.0;
/// NEON single-precision lanes per cycle \[A4\] (not used by this build).
pub const NEON_F32_LANES_PER_CYCLE: f64 = 2.0;

/// Peak rates in operations per second that follow from the above.
pub const ISSUE_OPS_PER_S: f64 = CLOCK_HZ * ISSUE_INSTRUCTIONS_PER_CYCLE;
pub const VADD_F64_OPS_PER_S: f64 = CLOCK_HZ / VADD_F64_CYCLES;
pub const VMUL_F64_OPS_PER_S: f64 = CLOCK_HZ / VMUL_F64_CYCLES;
pub const VDIV_F64_OPS_PER_S: f64 = CLOCK_HZ / VDIV_F64_CYCLES;
pub const VSQRT_F64_OPS_PER_S: f64 = CLOCK_HZ / VSQRT_F64_CYCLES;
pub const NEON_F32_OPS_PER_S: f64 = CLOCK_HZ * NEON_F32_LANES_PER_CYCLE;

/// DDR3 peak, bytes/s \[A5\]; for scale, not used by the estimates.
pub const DRAM_PEAK_BYTES_PER_S: f64 = 3.2e9;
/// Cached streaming to and from the DDR3 by one A9, bytes read plus bytes written per second
/// \[A6\]. A copy of N bytes moves 2N.
pub const DRAM_STREAM_BYTES_PER_S: f64 = 2.0 * 193.85e6;
/// Zero-filling cached memory (memset), bytes/s \[A7\].
pub const DRAM_FILL_BYTES_PER_S: f64 = 99.0 * 10.0 * 1024.0 * 1024.0 / 0.713;
/// memcpy out of the uncached DMA ring, bytes read per second \[A8\] (the cached destination's
/// writes are inside this rate).
pub const UNCACHED_READ_BYTES_PER_S: f64 = 64e6;
/// Cache sizes (hardware-facts.md §2): a loop's working set under these stays on chip.
pub const L1_DATA_BYTES: f64 = 32.0 * 1024.0;
pub const L2_BYTES: f64 = 512.0 * 1024.0;
/// Cores that rayon's global pool uses on the HPS.
pub const CORES: u32 = 2;

/// What one iteration of a loop costs the core, counted from its compiled body.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct Ops {
    /// Instructions issued.
    pub instructions: f64,
    /// Slots of the port loads, stores and VFP instructions share.
    pub ls_fp_slots: f64,
    /// Cycles the VFP pipeline is held.
    pub fp_pipe_cycles: f64,
    /// Loop-carried latency: cycles an iteration waits for the previous one's result.
    pub chain_cycles: f64,
}

impl Ops {
    pub const fn new(
        instructions: f64,
        ls_fp_slots: f64,
        fp_pipe_cycles: f64,
        chain_cycles: f64,
    ) -> Self {
        Self {
            instructions,
            ls_fp_slots,
            fp_pipe_cycles,
            chain_cycles,
        }
    }

    /// Cycles per iteration: the largest of issue width, the shared load/store/VFP port, the
    /// VFP pipeline and the loop-carried chain. A lower bound: it assumes perfect scheduling,
    /// no mispredicted branch and L1 hits for everything not counted as memory traffic.
    pub fn cycles(&self) -> f64 {
        (self.instructions / ISSUE_INSTRUCTIONS_PER_CYCLE)
            .max(self.ls_fp_slots / LS_FP_SLOTS_PER_CYCLE)
            .max(self.fp_pipe_cycles)
            .max(self.chain_cycles)
    }

    /// This body with `n` calls of `callee` inside it (chains add up too).
    pub fn with_calls(self, n: f64, callee: Ops) -> Self {
        Self {
            instructions: self.instructions + n * callee.instructions,
            ls_fp_slots: self.ls_fp_slots + n * callee.ls_fp_slots,
            fp_pipe_cycles: self.fp_pipe_cycles + n * callee.fp_pipe_cycles,
            chain_cycles: self.chain_cycles + n * callee.chain_cycles,
        }
    }
}

/// Bytes a pass moves outside the caches, by kind.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct Bytes {
    /// Read from the uncached DMA ring.
    pub uncached_read: f64,
    /// Read from or written to cached memory that does not fit the L2.
    pub dram_stream: f64,
    /// Zero-filled.
    pub dram_fill: f64,
}

impl Bytes {
    /// Seconds to move them, each kind at its rate.
    pub fn seconds(&self) -> f64 {
        self.uncached_read / UNCACHED_READ_BYTES_PER_S
            + self.dram_stream / DRAM_STREAM_BYTES_PER_S
            + self.dram_fill / DRAM_FILL_BYTES_PER_S
    }
}

/// One loop of a stage.
#[derive(Clone, Debug, PartialEq)]
pub struct Pass {
    pub name: &'static str,
    pub bytes: Bytes,
    /// Core cycles of the whole pass.
    pub cycles: f64,
    /// Whether rayon spreads it over the cores.
    pub parallel: bool,
}

impl Pass {
    pub fn memory_s(&self) -> f64 {
        self.bytes.seconds()
    }

    /// Compute time on one core.
    pub fn compute_s(&self) -> f64 {
        self.cycles / CLOCK_HZ
    }

    /// max(memory, compute) with `cores` cores (only a parallel pass uses more than one).
    pub fn seconds(&self, cores: u32) -> f64 {
        let cores = if self.parallel { cores.max(1) } else { 1 };
        self.memory_s().max(self.compute_s() / f64::from(cores))
    }
}

/// A stage of the cycle: its passes, in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Stage {
    pub name: &'static str,
    pub passes: Vec<Pass>,
}

impl Stage {
    /// The memory part: every pass's memory time.
    pub fn memory_s(&self) -> f64 {
        self.passes.iter().map(Pass::memory_s).sum()
    }

    /// The compute part on one core.
    pub fn compute_s(&self) -> f64 {
        self.passes.iter().map(Pass::compute_s).sum()
    }

    /// The estimate: the sum over passes of max(memory, compute), with `cores` cores.
    pub fn seconds(&self, cores: u32) -> f64 {
        self.passes.iter().map(|p| p.seconds(cores)).sum()
    }
}

/// One call of glibc's `fmin` or `fmax` \[A9\], averaged over its two paths: 9.5 instructions;
/// `push {r3, lr}` 1 slot, `vpush {d8-d9}` 2, `vpop` 2, `pop {r3, pc}` 1, and 3 to 5 VFP
/// instructions (`vcmp.f64`, `vmrs`, 1 to 3 `vmov.f64`): 10 slots, 4 VFP pipeline cycles.
pub const LIBM_MIN_MAX_CALL: Ops = Ops::new(9.5, 10.0, 4.0, 0.0);

/// Reading the ring: `RingLayout::read_slot` (hps/core/src/fpga/frames.rs) and the unpacking
/// to samples (`fabric_source.rs`, and `budget.rs` the same way), per payload word.
pub mod ring {
    use super::Ops;
    /// `descriptor::checksum`: `ldr r3, [r2], #4; subs; add; bne`.
    pub const CHECKSUM_PER_WORD: Ops = Ops::new(4.0, 1.0, 0.0, 0.0);
    /// The unpacking loop: `ldr r3, [r0], #4; subs; and r3, r3, #0x0fff0fff; str r3, [r2], #4;
    /// bne` (both 12-bit samples masked in one `and`, stored as two u16 in one `str`).
    pub const UNPACK_PER_WORD: Ops = Ops::new(5.0, 2.0, 0.0, 0.0);
}

/// The ring reader's passes for `frames` raw frames of `words_per_frame` payload words.
pub fn hps_read(frames: f64, words_per_frame: f64) -> Stage {
    let bytes = 4.0 * words_per_frame * frames;
    let words = words_per_frame * frames;
    Stage {
        name: "hps_read",
        passes: vec![
            Pass {
                name: "copy out of the uncached ring into words (memcpy, read_words_le)",
                bytes: Bytes {
                    uncached_read: bytes,
                    ..Bytes::default()
                },
                cycles: 0.0,
                parallel: false,
            },
            Pass {
                name: "checksum",
                bytes: Bytes {
                    dram_stream: bytes,
                    ..Bytes::default()
                },
                cycles: words * ring::CHECKSUM_PER_WORD.cycles(),
                parallel: false,
            },
            Pass {
                name: "zero the sample buffer (vec![0u16; 2n]: calloc)",
                bytes: Bytes {
                    dram_fill: bytes,
                    ..Bytes::default()
                },
                cycles: 0.0,
                parallel: false,
            },
            Pass {
                name: "unpack to samples",
                bytes: Bytes {
                    dram_stream: 2.0 * bytes,
                    ..Bytes::default()
                },
                cycles: words * ring::UNPACK_PER_WORD.cycles(),
                parallel: false,
            },
        ],
    }
}

/// Map mode's ring read (`[fabric] hdr = "fabric"`, issue 22 item 1): the one map of `words`
/// words, copied out of the uncached ring straight into words (`DmaMemory::read_words_le`: no
/// zeroed byte buffer, no pass from bytes to words); no unpacking (the words go to
/// `hdr::fabric_map` as they are).
pub fn hps_read_map(words: f64) -> Stage {
    let bytes = 4.0 * words;
    Stage {
        name: "hps_read_map",
        passes: vec![Pass {
            name: "copy out of the uncached ring into words (memcpy, read_words_le)",
            bytes: Bytes {
                uncached_read: bytes,
                ..Bytes::default()
            },
            cycles: 0.0,
            parallel: false,
        }],
    }
}

/// Core cycles to invalidate one 32-byte line before a cached read \[A11\] (**estimate**).
pub const INVALIDATE_CYCLES_PER_LINE: f64 = 40.0;
/// The A9's cache line, bytes (Cortex-A9 TRM: 32-byte lines in the L1 and the PL310).
pub const CACHE_LINE_BYTES: f64 = 32.0;

/// [`hps_read_map`] through the cached mapping with explicit maintenance (`[hardware]
/// dma_device = "/dev/udmabufN"`, bitstream/README.md): the range invalidated \[A11\], then
/// the same passes with the copy at the cached streaming rate.
pub fn hps_read_map_cached(words: f64) -> Stage {
    let bytes = 4.0 * words;
    let mut stage = hps_read_map(words);
    stage.name = "hps_read_map_cached";
    for pass in &mut stage.passes {
        if pass.bytes.uncached_read > 0.0 {
            pass.name = "copy out of the cached mapping (memcpy)";
            pass.bytes = Bytes {
                dram_stream: 2.0 * bytes,
                ..Bytes::default()
            };
        }
    }
    stage.passes.insert(
        0,
        Pass {
            name: "invalidate the range (sync_for_cpu)",
            bytes: Bytes::default(),
            cycles: bytes / CACHE_LINE_BYTES * INVALIDATE_CYCLES_PER_LINE,
            parallel: false,
        },
    );
    stage
}

/// `hdr::fabric_map` (hps/core/src/hdr/fabric_map.rs), per group. **Estimate**: written from
/// the source, not counted from a listing (the function is newer than the listing above).
pub mod fabric_map {
    use super::{Ops, VDIV_F64_CYCLES, VSQRT_F64_CYCLES};
    /// A valid group: the word's fields and the usable test (about 15 integer instructions),
    /// `Merger::single`: the rate by the precomputed 1/(t g) (`vmul.f64`), one `vsqrt.f64`
    /// and one `vdiv.f64` for the relative sigma, four `vmul.f64`/`vmla.f64`, two
    /// conversions and the three stores: about 45 instructions, 25 load/store/VFP slots, the
    /// VFP pipeline held by the division and the square root.
    pub const VALID_GROUP: Ops =
        Ops::new(45.0, 25.0, VDIV_F64_CYCLES + VSQRT_F64_CYCLES + 8.0, 0.0);
    /// A flagged group: the fields, the usable test and the flag's store.
    pub const FLAGGED_GROUP: Ops = Ops::new(20.0, 4.0, 0.0, 0.0);
}

/// `hdr::fabric_map`'s passes over `groups` groups of which `valid_groups` are valid: a
/// single loop (not spread over cores).
pub fn hdr_fabric_map(groups: f64, valid_groups: f64) -> Stage {
    // Map: f32 luminance + u8 flag + f32 sigma per group.
    let map_bytes = 9.0 * groups;
    Stage {
        name: "hdr_fabric_map",
        passes: vec![
            Pass {
                name: "fill the map (NaN, UnderRange)",
                bytes: Bytes {
                    dram_fill: map_bytes,
                    ..Bytes::default()
                },
                cycles: 0.0,
                parallel: false,
            },
            Pass {
                // Per group: the map word, the f32 inverse vignetting, the map's outputs.
                name: "convert the groups",
                bytes: Bytes {
                    dram_stream: groups * 8.0 + map_bytes,
                    ..Bytes::default()
                },
                cycles: valid_groups * fabric_map::VALID_GROUP.cycles()
                    + (groups - valid_groups) * fabric_map::FLAGGED_GROUP.cycles(),
                // Rows in parallel (rayon).
                parallel: true,
            },
        ],
    }
}

/// The loops of `Merger::row` (hps/core/src/hdr/merge.rs), raw frames, per group. Counted from
/// the monomorphised `merge::<RawFrame>` (inlined into rayon's `bridge_producer_consumer`
/// helper) in the listing the module documentation names.
pub mod merge {
    use super::{Ops, LIBM_MIN_MAX_CALL};
    /// `group_row`, per group and exposure, without its calls: 60 instructions (4 `ldrh`,
    /// 4 `vmov s0, r0` + `vcvt.f64.u32`, 4 `vsub.f64`, 1 `vmul.f64`, 3 `vmla.f64`, 15
    /// `vmov.f64` shuffling the arguments of the six calls, `vstmia`, 4 `vldr` of the
    /// weights, 2 `vcmp.f64` + `vmrs`, 2 `strb`, 8 integer); slots 11 load/store + 35 VFP;
    /// VFP pipeline 39 cycles. Plus the six `fmin`/`fmax` calls of `min`/`max` over the four
    /// samples.
    pub const GROUP_ROW_INLINE: Ops = Ops::new(60.0, 46.0, 39.0, 0.0);
    pub const GROUP_ROW_CALLS: f64 = 6.0;
    /// `valid[i] = !(over[i] || under[i])`, per group and exposure: 13 instructions, 4 loads
    /// and stores.
    pub const VALID: Ops = Ops::new(13.0, 4.0, 0.0, 0.0);
    /// Σ signal and Σ t g, per group and exposure: 14 instructions (3 `vldr`, 2 `vstmia`,
    /// `ldrb`, 2 `vadd.f64`, `vmov.f64`, 5 integer).
    pub const SUMS: Ops = Ops::new(14.0, 9.0, 3.0, 0.0);
    /// The pilot rate, per group: `vdiv.f64` then a call of `fmax` (`.max(0.0)`).
    pub const PILOT_INLINE: Ops = Ops::new(8.0, 5.0, 21.0, 0.0);
    /// The inverse-variance sums, per group and valid exposure: 23 instructions with one
    /// `vdiv.f64`, one `vmla.f64`, two `vmul.f64`, two `vadd.f64`, three `vmov.f64`; VFP
    /// pipeline 31 cycles.
    pub const WEIGHTS_VALID: Ops = Ops::new(23.0, 16.0, 31.0, 0.0);
    /// The same for an exposure that is not valid (no division): 15 instructions.
    pub const WEIGHTS_SKIPPED: Ops = Ops::new(15.0, 9.0, 4.0, 0.0);
    /// The output of a valid group: 55 instructions with three `vdiv.f64`, one `vsqrt.f64`,
    /// two `vmul.f64`, three conversions, two compares; VFP pipeline 100 cycles.
    pub const OUTPUT_VALID: Ops = Ops::new(55.0, 31.0, 100.0, 0.0);
    /// The output of a flagged group: a base and a loop over the exposures' flags.
    pub const OUTPUT_FLAGGED: Ops = Ops::new(46.0, 11.0, 2.0, 0.0);
    pub const OUTPUT_FLAGGED_PER_EXPOSURE: Ops = Ops::new(14.0, 5.0, 0.0, 0.0);

    /// `group_row` with its calls: 106 cycles, held by the shared port.
    pub fn group_row() -> Ops {
        GROUP_ROW_INLINE.with_calls(GROUP_ROW_CALLS, LIBM_MIN_MAX_CALL)
    }

    /// The pilot with its call.
    pub fn pilot() -> Ops {
        PILOT_INLINE.with_calls(1.0, LIBM_MIN_MAX_CALL)
    }
}

/// What the merge works on: the counts its cost depends on.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct HdrWork {
    pub groups: f64,
    pub exposures: f64,
    /// (group, exposure) pairs where no sample is over- or under-range.
    pub valid_pairs: f64,
    /// Groups the map flags valid.
    pub valid_groups: f64,
}

impl HdrWork {
    /// Core cycles of the merge.
    pub fn cycles(&self) -> f64 {
        let pairs = self.groups * self.exposures;
        let flagged = self.groups - self.valid_groups;
        pairs * (merge::group_row().cycles() + merge::VALID.cycles() + merge::SUMS.cycles())
            + self.groups * merge::pilot().cycles()
            + self.valid_pairs * merge::WEIGHTS_VALID.cycles()
            + (pairs - self.valid_pairs) * merge::WEIGHTS_SKIPPED.cycles()
            + self.valid_groups * merge::OUTPUT_VALID.cycles()
            + flagged
                * merge::OUTPUT_FLAGGED
                    .with_calls(self.exposures, merge::OUTPUT_FLAGGED_PER_EXPOSURE)
                    .cycles()
    }
}

/// The merge's passes.
pub fn hdr_merge(work: &HdrWork) -> Stage {
    // Map: f32 luminance + u8 flag + f32 sigma per group.
    let map_bytes = 9.0 * work.groups;
    Stage {
        name: "hdr_merge",
        passes: vec![
            Pass {
                name: "fill the map (NaN, UnderRange)",
                bytes: Bytes {
                    dram_fill: map_bytes,
                    ..Bytes::default()
                },
                cycles: 0.0,
                parallel: false,
            },
            Pass {
                // Per group: two rows of two u16 samples per exposure, the f32 inverse
                // vignetting, the map's outputs. The row scratch (about 120 kB) stays in the L2.
                name: "merge the rows",
                bytes: Bytes {
                    dram_stream: work.groups * 8.0 * work.exposures + work.groups * 4.0 + map_bytes,
                    ..Bytes::default()
                },
                cycles: work.cycles(),
                parallel: true,
            },
        ],
    }
}

/// The loops of `sun::extract_sun` and `bright_components` (hps/core/src/sun/extract.rs),
/// counted from the same listing. Those marked *estimate* were read from the listing less
/// exactly (paths through several blocks, or a library call).
pub mod sun {
    use super::{Ops, LIBM_MIN_MAX_CALL};
    /// `map.flags.iter().all(OverRange)`, per flag read.
    pub const ALL_OVER_PER_FLAG: Ops = Ops::new(4.0, 1.0, 0.0, 0.0);
    /// The field-of-view test with a prediction, per group: is_finite, three conversions and a
    /// dot product (*estimate*).
    pub const FOV_PER_GROUP: Ops = Ops::new(20.0, 10.0, 12.0, 0.0);
    /// The scan over the labels, per group (the call of the candidate test counted apart):
    /// `ldr`, `ldr`, `cmn`, `bne`, the call's 3 instructions, `cmp`, `beq`, `add`, `cmp`,
    /// `beq`.
    pub const SCAN_PER_GROUP: Ops = Ops::new(13.0, 2.0, 0.0, 0.0);
    /// The candidate test (a closure compiled as its own function) on a group outside the
    /// lens: prologue `push` of 9 registers and `vpush {d8, d9}`, the first `is_finite`,
    /// epilogue: 24 instructions, 19 load/store slots.
    pub const CANDIDATE_UNSEEN: Ops = Ops::new(24.0, 19.0, 0.0, 0.0);
    /// The same on an imaged group whose flag is not valid (over- or under-range): 47
    /// instructions, 24 slots.
    pub const CANDIDATE_FLAGGED: Ops = Ops::new(47.0, 24.0, 0.0, 0.0);
    /// The same on a valid group: 76 instructions with `vdiv.f64` (Ω_disk / Ω), a call of
    /// `fmin` (`.min(1.0)`), two `vmul.f64`, two compares; 46 slots, VFP pipeline 32 cycles.
    pub const CANDIDATE_VALID_INLINE: Ops = Ops::new(76.0, 46.0, 32.0, 0.0);
    /// The breadth-first search, per member: pop from the `VecDeque`, push to `members`,
    /// `i % w` and `i / w` through one `__aeabi_uidiv` (\[A10\], 45 instructions), and the
    /// eight neighbours (i64 bounds, the label) without their candidate calls: about 225
    /// instructions, 53 slots (*estimate*).
    pub const BFS_PER_MEMBER: Ops = Ops::new(225.0, 53.0, 0.0, 0.0);
    /// `mean_direction`, per member: 4 loads, 4 conversions, 3 `vmul.f64`, 3 `vadd.f64` into
    /// three accumulators (each a 4-cycle chain).
    pub const DIRECTION_PER_MEMBER: Ops = Ops::new(17.0, 14.0, 13.0, 4.0);
    /// The flux a component carries (choice without a prediction), per member visit: two
    /// loads, two conversions, a multiply, a finiteness test, an add into the sum (*estimate*).
    pub const FLUX_PER_MEMBER: Ops = Ops::new(12.0, 8.0, 8.0, 4.0);
    /// The bounding box, per member of the chosen component: `i % w`, `i / w` (one
    /// `__aeabi_uidiv`) and four min/max (*estimate*).
    pub const BOX_PER_MEMBER: Ops = Ops::new(55.0, 6.0, 0.0, 0.0);
    /// The dilated box, per group: pushed to `groups`, then the measuring loop: is_finite,
    /// flag, excess, `peak.max` and `excess.max(0.0)` (two `fmax` calls), flux, and three
    /// `vmla.f64` into the weighted direction (a 9-cycle chain each) (*estimate*).
    pub const BOX_PER_GROUP_INLINE: Ops = Ops::new(50.0, 21.0, 20.0, 9.0);
    /// `ring_median_cd_m2`, per group of the box it scans (*estimate*).
    pub const RING_PER_GROUP: Ops = Ops::new(20.0, 6.0, 0.0, 0.0);
    /// Its sort, per comparison (*estimate*).
    pub const SORT_PER_COMPARISON: Ops = Ops::new(8.0, 2.0, 0.0, 0.0);

    pub fn candidate_valid() -> Ops {
        CANDIDATE_VALID_INLINE.with_calls(1.0, LIBM_MIN_MAX_CALL)
    }

    pub fn box_per_group() -> Ops {
        BOX_PER_GROUP_INLINE.with_calls(2.0, LIBM_MIN_MAX_CALL)
    }
}

/// What the sun extraction works on (from `sun::extract::extraction_work`).
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct SunWork {
    pub groups: f64,
    /// Flags read by the all-saturated test.
    pub all_over_flags: f64,
    /// Groups tested against the predicted direction (0 without a prediction).
    pub fov_groups: f64,
    /// Calls of the candidate test from the scan, on groups outside the lens, imaged but
    /// flagged, and valid.
    pub scan_calls: [f64; 3],
    /// Calls from the breadth-first search, likewise.
    pub search_calls: [f64; 3],
    /// Groups in the bright components.
    pub members: f64,
    /// Member visits of `mean_direction`.
    pub direction_visits: f64,
    /// Member visits of the flux comparisons.
    pub flux_visits: f64,
    /// Members of the chosen component.
    pub chosen_members: f64,
    /// Groups of the dilated box.
    pub box_groups: f64,
    /// Groups of the box `ring_median_cd_m2` scans, and the values it sorts.
    pub ring_box_groups: f64,
    pub ring_values: f64,
}

impl SunWork {
    fn calls_cycles(calls: &[f64; 3]) -> f64 {
        calls[0] * sun::CANDIDATE_UNSEEN.cycles()
            + calls[1] * sun::CANDIDATE_FLAGGED.cycles()
            + calls[2] * sun::candidate_valid().cycles()
    }

    /// Cycles of finding the components.
    pub fn search_cycles(&self) -> f64 {
        self.all_over_flags * sun::ALL_OVER_PER_FLAG.cycles()
            + self.fov_groups * sun::FOV_PER_GROUP.cycles()
            + self.groups * sun::SCAN_PER_GROUP.cycles()
            + Self::calls_cycles(&self.scan_calls)
            + Self::calls_cycles(&self.search_calls)
            + self.members * sun::BFS_PER_MEMBER.cycles()
    }

    /// Cycles of measuring the chosen one.
    pub fn measure_cycles(&self) -> f64 {
        let comparisons = if self.ring_values > 1.0 {
            self.ring_values * self.ring_values.log2()
        } else {
            0.0
        };
        self.direction_visits * sun::DIRECTION_PER_MEMBER.cycles()
            + self.flux_visits * sun::FLUX_PER_MEMBER.cycles()
            + self.chosen_members * sun::BOX_PER_MEMBER.cycles()
            + self.box_groups * sun::box_per_group().cycles()
            + self.ring_box_groups * sun::RING_PER_GROUP.cycles()
            + comparisons * sun::SORT_PER_COMPARISON.cycles()
    }
}

/// One access to a fabric register over the lightweight bridge, seconds \[A12\] (**estimate**).
pub const LW_BRIDGE_ACCESS_S: f64 = 1e-6;

/// The sun from the fabric's accumulators (`sun::fabric`, `skyluxd`'s fabric source and cycle,
/// issue 22 item 2), per capture.
pub mod sun_fabric {
    use super::{Ops, VDIV_F64_CYCLES, VSQRT_F64_CYCLES};
    /// Register accesses: arming (`sun.frames` read, the four writes of
    /// `Fabric::sun_configure`) and one consistent read (`Fabric::sun_read`: `sun.frames`,
    /// the three 64-bit sums as six words, the count, the over-range count, the largest L, the
    /// box's two words, `sun.frames` again): 5 + 13.
    pub const REGISTER_ACCESSES: f64 = 18.0;
    /// The arithmetic of one capture, *estimate* from the source: the solar position for the
    /// prediction is left out (the cycle computes it in every mode). `FabricSunSearch::around`
    /// and `config` and `sun_from_fabric` make three projections and three unprojections
    /// through the lens: five θ(r) inversions of about six Newton steps (the lens polynomial,
    /// its derivative and a `vdiv.f64`, some 60 instructions a step), about twelve calls of
    /// libm's `sin`, `cos`, `atan2`, `acos` (some 150 instructions each on armhf, with their
    /// range reduction), the vignetting polynomial, the centroid's two divisions and the
    /// rotations: about 5000 instructions, 2000 load/store/VFP slots, the VFP pipeline held by
    /// some 40 divisions and 8 square roots. (On this x86 machine the same arithmetic and the
    /// ring's median take 3 µs: `sun_fabric_here_ms`.)
    pub const ARITHMETIC: Ops = Ops::new(
        5000.0,
        2000.0,
        40.0 * VDIV_F64_CYCLES + 8.0 * VSQRT_F64_CYCLES,
        0.0,
    );
    /// `check_sums`: a dozen compares and six 128-bit multiplies (*estimate*).
    pub const CHECK: Ops = Ops::new(100.0, 20.0, 0.0, 0.0);
}

/// The sun from the accumulators' sums: the register accesses \[A12\], the arithmetic, the
/// circumsolar background from the map (`fabric_background_cd_m2`: `ring_median_cd_m2` over
/// `ring_box_groups` groups, sorting `ring_values`, at the HPS search's costs per group and
/// comparison) and the limb (`FabricSun::with_limb`: `limb_groups` groups of the dilated box,
/// at the scan's cost per group of its box). Instead of [`sun_extraction`]'s scan of the whole
/// map.
pub fn sun_fabric(ring_box_groups: f64, ring_values: f64, limb_groups: f64) -> Stage {
    let comparisons = if ring_values > 1.0 {
        ring_values * ring_values.log2()
    } else {
        0.0
    };
    Stage {
        name: "sun_fabric",
        passes: vec![
            Pass {
                name: "arm and read the accumulators (lightweight bridge)",
                bytes: Bytes::default(),
                cycles: sun_fabric::REGISTER_ACCESSES * LW_BRIDGE_ACCESS_S * CLOCK_HZ,
                parallel: false,
            },
            Pass {
                name: "check the sums, the search window, centroid and calibration",
                bytes: Bytes::default(),
                cycles: sun_fabric::CHECK.cycles() + sun_fabric::ARITHMETIC.cycles(),
                parallel: false,
            },
            Pass {
                name: "limb: the map's groups around the box",
                bytes: Bytes {
                    dram_stream: (4.0 + 1.0 + 12.0 + 4.0) * limb_groups,
                    ..Bytes::default()
                },
                cycles: limb_groups * sun::box_per_group().cycles(),
                parallel: false,
            },
            Pass {
                name: "background: the ring around the box (median)",
                // Luminance, flag and direction per group of the ring's box, from the map.
                bytes: Bytes {
                    dram_stream: (4.0 + 1.0 + 12.0) * ring_box_groups,
                    ..Bytes::default()
                },
                cycles: ring_box_groups * sun::RING_PER_GROUP.cycles()
                    + comparisons * sun::SORT_PER_COMPARISON.cycles(),
                parallel: false,
            },
        ],
    }
}

/// The sun extraction's passes. Bytes per group of the scan: the f32x3 direction, the flag,
/// the f32 luminance and solid angle, the u32 label (written, then read).
pub fn sun_extraction(work: &SunWork) -> Stage {
    const SCAN_BYTES_PER_GROUP: f64 = 12.0 + 1.0 + 4.0 + 4.0 + 4.0;
    Stage {
        name: "sun_extraction",
        passes: vec![
            Pass {
                name: "labels (vec![usize::MAX; n])",
                bytes: Bytes {
                    dram_fill: 4.0 * work.groups,
                    ..Bytes::default()
                },
                cycles: 0.0,
                parallel: false,
            },
            Pass {
                name: "scan and components",
                bytes: Bytes {
                    dram_stream: SCAN_BYTES_PER_GROUP * work.groups,
                    ..Bytes::default()
                },
                cycles: work.search_cycles(),
                parallel: false,
            },
            Pass {
                name: "measure the chosen component",
                bytes: Bytes {
                    dram_stream: SCAN_BYTES_PER_GROUP * (work.box_groups + work.ring_box_groups),
                    ..Bytes::default()
                },
                cycles: work.measure_cycles(),
                parallel: false,
            },
        ],
    }
}

/// `DaylightCoefficients::apply_into` (hps/core/src/engine/daylight_coefficients.rs), per
/// coefficient: `vldmia r2!, {d16}; subs; vldmia r0!, {d17}; vmla.f64 d0, d17, d16; bne`. The
/// sum runs in order through one accumulator, so each VMLA waits for the last: a 9-cycle chain.
pub const DC_PER_COEFFICIENT: Ops = Ops::new(5.0, 3.0, VMLA_F64_CYCLES, VMLA_F64_LATENCY_CYCLES);

/// The daylight-coefficient update: `sensors` rows of `bins` f64 coefficients streamed from
/// the DDR3 (the patch luminances, 8 bytes × bins, stay in the L2 between rows).
pub fn dc_update(sensors: f64, bins: f64) -> Stage {
    let coefficients = sensors * bins;
    Stage {
        name: "dc_update",
        passes: vec![Pass {
            name: "rows × luminances",
            bytes: Bytes {
                dram_stream: 8.0 * coefficients,
                ..Bytes::default()
            },
            cycles: coefficients * DC_PER_COEFFICIENT.cycles(),
            parallel: true,
        }],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * b.abs().max(1e-30)
    }

    /// The binding bound wins: issue width, the shared port, the VFP pipeline, the chain.
    #[test]
    fn cycles_are_the_binding_bound() {
        assert_eq!(Ops::new(10.0, 3.0, 2.0, 0.0).cycles(), 5.0);
        assert_eq!(Ops::new(10.0, 7.0, 2.0, 0.0).cycles(), 7.0);
        assert_eq!(Ops::new(10.0, 7.0, 20.0, 0.0).cycles(), 20.0);
        assert_eq!(Ops::new(10.0, 7.0, 20.0, 25.0).cycles(), 25.0);
        let with = Ops::new(2.0, 1.0, 0.0, 0.0).with_calls(2.0, Ops::new(3.0, 4.0, 1.0, 0.0));
        assert_eq!(with, Ops::new(8.0, 9.0, 2.0, 0.0));
    }

    /// One sensor of 925 bins: 925 × 9 cycles at 925 MHz is 9 µs of compute; 7,400 bytes at
    /// 387.7 MB/s is 19.087 µs of memory; the pass takes the larger, on one core or two.
    #[test]
    fn dc_update_of_one_sensor() {
        let s = dc_update(1.0, 925.0);
        assert!(close(s.compute_s(), 9e-6));
        assert!(close(s.memory_s(), 7400.0 / 387.7e6));
        assert!(close(s.seconds(1), 7400.0 / 387.7e6));
        assert!(close(s.seconds(2), s.seconds(1)));
        // Memory-bound at any size: 8 bytes per 9 cycles is 822 MB/s of demand.
        let big = dc_update(400.0, 4610.0);
        assert!(big.memory_s() > big.compute_s());
    }

    /// One frame of 1,000 words: the passes' memory in microseconds by hand (the words read
    /// in place: no zeroed byte buffer, no conversion pass), the checksum's and the
    /// unpacking's compute (2 and 2.5 cycles a word) under their memory.
    #[test]
    fn hps_read_of_one_small_frame() {
        let s = hps_read(1.0, 1000.0);
        let fill = 4000.0 / DRAM_FILL_BYTES_PER_S;
        let uncached = 4000.0 / 64e6; // 62.5 µs
        assert!(close(uncached, 62.5e-6));
        let stream = (4000.0 + 8000.0) / 387.7e6;
        assert!(close(s.memory_s(), fill + uncached + stream));
        assert!(close(s.compute_s(), 4500.0 / 925e6));
        assert!(close(s.seconds(1), s.memory_s()));
        assert_eq!(s.passes.len(), 4);
    }

    /// A map of 1,000 words read cached: the invalidation (125 lines × 40 cycles), then
    /// 8,000 bytes of cached traffic (the copy into words) instead of the uncached read;
    /// faster than the uncached read.
    #[test]
    fn a_cached_map_read_invalidates_then_streams() {
        let s = hps_read_map_cached(1000.0);
        assert_eq!(s.passes.len(), 2);
        assert!(close(s.compute_s(), 125.0 * 40.0 / 925e6));
        assert!(close(s.memory_s(), 8_000.0 / 387.7e6));
        assert!(s.seconds(1) < hps_read_map(1000.0).seconds(1));
    }

    /// The merge per group at five exposures, half of the pairs valid, the group valid:
    /// 5 × (106 + 6.5 + 9) + 25 + 2.5 × 31 + 2.5 × 9 + 100 = 832.5 cycles.
    #[test]
    fn merge_cycles_per_group() {
        assert_eq!(merge::group_row().cycles(), 106.0);
        assert_eq!(merge::pilot().cycles(), 25.0);
        let w = HdrWork {
            groups: 1.0,
            exposures: 5.0,
            valid_pairs: 2.5,
            valid_groups: 1.0,
        };
        assert!(close(w.cycles(), 832.5));
        // A flagged group: 5 × 121.5 + 25 + 5 × 9 + (46 + 70) / 2 = 735.5.
        let flagged = HdrWork {
            valid_pairs: 0.0,
            valid_groups: 0.0,
            ..w
        };
        assert!(close(flagged.cycles(), 735.5));
    }

    /// Two cores halve the compute of a parallel pass, not its memory, and leave a serial
    /// pass alone; a stage adds its passes' max(memory, compute).
    #[test]
    fn passes_and_cores() {
        let compute_bound = Pass {
            name: "c",
            bytes: Bytes {
                dram_stream: 387.7e6 * 0.1,
                ..Bytes::default()
            },
            cycles: 925e6,
            parallel: true,
        };
        assert!(close(compute_bound.seconds(1), 1.0));
        assert!(close(compute_bound.seconds(2), 0.5));
        let memory_bound = Pass {
            cycles: 925e6 * 0.05,
            ..compute_bound.clone()
        };
        assert!(close(memory_bound.seconds(2), 0.1));
        let serial = Pass {
            parallel: false,
            ..compute_bound.clone()
        };
        assert!(close(serial.seconds(2), 1.0));
        let stage = Stage {
            name: "s",
            passes: vec![compute_bound, memory_bound, serial],
        };
        assert!(close(stage.seconds(2), 0.5 + 0.1 + 1.0));
        assert!(close(stage.memory_s(), 0.3));
    }

    /// A valid candidate test costs its port slots (46 + 10 for `fmin`); the uncached read
    /// of 50.4 MB alone is 0.79 s.
    #[test]
    fn sun_and_uncached_figures() {
        assert_eq!(sun::candidate_valid().cycles(), 56.0);
        assert_eq!(sun::box_per_group().cycles(), 41.0);
        let read = hps_read(5.0, 1296.0 * 1944.0);
        let uncached: f64 = read.passes[0].memory_s();
        assert!((uncached - 0.787).abs() < 0.001, "{uncached}");
    }
}
