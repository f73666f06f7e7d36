//! Closing the loop with measured data: compare the model with reference instruments, find
//! the residual, trace it to a missing effect, add it, and report before and after on
//! held-out data.

pub mod closure;
pub mod diagnostics;
pub mod effects;
pub mod frame_evidence;
pub mod glazing;
pub mod illuminance_loop;
pub mod loop_figures;
pub mod perez_baseline;
pub mod prediction;
pub mod report;
pub mod sample;
pub mod scoring;
pub mod sky_colour;
pub mod sky_geometry;
pub mod split;
pub mod terms;
