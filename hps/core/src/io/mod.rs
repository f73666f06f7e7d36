//! Readers and writers of external records. Parsing lives here, apart from the physics that
//! uses the values (the sun, the sky models).

pub mod irradiance;
pub mod radiance_matrix;
