//! The world the Skylux device lives in, modelled so the whole device runs on a laptop bit for
//! bit as the hardware would: the bus models around the fabric now; the sensor, lens, sky and
//! SDRAM models as the issues that need them land.
//!
//! `sim/` holds models only, never product logic: the product is `rtl/` and `hps/`.

pub mod analysis;
pub mod battery;
pub mod bus;
pub mod campaign;
pub mod capture;
pub mod capture_path;
pub mod core_rig;
pub mod dc_case;
pub mod fabric_model;
pub mod hdr_case;
pub mod mt9p031;
pub mod pixel_bus;
pub mod radiance_tools;
pub mod radiance_truth;
pub mod raybox;
pub mod sensor;
pub mod sky;
pub mod sky_colour;

pub use bus::{AvalonHost, RegisterFileModel, SimRegisterBus};
