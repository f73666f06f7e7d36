//! The numerical tools every fit shares, each written once: small dense linear algebra,
//! one-dimensional minimisation and correlation, a stable hash. Physics modules call these; nothing here
//! knows about light.

pub mod fnv;
pub mod linalg;
pub mod search;
pub mod stats;

pub use search::golden_section;
pub use stats::{pearson, Pearson};
