//! The only physical memory skyluxd maps: the register window behind the lightweight
//! HPS-to-FPGA bridge (through `/dev/uioN`'s map 0, or `/dev/mem`) and the frame buffer in
//! the reserved DMA region. The register window is opened with `O_SYNC` (device memory).
//! The buffer, by default through `/dev/mem` with `O_SYNC`, is non-cached: the
//! FPGA-to-SDRAM port is not cache-coherent and a cached mapping without maintenance would
//! return stale frames (hardware-facts.md §3.2, §3.4). With `dma_device` (u-dma-buf) it is
//! mapped cached and kept coherent by explicit invalidation and cleaning of each range read
//! or written (`skylux_bus::udmabuf`): frames are then read at cached bandwidth.

use crate::config::HardwareConfig;
use skylux_bus::{BusError, DmaMemory, MappedWindow, UdmabufWindow};
use std::path::Path;

/// `/dev/mem`.
pub const DEV_MEM: &str = "/dev/mem";
/// Where u-dma-buf publishes each buffer's attributes.
pub const UDMABUF_CLASS: &str = "/sys/class/u-dma-buf";

/// The two mapped windows.
pub struct Windows {
    pub registers: MappedWindow,
    pub dma: DmaWindow,
}

/// The frame buffer, uncached or cached with maintenance.
#[derive(Debug)]
pub enum DmaWindow {
    Uncached(MappedWindow),
    Cached(UdmabufWindow),
}

impl DmaMemory for DmaWindow {
    fn phys_base(&self) -> u64 {
        match self {
            DmaWindow::Uncached(w) => w.phys_base(),
            DmaWindow::Cached(w) => w.phys_base(),
        }
    }
    fn len_bytes(&self) -> u64 {
        match self {
            DmaWindow::Uncached(w) => w.len_bytes(),
            DmaWindow::Cached(w) => w.len_bytes(),
        }
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        match self {
            DmaWindow::Uncached(w) => w.read_bytes(offset, buf),
            DmaWindow::Cached(w) => w.read_bytes(offset, buf),
        }
    }
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        match self {
            DmaWindow::Uncached(w) => w.write_bytes(offset, data),
            DmaWindow::Cached(w) => w.write_bytes(offset, data),
        }
    }
    fn read_words_le(
        &mut self,
        offset: u64,
        count: usize,
        words: &mut Vec<u32>,
    ) -> Result<(), BusError> {
        match self {
            DmaWindow::Uncached(w) => w.read_words_le(offset, count, words),
            DmaWindow::Cached(w) => w.read_words_le(offset, count, words),
        }
    }
}

/// Why the windows could not be mapped.
#[derive(Debug, thiserror::Error)]
pub enum MapError {
    #[error("hardware.{key}: {message}")]
    Refused { key: &'static str, message: String },
    #[error("{0}")]
    Bus(#[from] skylux_bus::BusError),
}

/// Maps the windows `h` names, after checking again that they are the allowed ones.
pub fn map(h: &HardwareConfig) -> Result<Windows, MapError> {
    h.check().map_err(|e| MapError::Refused {
        key: e.key,
        message: e.message,
    })?;
    let registers = match &h.uio_device {
        // A UIO device's map 0 starts at file offset 0 and stands for the node's `reg`.
        Some(uio) => MappedWindow::open(uio, 0, h.register_size, h.register_base)?,
        None => MappedWindow::open(
            Path::new(DEV_MEM),
            h.register_base,
            h.register_size,
            h.register_base,
        )?,
    };
    let dma = map_dma(h, Path::new(UDMABUF_CLASS))?;
    Ok(Windows { registers, dma })
}

/// The frame buffer `h` names, u-dma-buf's class directory at `udmabuf_class` (tests stand
/// one in); `h` already checked.
fn map_dma(h: &HardwareConfig, udmabuf_class: &Path) -> Result<DmaWindow, MapError> {
    Ok(match &h.dma_device {
        Some(device) => {
            let name = device.file_name().ok_or_else(|| MapError::Refused {
                key: "dma_device",
                message: format!("{}: not a device file", device.display()),
            })?;
            let w = UdmabufWindow::open(device, &udmabuf_class.join(name))?;
            let (base, end) = (w.phys_base(), w.phys_base().checked_add(w.len_bytes()));
            if base < h.dma_base || end.is_none_or(|e| e > h.dma_base + h.dma_size) {
                return Err(MapError::Refused {
                    key: "dma_device",
                    message: format!(
                        "{}: its buffer {base:#x} + {:#x} is not inside dma_base {:#x} +                          dma_size {:#x}",
                        device.display(),
                        w.len_bytes(),
                        h.dma_base,
                        h.dma_size
                    ),
                });
            }
            DmaWindow::Cached(w)
        }
        None => DmaWindow::Uncached(MappedWindow::open(
            Path::new(DEV_MEM),
            h.dma_base,
            h.dma_size,
            h.dma_base,
        )?),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A u-dma-buf (files standing in for the device and its class directory) whose buffer
    /// sits at `phys`.
    fn fake_board(phys: u64) -> (tempfile::TempDir, HardwareConfig) {
        let dir = tempfile::tempdir().unwrap();
        let class = dir.path().join("class/udmabuf0");
        std::fs::create_dir_all(&class).unwrap();
        std::fs::write(class.join("phys_addr"), format!("{phys:#x}\n")).unwrap();
        std::fs::write(class.join("size"), "65536\n").unwrap();
        for f in ["sync_for_cpu", "sync_for_device"] {
            std::fs::write(class.join(f), "").unwrap();
        }
        let device = dir.path().join("udmabuf0");
        std::fs::write(&device, vec![0u8; 65536]).unwrap();
        let h = HardwareConfig {
            dma_device: Some(device),
            ..HardwareConfig::default()
        };
        (dir, h)
    }

    #[test]
    fn a_udmabuf_inside_the_region_is_mapped_cached() {
        let (dir, h) = fake_board(0x3800_0000);
        let mut dma = map_dma(&h, &dir.path().join("class")).unwrap();
        assert!(matches!(dma, DmaWindow::Cached(_)));
        assert_eq!(dma.phys_base(), 0x3800_0000);
        let mut buf = [0u8; 8];
        dma.read_bytes(64, &mut buf).unwrap();
        let cmd = std::fs::read_to_string(dir.path().join("class/udmabuf0/sync_for_cpu")).unwrap();
        assert_eq!(cmd, UdmabufWindow::sync_command(64, 8, 2));
    }

    #[test]
    fn a_udmabuf_outside_the_region_is_refused() {
        let (dir, h) = fake_board(0x2000_0000);
        match map_dma(&h, &dir.path().join("class")) {
            Err(MapError::Refused { key, message }) => {
                assert_eq!(key, "dma_device");
                assert!(message.contains("0x20000000"), "{message}");
            }
            other => panic!("{:?}", other.map(|_| ())),
        }
    }

    #[test]
    fn refuses_before_opening_anything() {
        let h = HardwareConfig {
            register_base: 0xC000_0000,
            ..HardwareConfig::default()
        };
        match map(&h) {
            Err(MapError::Refused { key, .. }) => assert_eq!(key, "register_base"),
            _ => panic!("the H2F window must be refused"),
        }
    }
}
