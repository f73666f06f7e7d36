//! The memory-mapped backend over ordinary files: bounds, alignment, offsets, DMA access.
//! These run on armv7 under qemu too, where `usize` is 32 bits.

use proptest::prelude::*;
use skylux_bus::{check_access, BusError, DmaMemory, MappedWindow, RegisterBus};
use std::io::Write;

fn file_of(len: usize, fill: impl Fn(usize) -> u8) -> tempfile::NamedTempFile {
    let mut f = tempfile::NamedTempFile::new().unwrap();
    f.write_all(&(0..len).map(fill).collect::<Vec<_>>())
        .unwrap();
    f.flush().unwrap();
    f
}

#[test]
fn registers_are_little_endian_words_at_the_right_offset() {
    let f = file_of(3 * 4096, |i| i as u8);
    // A window that starts one page into the file, standing for a physical base.
    let mut w = MappedWindow::open(f.path(), 4096, 4096, 0xFF20_0000).unwrap();
    assert_eq!(w.read32(0).unwrap(), u32::from_le_bytes([0, 1, 2, 3]));
    assert_eq!(w.read32(8).unwrap(), u32::from_le_bytes([8, 9, 10, 11]));
    w.write32(4092, 0xCAFE_F00D).unwrap();
    assert_eq!(w.read32(4092).unwrap(), 0xCAFE_F00D);
    drop(w);
    let bytes = std::fs::read(f.path()).unwrap();
    assert_eq!(&bytes[8188..8192], &0xCAFE_F00Du32.to_le_bytes());
    assert_eq!(bytes[8192], 0, "nothing written past the window");
}

#[test]
fn out_of_bounds_and_unaligned_accesses_are_refused() {
    let f = file_of(4096, |_| 0);
    let mut w = MappedWindow::open(f.path(), 0, 4096, 0).unwrap();
    assert!(matches!(w.read32(4096), Err(BusError::OutOfBounds { .. })));
    assert!(matches!(
        w.write32(4094, 1),
        Err(BusError::Unaligned { .. })
    ));
    assert!(matches!(
        w.read32(u32::MAX - 3),
        Err(BusError::OutOfBounds { .. })
    ));
    let mut buf = [0u8; 16];
    assert!(matches!(
        w.read_bytes(4090, &mut buf),
        Err(BusError::OutOfBounds { .. })
    ));
    assert!(matches!(
        w.read_bytes(u64::MAX - 4, &mut buf),
        Err(BusError::OutOfBounds { .. })
    ));
}

#[test]
fn a_short_or_missing_file_is_a_clear_error() {
    let f = file_of(1000, |_| 0);
    let e = MappedWindow::open(f.path(), 0, 4096, 0).unwrap_err();
    assert!(matches!(e, BusError::FileTooShort { .. }));
    assert!(
        e.to_string().contains(&f.path().display().to_string()),
        "{e}"
    );
    let e =
        MappedWindow::open(std::path::Path::new("/nonexistent/skylux"), 0, 4096, 0).unwrap_err();
    assert!(
        e.to_string().contains("/nonexistent/skylux") && e.to_string().contains("cannot open"),
        "{e}"
    );
}

#[test]
fn dma_buffer_bytes_round_trip() {
    let f = file_of(64 * 1024, |_| 0);
    let mut w = MappedWindow::open(f.path(), 0, 64 * 1024, 0x3000_0000).unwrap();
    assert_eq!((w.phys_base(), w.len_bytes()), (0x3000_0000, 64 * 1024));
    let frame: Vec<u8> = (0..5000).map(|i| (i * 7) as u8).collect();
    w.write_bytes(1234, &frame).unwrap();
    let mut back = vec![0u8; frame.len()];
    w.read_bytes(1234, &mut back).unwrap();
    assert_eq!(back, frame);
}

proptest! {
    /// The bounds check never overflows and agrees with exact (128-bit) arithmetic.
    #[test]
    fn check_access_is_exact(offset in any::<u64>(), len in any::<u64>(), size in any::<u64>()) {
        let fits = (offset as u128 + len as u128) <= size as u128;
        prop_assert_eq!(check_access(offset, len, size, 1).is_ok(), fits);
    }
}
