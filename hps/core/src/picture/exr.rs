//! OpenEXR pictures.

use super::{output_error, OutputError, Picture};
use std::path::Path;

/// Writes the image as OpenEXR: float32 channels `R`, `G`, `B` (radiance, W/sr/m²) and `Y`
/// (luminance, cd/m²), and the view in the header attribute `skylux.view` (RADIANCE's syntax).
pub fn write_exr(path: &Path, image: &Picture) -> Result<(), OutputError> {
    use exr::prelude::*;
    let channel = |f: &dyn Fn(usize) -> f64| -> Vec<f32> {
        (0..image.radiance_rgb.len()).map(|i| f(i) as f32).collect()
    };
    let channels = AnyChannels::sort(smallvec::smallvec![
        AnyChannel::new("R", FlatSamples::F32(channel(&|i| image.radiance_rgb[i].x))),
        AnyChannel::new("G", FlatSamples::F32(channel(&|i| image.radiance_rgb[i].y))),
        AnyChannel::new("B", FlatSamples::F32(channel(&|i| image.radiance_rgb[i].z))),
        AnyChannel::new(
            "Y",
            FlatSamples::F32(channel(&|i| image.luminance_cd_m2[i]))
        ),
    ]);
    let mut layer = Layer::new(
        (image.width_px as usize, image.height_px as usize),
        LayerAttributes::named("render"),
        Encoding::FAST_LOSSLESS,
        channels,
    );
    if let (Some(name), Some(value)) = (
        Text::new_or_none("skylux.view"),
        Text::new_or_none(&image.view),
    ) {
        layer
            .attributes
            .other
            .insert(name, AttributeValue::Text(value));
    }
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(|e| output_error(path, e))
}
