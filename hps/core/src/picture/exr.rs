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

/// An OpenEXR picture's luminance and view, as [`write_exr`] writes them.
#[derive(Clone, Debug, PartialEq)]
pub struct ExrLuminance {
    pub width_px: u32,
    pub height_px: u32,
    /// The `skylux.view` header attribute (RADIANCE view options), if any.
    pub view: Option<String>,
    /// The `Y` channel, cd/m², rows from the top.
    pub luminance_cd_m2: Vec<f64>,
}

/// Reads the `Y` channel (luminance, cd/m²) and the `skylux.view` attribute of an OpenEXR
/// file's first layer.
pub fn read_exr_luminance(path: &Path) -> Result<ExrLuminance, super::rgbe::PictureReadError> {
    let file = std::fs::File::open(path).map_err(|e| super::rgbe::PictureReadError {
        path: path.into(),
        message: format!("cannot open: {e}"),
    })?;
    decode_exr_luminance(path, std::io::BufReader::new(file))
}

/// [`read_exr_luminance`] of a file's bytes in memory; `path` names it in errors.
pub fn parse_exr_luminance(
    path: &Path,
    bytes: &[u8],
) -> Result<ExrLuminance, super::rgbe::PictureReadError> {
    decode_exr_luminance(path, std::io::Cursor::new(bytes))
}

fn decode_exr_luminance(
    path: &Path,
    mut source: impl std::io::Read + std::io::Seek,
) -> Result<ExrLuminance, super::rgbe::PictureReadError> {
    use exr::prelude::*;
    let fail = |message: String| super::rgbe::PictureReadError {
        path: path.into(),
        message,
    };
    check_declared_size(&mut source)
        .map_err(|e| fail(format!("not a readable OpenEXR file: {e}")))?;
    let image =
        read_first_layer(source).map_err(|e| fail(format!("not a readable OpenEXR file: {e}")))?;
    let layer = image.layer_data;
    let (w, h) = (layer.size.width(), layer.size.height());
    if (w as u64) * (h as u64) > super::rgbe::MAX_READ_PIXELS {
        return Err(fail(format!(
            "{w} × {h} pixels is more than this reader accepts"
        )));
    }
    let y = layer
        .channel_data
        .list
        .iter()
        .find(|c| c.name.eq("Y"))
        .ok_or_else(|| {
            fail("no `Y` channel (luminance, cd/m², as skylux render writes it)".into())
        })?;
    let luminance_cd_m2: Vec<f64> = y.sample_data.values_as_f32().map(f64::from).collect();
    let view = layer
        .attributes
        .other
        .iter()
        .find(|(name, _)| (*name).eq("skylux.view"))
        .and_then(|(_, value)| match value {
            AttributeValue::Text(t) => Some(t.to_string()),
            _ => None,
        });
    Ok(ExrLuminance {
        width_px: w as u32,
        height_px: h as u32,
        view,
        luminance_cd_m2,
    })
}

/// Reads the headers of the OpenEXR data in `source`, refuses a layer larger than
/// [`super::rgbe::MAX_READ_PIXELS`] before anything is decoded, and rewinds `source` for the
/// decoder. The exr crate allocates what a header declares, so a few bytes could otherwise
/// ask for gigabytes (the fuzzer's `exr` finding of 2026-11-27: 34 GB, an abort).
/// The first valid layer of an OpenEXR file, every channel and attribute, at its largest
/// resolution. The exr crate asserts on some malformed blocks instead of returning an error
/// (the fuzzer's third finding, 2026-11-27: `line should have been filtered` on a tile whose
/// coordinates disagree with its header, fuzz/regressions/exr): its panic is caught here and
/// becomes an error, so no file stops the daemon or a tool.
pub fn read_first_layer(
    source: impl std::io::Read + std::io::Seek,
) -> Result<
    exr::image::Image<exr::image::Layer<exr::image::AnyChannels<exr::image::FlatSamples>>>,
    String,
> {
    use exr::prelude::*;
    let decoded = std::panic::catch_unwind(std::panic::AssertUnwindSafe(move || {
        read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .first_valid_layer()
            .all_attributes()
            // Decoded on this thread: a panic on the crate's own decoding threads would abort
            // the process, out of this catch_unwind's reach.
            .non_parallel()
            .from_buffered(source)
    }));
    match decoded {
        Ok(result) => result.map_err(|e| e.to_string()),
        Err(panic) => Err(format!(
            "the file's blocks contradict its header (the exr decoder failed: {})",
            panic
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| panic.downcast_ref::<&str>().copied())
                .unwrap_or("a panic")
        )),
    }
}

pub fn check_declared_size(
    source: &mut (impl std::io::Read + std::io::Seek),
) -> Result<(), String> {
    let meta =
        exr::meta::MetaData::read_from_buffered(&mut *source, false).map_err(|e| e.to_string())?;
    for header in meta.headers.iter() {
        let (w, h) = (header.layer_size.width(), header.layer_size.height());
        let pixels = (w as u64).saturating_mul(h as u64);
        if pixels > super::rgbe::MAX_READ_PIXELS {
            return Err(format!(
                "a layer of {w} × {h} pixels is more than this reader accepts ({} pixels)",
                super::rgbe::MAX_READ_PIXELS
            ));
        }
        // The exr crate allocates a whole tile per block, whatever the layer's size: a 3 KB
        // file declaring 64 x 4,194,368-pixel tiles over an 8 x 8 image took 1.8 GB and 1.7 s
        // (the fuzzer's finding, fuzz/regressions/exr). A tile has no reason to hold more
        // pixels than its layer (or than a 64 x 64 tile, the format's usual size).
        if let exr::meta::BlockDescription::Tiles(t) = &header.blocks {
            let (tw, th) = (t.tile_size.width(), t.tile_size.height());
            let tile_pixels = (tw as u64).saturating_mul(th as u64);
            if tile_pixels > pixels.max(64 * 64) {
                return Err(format!(
                    "tiles of {tw} × {th} pixels over a layer of {w} × {h}: larger than the \
                     image itself"
                ));
            }
        }
    }
    source
        .seek(std::io::SeekFrom::Start(0))
        .map_err(|e| e.to_string())?;
    Ok(())
}
