//! Helpers shared by the integration tests of this folder.

pub mod loop_harness;
