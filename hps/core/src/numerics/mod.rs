//! The numerical tools every fit shares, each written once: small dense linear algebra,
//! one-dimensional minimisation and correlation. Physics modules call these; nothing here
//! knows about light.

pub mod linalg;
pub mod search;
pub mod stats;

pub use search::golden_section;
pub use stats::{pearson, Pearson};
