//! The physical backend: a window of physical memory (the register bridge or a DMA buffer)
//! mapped with memmap2 and accessed with volatile loads and stores.
//!
//! On the DE1-SoC the file is `/dev/mem` (or `/dev/uioN`, whose map 0 starts at offset 0) and
//! is opened with `O_SYNC`: on ARM, Linux then maps RAM write-combining and non-RAM (the
//! bridges, memory excluded with `mem=` or `no-map`) as device memory (`phys_mem_access_prot`,
//! hardware-facts.md §3.4). The FPGA-to-SDRAM port is not cache-coherent, so a cached mapping
//! would return stale frame data; the uncached mapping is what makes DMA reads correct.
//! In tests the same code maps an ordinary file.

use crate::{check_access, BusError, DmaMemory, RegisterBus};
use std::fs::OpenOptions;
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Path, PathBuf};

/// A mapped window of physical memory (or of a file standing in for it).
pub struct MappedWindow {
    map: memmap2::MmapRaw,
    size: u64,
    phys_base: u64,
    path: PathBuf,
}

impl std::fmt::Debug for MappedWindow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "MappedWindow({}, base {:#x}, {:#x} bytes)",
            self.path.display(),
            self.phys_base,
            self.size
        )
    }
}

impl MappedWindow {
    /// Maps `size` bytes of `path` starting at byte `file_offset`; `phys_base` is the physical
    /// address the window stands for (equal to `file_offset` for `/dev/mem`, the UIO map's
    /// address for `/dev/uioN`).
    pub fn open(
        path: &Path,
        file_offset: u64,
        size: u64,
        phys_base: u64,
    ) -> Result<Self, BusError> {
        let io = |what: &'static str| {
            move |source| BusError::Io {
                path: path.to_path_buf(),
                what,
                source,
            }
        };
        let len = usize::try_from(size).map_err(|_| BusError::TooLarge { size })?;
        let file = OpenOptions::new()
            .read(true)
            .write(true)
            .custom_flags(libc::O_SYNC)
            .open(path)
            .map_err(io("cannot open"))?;
        let meta = file.metadata().map_err(io("cannot stat"))?;
        if meta.is_file() && meta.len() < file_offset.saturating_add(size) {
            return Err(BusError::FileTooShort {
                path: path.to_path_buf(),
                base: file_offset,
                wanted: size,
                actual: meta.len().saturating_sub(file_offset),
            });
        }
        let map = memmap2::MmapOptions::new()
            .offset(file_offset)
            .len(len)
            .map_raw(&file)
            .map_err(io("cannot map"))?;
        Ok(Self {
            map,
            size,
            phys_base,
            path: path.to_path_buf(),
        })
    }

    /// Maps the register window behind the lightweight bridge through `/dev/mem`.
    pub fn open_registers(dev_mem: &Path) -> Result<Self, BusError> {
        let base = skylux_regmap::LW_BRIDGE_PHYS_BASE as u64;
        Self::open(
            dev_mem,
            base,
            skylux_regmap::LW_BRIDGE_SPAN_BYTES as u64,
            base,
        )
    }

    /// The file this window maps.
    pub fn path(&self) -> &Path {
        &self.path
    }

    fn ptr(&self, offset: u64) -> *mut u8 {
        // In bounds: every caller checked `offset + len <= size`, and size fits usize.
        unsafe { self.map.as_mut_ptr().add(offset as usize) }
    }
}

impl RegisterBus for MappedWindow {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        check_access(offset as u64, 4, self.size, 4)?;
        // Aligned and in bounds (checked above); volatile so every read reaches the bus.
        Ok(unsafe { std::ptr::read_volatile(self.ptr(offset as u64) as *const u32) })
    }

    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        check_access(offset as u64, 4, self.size, 4)?;
        unsafe { std::ptr::write_volatile(self.ptr(offset as u64) as *mut u32, value) };
        Ok(())
    }
}

impl DmaMemory for MappedWindow {
    fn phys_base(&self) -> u64 {
        self.phys_base
    }

    fn len_bytes(&self) -> u64 {
        self.size
    }

    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        check_access(offset, buf.len() as u64, self.size, 1)?;
        // Order this copy after whatever told us the data is there (a status register read).
        std::sync::atomic::fence(std::sync::atomic::Ordering::SeqCst);
        unsafe { std::ptr::copy_nonoverlapping(self.ptr(offset), buf.as_mut_ptr(), buf.len()) };
        Ok(())
    }

    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        check_access(offset, data.len() as u64, self.size, 1)?;
        unsafe { std::ptr::copy_nonoverlapping(data.as_ptr(), self.ptr(offset), data.len()) };
        std::sync::atomic::fence(std::sync::atomic::Ordering::SeqCst);
        Ok(())
    }

    fn read_words_le(
        &mut self,
        offset: u64,
        count: usize,
        words: &mut Vec<u32>,
    ) -> Result<(), BusError> {
        let len = 4 * count as u64;
        check_access(offset, len, self.size, 1)?;
        std::sync::atomic::fence(std::sync::atomic::Ordering::SeqCst);
        // The fabric does not write the range while it is read (the ring's descriptor said
        // the slot is complete).
        // SAFETY: `offset + len` is inside the mapping (checked above).
        unsafe { crate::append_words_le(words, self.ptr(offset), count) };
        Ok(())
    }
}
