pub mod radiance;
