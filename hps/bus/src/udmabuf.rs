//! The DMA buffer through the u-dma-buf driver (`/dev/udmabufN`), mapped **cached**, with the
//! cache kept coherent by hand: the FPGA-to-SDRAM port is not cache-coherent
//! (hardware-facts.md §3.2), so before the HPS reads what the fabric wrote, the lines of
//! that range are invalidated (`sync_for_cpu`, direction DMA_FROM_DEVICE), and after the
//! HPS writes (releasing a slot), the lines are cleaned to SDRAM (`sync_for_device`,
//! DMA_TO_DEVICE) before the fabric may write there again.
//!
//! Why: an uncached mapping (`/dev/mem` with `O_SYNC`, [`crate::MappedWindow`]) makes every
//! load a bus transaction; the A9 reads such memory at a fraction of its cached bandwidth
//! (BENCHMARKS.md "skyluxd cycle budget"). Cached, a frame is read at memcpy speed after one
//! invalidation of its range.
//!
//! The driver's interface (u-dma-buf's manual, "sync_for_cpu", "sync_for_device"): the
//! buffer's physical address and size in `/sys/class/u-dma-buf/<name>/phys_addr` and
//! `size`; a write of `0x%08X%08X` (offset; size with its low 4 bits replaced by
//! direction << 2 | 1) to `sync_for_cpu` or `sync_for_device` syncs that range alone.
//! Ranges are widened to whole 32-byte cache lines (the A9's L1 and the L2C-310 line,
//! hardware-facts.md §3.4) and sizes rounded up to the 16 bytes the format keeps.
//!
//! In tests a directory of ordinary files stands in for the class directory and an ordinary
//! file for the device: the commands written are checked there.

use crate::{check_access, BusError, DmaMemory};
use std::fs::OpenOptions;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The cache line of the Cortex-A9 L1 and the PL310 L2 on the Cyclone V HPS.
pub const CACHE_LINE_BYTES: u64 = 32;
/// u-dma-buf's DMA_TO_DEVICE and DMA_FROM_DEVICE.
const TO_DEVICE: u64 = 1;
const FROM_DEVICE: u64 = 2;

/// The u-dma-buf buffer, mapped cached.
pub struct UdmabufWindow {
    map: memmap2::MmapRaw,
    size: u64,
    phys_base: u64,
    device: PathBuf,
    class_dir: PathBuf,
}

impl std::fmt::Debug for UdmabufWindow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "UdmabufWindow({}, base {:#x}, {:#x} bytes, cached)",
            self.device.display(),
            self.phys_base,
            self.size
        )
    }
}

fn io<'a>(path: &'a Path, what: &'static str) -> impl FnOnce(std::io::Error) -> BusError + 'a {
    move |source| BusError::Io {
        path: path.to_path_buf(),
        what,
        source,
    }
}

/// Reads a number from a sysfs attribute: hexadecimal with or without `0x` for
/// `phys_addr` (the driver prints `%pad`-style hex), decimal for `size`.
fn read_attribute(path: &Path, hex: bool) -> Result<u64, BusError> {
    let text = std::fs::read_to_string(path).map_err(io(path, "cannot read"))?;
    let t = text.trim();
    let digits = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X"));
    let parsed = match (hex, digits) {
        (_, Some(d)) => u64::from_str_radix(d, 16),
        (true, None) => u64::from_str_radix(t, 16),
        (false, None) => t.parse(),
    };
    parsed.map_err(|e| BusError::Io {
        path: path.to_path_buf(),
        what: "not a number",
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, format!("'{t}': {e}")),
    })
}

impl UdmabufWindow {
    /// Opens `device` (`/dev/udmabuf0`) and its class directory
    /// (`/sys/class/u-dma-buf/udmabuf0`), and maps the whole buffer cached.
    pub fn open(device: &Path, class_dir: &Path) -> Result<Self, BusError> {
        let phys_base = read_attribute(&class_dir.join("phys_addr"), true)?;
        let size = read_attribute(&class_dir.join("size"), false)?;
        let len = usize::try_from(size).map_err(|_| BusError::TooLarge { size })?;
        if size == 0 {
            return Err(BusError::FileTooShort {
                path: class_dir.join("size"),
                base: 0,
                wanted: 1,
                actual: 0,
            });
        }
        // Without O_SYNC: u-dma-buf then maps the buffer cached.
        let file = OpenOptions::new()
            .read(true)
            .write(true)
            .open(device)
            .map_err(io(device, "cannot open"))?;
        let meta = file.metadata().map_err(io(device, "cannot stat"))?;
        if meta.is_file() && meta.len() < size {
            return Err(BusError::FileTooShort {
                path: device.to_path_buf(),
                base: 0,
                wanted: size,
                actual: meta.len(),
            });
        }
        let map = memmap2::MmapOptions::new()
            .len(len)
            .map_raw(&file)
            .map_err(io(device, "cannot map"))?;
        Ok(Self {
            map,
            size,
            phys_base,
            device: device.to_path_buf(),
            class_dir: class_dir.to_path_buf(),
        })
    }

    /// The command u-dma-buf takes for a sync of `len` bytes at `offset` in `direction`: the
    /// range widened to whole cache lines (and the size to the format's 16 bytes).
    pub fn sync_command(offset: u64, len: u64, direction: u64) -> String {
        let start = offset / CACHE_LINE_BYTES * CACHE_LINE_BYTES;
        let end = (offset + len).div_ceil(CACHE_LINE_BYTES) * CACHE_LINE_BYTES;
        let size = (end - start).div_ceil(16) * 16;
        format!(
            "0x{:08X}{:08X}",
            start & 0xFFFF_FFFF,
            (size & 0xFFFF_FFF0) | (direction << 2) | 1
        )
    }

    fn sync(&self, attribute: &str, offset: u64, len: u64, direction: u64) -> Result<(), BusError> {
        let path = self.class_dir.join(attribute);
        let mut f = OpenOptions::new()
            .write(true)
            .open(&path)
            .map_err(io(&path, "cannot open"))?;
        f.write_all(Self::sync_command(offset, len, direction).as_bytes())
            .map_err(io(&path, "cache maintenance refused"))
    }

    fn ptr(&self, offset: u64) -> *mut u8 {
        // In bounds: every caller checked `offset + len <= size`, and size fits usize.
        unsafe { self.map.as_mut_ptr().add(offset as usize) }
    }
}

impl DmaMemory for UdmabufWindow {
    fn phys_base(&self) -> u64 {
        self.phys_base
    }

    fn len_bytes(&self) -> u64 {
        self.size
    }

    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        check_access(offset, buf.len() as u64, self.size, 1)?;
        if buf.is_empty() {
            return Ok(());
        }
        // Drop whatever the cache holds of the range (lines speculatively fetched while the
        // fabric wrote), so the copy reads SDRAM. Safe for the widened edges too: every
        // write is cleaned at once (below), so no line of the buffer is ever dirty here.
        self.sync("sync_for_cpu", offset, buf.len() as u64, FROM_DEVICE)?;
        std::sync::atomic::fence(std::sync::atomic::Ordering::SeqCst);
        unsafe { std::ptr::copy_nonoverlapping(self.ptr(offset), buf.as_mut_ptr(), buf.len()) };
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
        if count == 0 {
            return Ok(());
        }
        // As `read_bytes`: the range invalidated first, then one pass reading it in place.
        self.sync("sync_for_cpu", offset, len, FROM_DEVICE)?;
        std::sync::atomic::fence(std::sync::atomic::Ordering::SeqCst);
        // SAFETY: `offset + len` is inside the mapping (checked above).
        unsafe { crate::append_words_le(words, self.ptr(offset), count) };
        Ok(())
    }

    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        check_access(offset, data.len() as u64, self.size, 1)?;
        if data.is_empty() {
            return Ok(());
        }
        unsafe { std::ptr::copy_nonoverlapping(data.as_ptr(), self.ptr(offset), data.len()) };
        std::sync::atomic::fence(std::sync::atomic::Ordering::SeqCst);
        // Push the written lines to SDRAM before the fabric reads or overwrites the range.
        self.sync("sync_for_device", offset, data.len() as u64, TO_DEVICE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A class directory and a device file standing in for the driver's.
    fn fake(size: u64, phys: &str) -> (tempfile::TempDir, PathBuf, PathBuf) {
        let dir = tempfile::tempdir().unwrap();
        let class = dir.path().join("udmabuf0");
        std::fs::create_dir(&class).unwrap();
        std::fs::write(class.join("phys_addr"), phys).unwrap();
        std::fs::write(class.join("size"), format!("{size}\n")).unwrap();
        std::fs::write(class.join("sync_for_cpu"), "").unwrap();
        std::fs::write(class.join("sync_for_device"), "").unwrap();
        let device = dir.path().join("dev-udmabuf0");
        std::fs::write(&device, vec![0u8; size as usize]).unwrap();
        (dir, class, device)
    }

    #[test]
    fn commands_cover_whole_lines_in_the_drivers_format() {
        // 100 bytes at 0x1234: lines 0x1220..0x12A0, 128 bytes, direction 2, sync bit.
        assert_eq!(
            UdmabufWindow::sync_command(0x1234, 100, FROM_DEVICE),
            format!("0x{:08X}{:08X}", 0x1220, 128 | (2 << 2) | 1)
        );
        // One byte is one line; an aligned line is itself.
        assert_eq!(
            UdmabufWindow::sync_command(64, 1, TO_DEVICE),
            "0x0000004000000025"
        );
        assert_eq!(
            UdmabufWindow::sync_command(64, 32, TO_DEVICE),
            "0x0000004000000025"
        );
    }

    #[test]
    fn reads_invalidate_and_writes_clean_their_range() {
        let (_dir, class, device) = fake(4096, "0x38000000\n");
        let mut w = UdmabufWindow::open(&device, &class).unwrap();
        assert_eq!(w.phys_base(), 0x3800_0000);
        assert_eq!(w.len_bytes(), 4096);
        w.write_bytes(256, &[1, 2, 3, 4]).unwrap();
        assert_eq!(
            std::fs::read_to_string(class.join("sync_for_device")).unwrap(),
            UdmabufWindow::sync_command(256, 4, TO_DEVICE)
        );
        // What the "fabric" wrote into the file is what a read returns.
        let mut buf = [0u8; 4];
        w.read_bytes(256, &mut buf).unwrap();
        assert_eq!(buf, [1, 2, 3, 4]);
        assert_eq!(
            std::fs::read_to_string(class.join("sync_for_cpu")).unwrap(),
            UdmabufWindow::sync_command(256, 4, FROM_DEVICE)
        );
        assert!(w.read_bytes(4094, &mut buf).is_err(), "out of bounds");
        // Words read in place: the same little-endian words, appended, the range invalidated.
        w.write_bytes(1024, &[1, 0, 0, 0, 0xEF, 0xBE, 0xAD, 0xDE])
            .unwrap();
        let mut words = vec![7u32];
        w.read_words_le(1024, 2, &mut words).unwrap();
        assert_eq!(words, [7, 1, 0xDEAD_BEEF]);
        assert_eq!(
            std::fs::read_to_string(class.join("sync_for_cpu")).unwrap(),
            UdmabufWindow::sync_command(1024, 8, FROM_DEVICE)
        );
        assert!(
            w.read_words_le(4092, 2, &mut words).is_err(),
            "out of bounds"
        );
        assert_eq!(words.len(), 3, "nothing appended on an error");
    }

    #[test]
    fn a_missing_or_unreadable_driver_is_a_clear_error() {
        let (_dir, class, device) = fake(4096, "zz\n");
        let e = UdmabufWindow::open(&device, &class)
            .unwrap_err()
            .to_string();
        assert!(e.contains("phys_addr") && e.contains("zz"), "{e}");
        let (_dir, class, device) = fake(4096, "38000000\n");
        std::fs::write(class.join("size"), "8192\n").unwrap();
        let e = UdmabufWindow::open(&device, &class)
            .unwrap_err()
            .to_string();
        assert!(e.contains("dev-udmabuf0"), "{e}");
        let e = UdmabufWindow::open(Path::new("/no/udmabuf"), Path::new("/no/class"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("/no/class/phys_addr"), "{e}");
        // Without the sync attribute, a read fails rather than return stale data.
        let (_dir, class, device) = fake(4096, "38000000\n");
        std::fs::remove_file(class.join("sync_for_cpu")).unwrap();
        let mut w = UdmabufWindow::open(&device, &class).unwrap();
        let e = w.read_bytes(0, &mut [0u8; 8]).unwrap_err().to_string();
        assert!(e.contains("sync_for_cpu"), "{e}");
    }
}
