//! How HPS code reaches the fabric.
//!
//! Two traits: [`RegisterBus`] for the 32-bit registers behind the lightweight bridge and
//! [`DmaMemory`] for the buffers the fabric writes through the FPGA-to-SDRAM port. Drivers
//! are written against the traits only, so the same driver runs on the DE1-SoC
//! ([`mapped::MappedWindow`] over `/dev/mem` or a UIO device, [`udmabuf::UdmabufWindow`] over
//! u-dma-buf with explicit cache maintenance), on an ordinary file in tests,
//! and against the cycle-accurate fabric model (`skylux-sim`).

pub mod error;
pub mod mapped;
pub mod registers;
pub mod udmabuf;

pub use error::BusError;
pub use mapped::MappedWindow;
pub use registers::RegisterAccess;
pub use udmabuf::UdmabufWindow;

/// 32-bit register access in the register window.
pub trait RegisterBus {
    /// Reads the register at byte `offset` from the start of the window.
    fn read32(&mut self, offset: u32) -> Result<u32, BusError>;
    /// Writes the register at byte `offset` from the start of the window.
    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError>;
}

/// Access to a DMA buffer: a physically contiguous window of SDRAM that the fabric writes.
pub trait DmaMemory {
    /// Physical address of the first byte, as programmed into the fabric.
    fn phys_base(&self) -> u64;
    /// Size in bytes.
    fn len_bytes(&self) -> u64;
    /// Copies `buf.len()` bytes starting at byte `offset` of the buffer into `buf`.
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError>;
    /// Copies `data` into the buffer at byte `offset`.
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError>;
    /// Appends the `count` little-endian 32-bit words from byte `offset` to `words`. A
    /// mapping reads them in place in one pass (no zeroed byte buffer, no second pass turning
    /// bytes into words: two of the frame reader's three passes over a frame on the A9,
    /// `timing::a9::hps_read`); this default goes through bytes.
    fn read_words_le(
        &mut self,
        offset: u64,
        count: usize,
        words: &mut Vec<u32>,
    ) -> Result<(), BusError> {
        let mut bytes = vec![0u8; 4 * count];
        self.read_bytes(offset, &mut bytes)?;
        words.extend(
            bytes
                .chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
        );
        Ok(())
    }
}

/// Appends `count` little-endian words copied from `src` to `words`: the one pass of
/// [`DmaMemory::read_words_le`] over a mapping, the C library's memcpy straight into the
/// words (word and multiple loads from the mapping, as the byte copy did).
///
/// # Safety
/// `src` must be valid for reads of `4 * count` bytes.
pub(crate) unsafe fn append_words_le(words: &mut Vec<u32>, src: *const u8, count: usize) {
    words.reserve(count);
    let start = words.len();
    // SAFETY: `reserve` made room for `count` more words after `start`; the caller vouches
    // for `src`; every byte of the new words is written before `set_len`.
    unsafe {
        std::ptr::copy_nonoverlapping(src, words.as_mut_ptr().add(start).cast::<u8>(), 4 * count);
        words.set_len(start + count);
    }
    if cfg!(target_endian = "big") {
        for w in &mut words[start..] {
            *w = u32::from_le(*w);
        }
    }
}

impl<T: RegisterBus + ?Sized> RegisterBus for &mut T {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        (**self).read32(offset)
    }
    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        (**self).write32(offset, value)
    }
}

impl<T: RegisterBus + ?Sized> RegisterBus for Box<T> {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        (**self).read32(offset)
    }
    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        (**self).write32(offset, value)
    }
}

/// Checks an access of `len` bytes at `offset` against a window of `size` bytes with the
/// given alignment, without overflowing on 32-bit targets.
pub fn check_access(offset: u64, len: u64, size: u64, align: u64) -> Result<(), BusError> {
    if !offset.is_multiple_of(align) {
        return Err(BusError::Unaligned { offset, align });
    }
    match offset.checked_add(len) {
        Some(end) if end <= size => Ok(()),
        _ => Err(BusError::OutOfBounds { offset, len, size }),
    }
}
