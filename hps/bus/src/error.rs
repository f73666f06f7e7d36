use std::path::PathBuf;

/// Why an access to the fabric failed. Every variant names what was accessed.
#[derive(Debug, thiserror::Error)]
pub enum BusError {
    #[error("access of {len} bytes at offset {offset:#x} is outside the {size:#x}-byte window")]
    OutOfBounds { offset: u64, len: u64, size: u64 },
    #[error("offset {offset:#x} is not {align}-byte aligned")]
    Unaligned { offset: u64, align: u64 },
    #[error("{path}: {what}: {source}")]
    Io {
        path: PathBuf,
        what: &'static str,
        source: std::io::Error,
    },
    #[error("{path}: the file holds {actual:#x} bytes from offset {base:#x}, {wanted:#x} needed")]
    FileTooShort {
        path: PathBuf,
        base: u64,
        wanted: u64,
        actual: u64,
    },
    #[error("mapping of {size:#x} bytes does not fit this target's address space")]
    TooLarge { size: u64 },
    #[error("register {name}: index {index} is out of range (the array has {count})")]
    NoSuchElement {
        name: &'static str,
        index: u32,
        count: u32,
    },
    #[error("simulated fabric: {0}")]
    Simulation(String),
}
