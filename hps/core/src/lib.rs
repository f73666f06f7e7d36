//! The HPS side of Skylux: drivers for the fabric (over `skylux-bus`), and from later issues
//! HDR synthesis, the sky, the sun and the daylighting engine.

pub mod bsdf;
pub mod cal;
pub mod calibration;
pub mod camera;
pub mod campaign;
pub mod compare;
pub mod engine;
pub mod fpga;
pub mod fuzzing;
pub mod glare;
pub mod hdr;
pub mod io;
pub mod model;
pub mod numerics;
pub mod output;
pub mod photometry;
pub mod picture;
pub mod prerequisite;
pub mod scene;
pub mod sky;
pub mod sun;
pub mod timing;
pub mod toml_file;
pub mod validation;
