//! Shared helpers of the end-to-end tests.

use skylux_bus::MappedWindow;
use skylux_regmap::{reset_image, LW_BRIDGE_PHYS_BASE, LW_BRIDGE_SPAN_BYTES};
use std::io::Write;

/// A file laid out like the register window of a freshly configured device (every register at
/// its reset value, little-endian as the ARM sees it), mapped with the production backend.
pub fn register_window_file() -> (tempfile::NamedTempFile, MappedWindow) {
    let mut bytes = vec![0u8; LW_BRIDGE_SPAN_BYTES as usize];
    for (offset, value) in reset_image() {
        bytes[offset as usize..offset as usize + 4].copy_from_slice(&value.to_le_bytes());
    }
    let mut file = tempfile::NamedTempFile::new().unwrap();
    file.write_all(&bytes).unwrap();
    file.flush().unwrap();
    let window = MappedWindow::open(
        file.path(),
        0,
        LW_BRIDGE_SPAN_BYTES as u64,
        LW_BRIDGE_PHYS_BASE as u64,
    )
    .unwrap();
    (file, window)
}
