//! Files the product writes for people and other programs: atomic, durable file writes and
//! PNG plots. Every module that writes a report, a table or a figure comes here, so how a file
//! reaches the disk and how a plot is drawn are each written once.

pub mod atomic;
pub mod plot;

pub use atomic::{fsync_dir, fsync_file, tmp_name, write_atomic, write_atomic_with, WriteError};
