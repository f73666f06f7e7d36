//! The ray-box unit's driver: batches of work items (`skylux_regmap::raybox_format`) written to
//! the DMA buffer, the batch started through the `raybox.*` registers, results read back.
//!
//! [`RayBoxBackend`] is what the engine's accelerated box test (`engine::accel`) calls: the
//! driver on the fabric ([`RayBoxDriver`]) or the golden model standing in for it
//! ([`GoldenRayBox`]), which answers bit for bit as the unit does.

use skylux_bus::{BusError, DmaMemory, RegisterBus};
use skylux_regmap::raybox;
use skylux_regmap::raybox_format::{
    result_word, unpack_result, FORMAT_VERSION, INDEX_BITS, ITEM_BYTES, ITEM_WORDS, RESULT_BYTES,
};

/// One work item's memory words.
pub type ItemWords = [u64; ITEM_WORDS];

/// Why a batch failed. Every variant names the register field or item concerned.
#[derive(Debug, thiserror::Error)]
pub enum RayBoxError {
    #[error("ray-box registers: {0}")]
    Bus(#[from] BusError),
    #[error("raybox.info.FORMAT is {found}, this software speaks format {expected}")]
    Format { found: u32, expected: u32 },
    #[error(
        "the DMA buffer at {base:#x} (+{len:#x} bytes) is outside the unit's 32-bit address space"
    )]
    BufferAddress { base: u64, len: u64 },
    #[error("the DMA buffer ({len} bytes) holds no work item and its result")]
    BufferTooSmall { len: u64 },
    #[error("raybox.status.BAD_DESCRIPTOR: the unit refused the batch or item {tests_done}")]
    BadDescriptor { tests_done: u32 },
    #[error("raybox.status.OUT_OF_WINDOW: the batch reaches outside raybox.window_*")]
    OutOfWindow,
    #[error("raybox.status.BUS_TIMEOUT: the SDRAM port stalled longer than raybox.bus_timeout ({tests_done} tests done)")]
    BusTimeout { tests_done: u32 },
    #[error("raybox.status.DONE not set after {polls} polls of raybox.status")]
    NoCompletion { polls: u64 },
    #[error("raybox.tests_done is {found}, the batch held {expected} items")]
    Incomplete { found: u32, expected: u32 },
    #[error("result {position} carries item index {found}: the result area was corrupted")]
    ResultIndex { position: usize, found: u32 },
    #[error("work item {index} has a wrong magic byte")]
    BadItem { index: usize },
}

/// Runs batches of ray-box work items.
pub trait RayBoxBackend: Send {
    /// Appends one result word per item of `items` to `results`.
    fn run(&mut self, items: &[ItemWords], results: &mut Vec<u64>) -> Result<(), RayBoxError>;
}

/// The golden model as a backend: what the unit answers, computed on the HPS.
#[derive(Clone, Copy, Debug, Default)]
pub struct GoldenRayBox;

impl RayBoxBackend for GoldenRayBox {
    fn run(&mut self, items: &[ItemWords], results: &mut Vec<u64>) -> Result<(), RayBoxError> {
        for (index, words) in items.iter().enumerate() {
            match result_word(index as u32, words) {
                Some(r) => results.push(r),
                None => return Err(RayBoxError::BadItem { index }),
            }
        }
        Ok(())
    }
}

/// The driver of the fabric's unit. The whole DMA buffer is the unit's window; each batch's
/// items sit at its start and the results right after them.
pub struct RayBoxDriver<R: RegisterBus, M: DmaMemory> {
    regs: R,
    memory: M,
    /// Most polls of `raybox.status` per batch before giving up.
    pub poll_limit: u64,
    lanes: u32,
}

/// Most items per batch: the width of `raybox.work_count.ITEMS` and of the result's index.
pub const MAX_BATCH_ITEMS: usize = 1 << INDEX_BITS;

impl<R: RegisterBus, M: DmaMemory> RayBoxDriver<R, M> {
    /// Checks the unit's format and programs its window.
    pub fn new(mut regs: R, memory: M) -> Result<Self, RayBoxError> {
        let info = regs.read32(raybox::info::REG.offset)?;
        let found = raybox::info::FORMAT.get(info);
        if found != FORMAT_VERSION {
            return Err(RayBoxError::Format {
                found,
                expected: FORMAT_VERSION,
            });
        }
        let (base, len) = (memory.phys_base(), memory.len_bytes());
        if base.checked_add(len).is_none_or(|end| end > 1 << 32) || base > u32::MAX as u64 {
            return Err(RayBoxError::BufferAddress { base, len });
        }
        if len < (ITEM_BYTES + RESULT_BYTES) as u64 {
            return Err(RayBoxError::BufferTooSmall { len });
        }
        regs.write32(raybox::window_base::REG.offset, base as u32)?;
        regs.write32(
            raybox::window_size::REG.offset,
            len.min(u32::MAX as u64) as u32,
        )?;
        Ok(Self {
            regs,
            memory,
            poll_limit: 1_000_000,
            lanes: raybox::info::LANES.get(info),
        })
    }

    /// Lanes the unit reports (`raybox.info.LANES`).
    pub fn lanes(&self) -> u32 {
        self.lanes
    }

    /// The register bus, for tests that look at other registers.
    pub fn registers(&mut self) -> &mut R {
        &mut self.regs
    }

    /// The DMA buffer.
    pub fn memory(&mut self) -> &mut M {
        &mut self.memory
    }

    /// Items per batch that fit the buffer.
    pub fn batch_capacity(&self) -> usize {
        let per_item = (ITEM_BYTES + RESULT_BYTES) as u64;
        ((self.memory.len_bytes() / per_item) as usize).min(MAX_BATCH_ITEMS - 1)
    }

    fn run_one(&mut self, items: &[ItemWords], results: &mut Vec<u64>) -> Result<(), RayBoxError> {
        let n = items.len();
        let mut bytes = Vec::with_capacity(n * ITEM_BYTES as usize);
        for w in items.iter().flatten() {
            bytes.extend_from_slice(&w.to_le_bytes());
        }
        self.memory.write_bytes(0, &bytes)?;
        let base = self.memory.phys_base() as u32;
        let result_offset = n as u32 * ITEM_BYTES;
        let status = raybox::status::REG.offset;
        let sticky = raybox::status::DONE.mask()
            | raybox::status::BAD_DESCRIPTOR.mask()
            | raybox::status::OUT_OF_WINDOW.mask()
            | raybox::status::BUS_TIMEOUT.mask();
        self.regs.write32(status, sticky)?;
        self.regs.write32(raybox::work_base::REG.offset, base)?;
        self.regs
            .write32(raybox::work_count::REG.offset, n as u32)?;
        self.regs
            .write32(raybox::result_base::REG.offset, base + result_offset)?;
        self.regs
            .write32(raybox::ctrl::REG.offset, raybox::ctrl::START.mask())?;
        let mut polls = 0;
        let s = loop {
            let s = self.regs.read32(status)?;
            if raybox::status::DONE.get(s) == 1 {
                break s;
            }
            polls += 1;
            if polls >= self.poll_limit {
                self.regs
                    .write32(raybox::ctrl::REG.offset, raybox::ctrl::ABORT.mask())?;
                return Err(RayBoxError::NoCompletion { polls });
            }
        };
        let tests_done = self.regs.read32(raybox::tests_done::REG.offset)?;
        if raybox::status::BUS_TIMEOUT.get(s) == 1 {
            return Err(RayBoxError::BusTimeout { tests_done });
        }
        if raybox::status::OUT_OF_WINDOW.get(s) == 1 {
            return Err(RayBoxError::OutOfWindow);
        }
        if raybox::status::BAD_DESCRIPTOR.get(s) == 1 {
            return Err(RayBoxError::BadDescriptor { tests_done });
        }
        if tests_done != n as u32 {
            return Err(RayBoxError::Incomplete {
                found: tests_done,
                expected: n as u32,
            });
        }
        let mut out = vec![0u8; n * RESULT_BYTES as usize];
        self.memory.read_bytes(result_offset as u64, &mut out)?;
        for (position, chunk) in out.chunks_exact(8).enumerate() {
            let word = u64::from_le_bytes(chunk.try_into().unwrap_or([0; 8]));
            let (found, _) = unpack_result(word);
            if found != position as u32 {
                return Err(RayBoxError::ResultIndex { position, found });
            }
            results.push(word);
        }
        Ok(())
    }
}

impl<R: RegisterBus + Send, M: DmaMemory + Send> RayBoxBackend for RayBoxDriver<R, M> {
    fn run(&mut self, items: &[ItemWords], results: &mut Vec<u64>) -> Result<(), RayBoxError> {
        let capacity = self.batch_capacity().max(1);
        // Result indices restart at 0 with each batch; callers go by position.
        for chunk in items.chunks(capacity) {
            self.run_one(chunk, results)?;
        }
        Ok(())
    }
}
