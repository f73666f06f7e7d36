//! RADIANCE pictures (`.hdr`): RGBE pixels under a header with the view.

use super::{output_error, OutputError, Picture};
use glam::DVec3;
use std::path::Path;

/// RADIANCE's RGBE encoding of one colour (color.c `setcolr`): a shared exponent and three
/// 8-bit mantissas, 0 for values below 1e-32.
pub fn rgbe(c: DVec3) -> [u8; 4] {
    let c = c.max(DVec3::ZERO);
    let d = c.max_element();
    if d.is_nan() || d <= 1e-32 {
        return [0; 4];
    }
    if !d.is_finite() {
        return [255, 255, 255, 255];
    }
    // frexp: d = m 2^e with m in [0.5, 1).
    let mut e = d.log2().floor() as i32 + 1;
    let mut m = d / 2f64.powi(e);
    if m >= 1.0 {
        m /= 2.0;
        e += 1;
    } else if m < 0.5 {
        m *= 2.0;
        e -= 1;
    }
    if e + 128 > 255 {
        return [255, 255, 255, 255];
    }
    if e + 128 < 0 {
        return [0; 4];
    }
    let scale = m * 256.0 / d;
    [
        (c.x * scale) as u8,
        (c.y * scale) as u8,
        (c.z * scale) as u8,
        (e + 128) as u8,
    ]
}

/// Writes the image as a RADIANCE picture: a header with the view (`VIEW=`), `EXPOSURE=` if
/// `exposure` is given (the factor by which the values were multiplied; they are written
/// unscaled here and the line only documents the factor) and `FORMAT=32-bit_rle_rgbe`, the
/// standard resolution line `-Y height +X width`, then flat RGBE scanlines from the top
/// (which every RADIANCE reader accepts).
pub fn write_hdr(path: &Path, image: &Picture, exposure: Option<f64>) -> Result<(), OutputError> {
    let mut out = Vec::with_capacity(image.radiance_rgb.len() * 4 + 256);
    out.extend_from_slice(b"#?RADIANCE\n");
    out.extend_from_slice(
        format!("SOFTWARE= skylux {} render\n", env!("CARGO_PKG_VERSION")).as_bytes(),
    );
    out.extend_from_slice(
        format!("SAMPLES= {} paths per pixel\n", image.samples_per_pixel).as_bytes(),
    );
    out.extend_from_slice(format!("VIEW= {}\n", image.view).as_bytes());
    if let Some(e) = exposure {
        out.extend_from_slice(format!("EXPOSURE={e:e}\n").as_bytes());
    }
    out.extend_from_slice(b"FORMAT=32-bit_rle_rgbe\n\n");
    out.extend_from_slice(format!("-Y {} +X {}\n", image.height_px, image.width_px).as_bytes());
    for c in &image.radiance_rgb {
        out.extend_from_slice(&rgbe(*c));
    }
    std::fs::write(path, out).map_err(|e| output_error(path, e))
}
