//! Matrix (phase) methods, as RADIANCE's `rfluxmtx` and `dctimestep` build and multiply
//! them: the view matrix V (sensors to the window's Klems patches), the daylight matrix D
//! (the window's Klems patches to sky patches), T from the window's BSDF
//! ([`crate::bsdf::KlemsTransmission`]), and their product with a sky vector.
//!
//! - [`window`]: the window's polygons and Klems frame, exactly `rfluxmtx`'s (`h=kf u=...`),
//!   so our V and D index the patches as theirs and as the XML's T.
//! - [`view`]: V, our engine's sensor paths through the room, credited to the patch they
//!   leave through the window by.
//! - [`daylight`]: D, paths from the window out through the outside geometry to the sky.
//! - [`three_phase`]: V T D s, and a window state switch (one product per state).
//! - [`five_phase`]: the sun's direct part replaced by the sun at its actual direction
//!   through the window at full resolution.
//! - [`shading_states`]: a window declared with several states (each a BSDF), every state
//!   under every sky from the room's matrices traced once.
//! - [`shaded_room`]: such a room from its files, its matrices cached between runs.
//! - [`scene_sky`]: a scene's sky (gensky, gendaylit) as a sky vector and its suns.
//!
//! Matrices are [`RadianceMatrix`] values, written in RADIANCE's matrix format so that
//! `dctimestep` and `rmtxop` read them, and read from theirs.

pub mod daylight;
pub mod five_phase;
pub mod scene_sky;
pub mod shaded_room;
pub mod shading_states;
pub mod three_phase;
pub mod view;
pub mod window;

pub use crate::io::radiance_matrix::RadianceMatrix;
pub use daylight::daylight_matrix;
pub use five_phase::{five_phase, sky_vector_from_luminance, sun_sky_vector, PhaseMatrices};
pub use scene_sky::{sky_vector_of_world, SunBeam};
pub use shaded_room::{ShadedRoom, ShadedRoomError, ShadedRoomFiles, ShadedRoomSettings};
pub use shading_states::{remove_glazing, ShadedWindow, ShadingState, StateMatrices, SunView};
pub use three_phase::{three_phase, WindowStates};
pub use view::{view_matrices, view_matrix};
pub use window::{KlemsWindow, WindowError};

/// Paths per random stream (as in `illuminance`, so results do not depend on thread count).
const BATCH_SAMPLES: u32 = 64;
