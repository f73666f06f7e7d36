//! The daylighting engine: Monte-Carlo path tracing of workplane illuminance on a RADIANCE
//! scene, computing what `rtrace -I` computes (issue 5).
//!
//! One file per concept, as pbrt-v4: [`ray`], [`slab`] (the box test, the one operation the
//! FPGA takes over, behind [`slab::BoxTest`]), [`bvh`], [`shapes`], [`material`] (a folder,
//! one file per material family, asked by everything else what happens at a hit),
//! [`sampling`], [`sky`], [`world`] (the traceable scene), [`integrator`], [`radiance`] (one
//! camera ray), [`illuminance`] and [`render`] (pictures, written by [`crate::picture`]).
//!
//! ```no_run
//! use skylux_hps::{engine, scene};
//! let scene = scene::load_files(&["room/scene.rad", "sky.rad"])?;
//! let sensors = scene::load_sensors("room/sensors.pts")?;
//! let world = engine::World::new(&scene)?;
//! let settings = engine::Settings { ambient_bounces: 5, samples_per_sensor: 1024, ..Default::default() };
//! for s in engine::illuminance(&world, &sensors, &settings, &|_, _| {})? {
//!     println!("{},{:.1},{:.1}", s.name, s.illuminance_lux, s.stderr_lux);
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod accel;
pub mod antimatter;
pub mod bvh;
pub mod bvh_unit;
pub mod daylight_coefficients;
mod error;
pub mod function;
pub mod genbsdf;
pub mod illuminance;
pub mod integrator;
pub mod material;
pub mod openings;
pub mod phase;
pub mod portal;
pub mod qmc;
pub mod radiance;
pub mod ray;
pub mod render;
pub mod rng;
pub mod sampling;
pub mod shapes;
pub mod sky;
pub mod sky_sampling;
pub mod slab;
pub mod traversal_stats;
pub mod virtual_sources;
pub mod window_sun;
pub mod world;

pub use daylight_coefficients::{daylight_coefficients, sun_coefficients, DaylightCoefficients};
pub use error::EngineError;
pub use illuminance::{
    illuminance, lux_from_irradiance, SensorIlluminance, WHITE_EFFICACY_LM_PER_W,
};
pub use integrator::Settings;
pub use world::{Environment, World};
