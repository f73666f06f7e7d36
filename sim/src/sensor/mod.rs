//! The image sensor as seen through its pixels: a luminance field imaged through the one
//! camera model (`skylux_hps::camera`) into Bayer samples, with the MT9P031's noise.

mod render;
pub mod spectral;

pub use render::{AnalogFrame, Footprint, FrameRenderer, Noise, SmallSource};
pub use spectral::{ChannelResponse, SpectralData};
