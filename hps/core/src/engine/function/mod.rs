//! Function modifiers in the engine: the `.cal` programs (and data files) that
//! `brightfunc`, `colorfunc`, `brightdata`, `colordata`, `texfunc`, `texdata`, `mixfunc`,
//! `mixdata`, `BRTDfunc`, the function materials (`plasfunc` .. `transdata`) and the
//! anisotropic ones (`plastic2`, `metal2`, `trans2`) name, compiled once per file
//! ([`loader`]), evaluated at each hit with the ray variables RADIANCE defines ([`ray`],
//! `src/rt/func.c`), and the materials they make ([`varying`]); and the text patterns
//! (`brighttext`, `colortext`, `mixtext`: [`text`], in a font read by [`font`]).
//!
//! A run-time evaluation error (a division by zero, a domain error) gives 0 for that
//! expression, as calcomp does, and is counted in [`CompiledFunction::warnings`];
//! RADIANCE prints a warning and goes on (for a pattern it leaves the colour unchanged
//! on a domain error: `p_func.c`).

pub mod build;
pub mod data;
pub mod font;
pub mod loader;
pub mod ray;
pub mod text;
pub mod varying;

pub use build::material_of;
pub use loader::{CompiledFunction, FunctionLoader};
pub use ray::{FunctionRay, Perturbed};
pub use varying::VaryingMaterial;
