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
