pub mod primitives;
pub mod radiance;
