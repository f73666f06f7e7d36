pub mod compare;
pub mod primitives;
pub mod radiance;
