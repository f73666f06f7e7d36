//! The luminance map as OpenEXR (campaign.md "Results written by skylux"): one pixel per 2x2
//! Bayer group in the raw frames' orientation, float32 channels `Y` (cd/m²) and `flags`
//! (0 valid, 1 over-range, 2 under-range), and the camera model in the header: the whole
//! `device.toml` as text (`skylux.device`) and the readout window (`skylux.readout`), which is
//! what maps every pixel to its direction and solid angle.

use super::{LuminanceMap, MapFlag};
use crate::camera::DeviceConfig;
use crate::campaign::Readout;
use exr::prelude::*;
use std::path::{Path, PathBuf};

/// Why a map could not be written or read.
#[derive(Debug, thiserror::Error)]
pub enum MapFileError {
    #[error("{path}: {message}")]
    Exr { path: PathBuf, message: String },
    #[error("{path}: {what}")]
    Invalid { path: PathBuf, what: String },
}

/// Header attribute holding `device.toml`.
pub const DEVICE_ATTRIBUTE: &str = "skylux.device";
/// Header attribute holding the readout window as `col_start row_start skip`.
pub const READOUT_ATTRIBUTE: &str = "skylux.readout";

/// Writes `map` with the camera model and readout in the header.
pub fn write_exr(
    path: &Path,
    map: &LuminanceMap,
    device: &DeviceConfig,
    readout: &Readout,
) -> std::result::Result<(), MapFileError> {
    let exr_error = |e: exr::error::Error| MapFileError::Exr {
        path: path.into(),
        message: e.to_string(),
    };
    let device_text = toml::to_string(device).map_err(|e| MapFileError::Invalid {
        path: path.into(),
        what: e.to_string(),
    })?;
    let flags: Vec<f32> = map.flags.iter().map(|f| *f as u8 as f32).collect();
    let channels = AnyChannels::sort(smallvec::smallvec![
        AnyChannel::new("Y", FlatSamples::F32(map.luminance_cd_m2.clone())),
        AnyChannel::new("flags", FlatSamples::F32(flags)),
    ]);
    let mut layer = Layer::new(
        (map.width, map.height),
        LayerAttributes::named("luminance"),
        Encoding::FAST_LOSSLESS,
        channels,
    );
    let text = |s: &str, what: &str| {
        Text::new_or_none(s).ok_or_else(|| MapFileError::Invalid {
            path: path.into(),
            what: format!("{what} is not representable as EXR text"),
        })
    };
    layer.attributes.other.insert(
        text(DEVICE_ATTRIBUTE, "name")?,
        AttributeValue::Text(text(&device_text, "device.toml")?),
    );
    // "col_start row_start skip", and the bin only when there is one (older readers and
    // files keep three numbers).
    let mut readout_text = format!(
        "{} {} {}",
        readout.col_start, readout.row_start, readout.skip
    );
    if readout.bin != 1 {
        readout_text.push_str(&format!(" {}", readout.bin));
    }
    layer.attributes.other.insert(
        text(READOUT_ATTRIBUTE, "name")?,
        AttributeValue::Text(text(&readout_text, "readout")?),
    );
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(exr_error)
}

/// Reads a map written by [`write_exr`], with its camera model and readout.
pub fn read_exr(
    path: &Path,
) -> std::result::Result<(LuminanceMap, DeviceConfig, Readout), MapFileError> {
    let file = std::fs::File::open(path).map_err(|e| MapFileError::Exr {
        path: path.into(),
        message: format!("cannot open: {e}"),
    })?;
    decode_exr(path, std::io::BufReader::new(file))
}

/// [`read_exr`] of a file's bytes in memory; `path` names it in errors.
pub fn parse_exr(
    path: &Path,
    bytes: &[u8],
) -> std::result::Result<(LuminanceMap, DeviceConfig, Readout), MapFileError> {
    decode_exr(path, std::io::Cursor::new(bytes))
}

fn decode_exr(
    path: &Path,
    mut source: impl std::io::Read + std::io::Seek,
) -> std::result::Result<(LuminanceMap, DeviceConfig, Readout), MapFileError> {
    let exr_error = |message: String| MapFileError::Exr {
        path: path.into(),
        message,
    };
    crate::picture::exr::check_declared_size(&mut source).map_err(exr_error)?;
    let invalid = |what: String| MapFileError::Invalid {
        path: path.into(),
        what,
    };
    let image = crate::picture::exr::read_first_layer(source).map_err(exr_error)?;
    let attribute = |name: &str| match image.layer_data.attributes.other.get(&Text::from(name)) {
        Some(AttributeValue::Text(t)) => Ok(t.to_string()),
        _ => Err(invalid(format!("header attribute {name} is missing"))),
    };
    let (device, _) = DeviceConfig::parse(&attribute(DEVICE_ATTRIBUTE)?, path)
        .map_err(|e| invalid(e.to_string()))?;
    let numbers: Vec<u32> = attribute(READOUT_ATTRIBUTE)?
        .split_whitespace()
        .filter_map(|s| s.parse().ok())
        .collect();
    let (col_start, row_start, skip, bin) = match numbers[..] {
        [c, r, s] => (c, r, s, 1),
        [c, r, s, b] => (c, r, s, b),
        _ => {
            return Err(invalid(format!(
                "{READOUT_ATTRIBUTE} must hold three or four whole numbers \
                 (col_start row_start skip [bin])"
            )))
        }
    };
    let layer = &image.layer_data;
    let (width, height) = (layer.size.width(), layer.size.height());
    let channel = |name: &str| -> std::result::Result<Vec<f32>, MapFileError> {
        let c = layer
            .channel_data
            .list
            .iter()
            .find(|c| c.name.to_string() == name)
            .ok_or_else(|| invalid(format!("channel {name} is missing")))?;
        Ok(c.sample_data.values_as_f32().collect())
    };
    let luminance_cd_m2 = channel("Y")?;
    let flags = channel("flags")?
        .into_iter()
        .map(|f| match f as u8 {
            0 => MapFlag::Valid,
            1 => MapFlag::OverRange,
            _ => MapFlag::UnderRange,
        })
        .collect();
    let n = luminance_cd_m2.len();
    let map = LuminanceMap {
        width,
        height,
        luminance_cd_m2,
        flags,
        relative_sigma: vec![f32::NAN; n],
    };
    Ok((
        map,
        device,
        Readout {
            col_start,
            row_start,
            skip,
            bin,
        },
    ))
}
