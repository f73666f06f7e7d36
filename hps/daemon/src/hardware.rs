//! The only physical memory skyluxd maps: the register window behind the lightweight
//! HPS-to-FPGA bridge (through `/dev/uioN`'s map 0, or `/dev/mem`) and the frame buffer in
//! the reserved DMA region (through `/dev/mem`). Both are opened with `O_SYNC` by
//! `MappedWindow`, so the register window is device memory and the buffer, which the kernel
//! never maps (`no-map`), is non-cached: the FPGA-to-SDRAM port is not cache-coherent and a
//! cached mapping would return stale frames (hardware-facts.md §3.2, §3.4).

use crate::config::HardwareConfig;
use skylux_bus::MappedWindow;
use std::path::Path;

/// `/dev/mem`.
pub const DEV_MEM: &str = "/dev/mem";

/// The two mapped windows.
pub struct Windows {
    pub registers: MappedWindow,
    pub dma: MappedWindow,
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
    let dma = MappedWindow::open(Path::new(DEV_MEM), h.dma_base, h.dma_size, h.dma_base)?;
    Ok(Windows { registers, dma })
}

#[cfg(test)]
mod tests {
    use super::*;

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
