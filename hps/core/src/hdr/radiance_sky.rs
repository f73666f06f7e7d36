//! The luminance map as a RADIANCE sky: an angular-fisheye picture of the upper hemisphere
//! (`sky.hdr`, RGBE), the function file that maps a direction into it (`skylux_sky.cal`), and
//! the description that makes it a `glow` sky (`sky.rad`), so that rtrace, rpict or any
//! RADIANCE tool sees the measured sky.
//!
//! Picture: zenith at the centre, north up, east left (the sky seen from below), the horizon
//! on the inscribed circle; the radius is proportional to the zenith angle (RADIANCE's
//! angular fisheye, `-vta`). Pixels hold radiance in RADIANCE units, luminance / 179
//! (WHTEFFICACY, `src/common/color.h`; hardware-facts.md §6), equal in R, G and B. RGBE as in
//! RADIANCE's `color.c` (`setcolr`): mantissas scaled by 256 / 2^e, exponent byte e + 128,
//! written flat (uncompressed scanlines are valid RADIANCE pictures).

use glam::DVec3;
use std::io::Write;
use std::path::Path;

use crate::photometry::WHITE_EFFICACY_LM_PER_W;

/// The function file: `sky_u`, `sky_v` of a direction (Dx, Dy, Dz) in the picture.
pub const CAL_FILE: &str = "{ skylux_sky.cal: the angular-fisheye sky picture written by skylux.
  Zenith at the centre, north up, east left (seen from below), horizon on the
  inscribed circle, radius proportional to the zenith angle. }
sky_rho = sqrt(Dx*Dx + Dy*Dy);
sky_r = acos(bound(-1, Dz, 1)) / PI;
sky_u = if(sky_rho - 1e-9, 0.5 - sky_r*Dx/sky_rho, 0.5);
sky_v = if(sky_rho - 1e-9, 0.5 + sky_r*Dy/sky_rho, 0.5);
";

/// The sky description using the picture and the function file (both beside it).
pub fn sky_description(picture: &str) -> String {
    format!(
        "# The measured sky as a glow source (written by skylux).\n\
         void colorpict skylux_map\n7 red green blue {picture} skylux_sky.cal sky_u sky_v\n0\n0\n\n\
         skylux_map glow skylux_glow\n0\n0\n4 1 1 1 0\n\n\
         skylux_glow source skylux_sky\n0\n0\n4 0 0 1 180\n"
    )
}

/// The world direction at the centre of picture pixel (i, j) of a `size` x `size` picture
/// (row j counted from the top), or `None` outside the horizon circle.
pub fn picture_direction(i: usize, j: usize, size: usize) -> Option<DVec3> {
    let u = (i as f64 + 0.5) / size as f64;
    let v = 1.0 - (j as f64 + 0.5) / size as f64;
    let (du, dv) = (u - 0.5, v - 0.5);
    let r = (du * du + dv * dv).sqrt();
    if r > 0.5 {
        return None;
    }
    let theta = r * std::f64::consts::PI;
    let (sin_phi, cos_phi) = if r > 0.0 {
        (-du / r, dv / r)
    } else {
        (0.0, 1.0)
    };
    Some(DVec3::new(
        theta.sin() * sin_phi,
        theta.sin() * cos_phi,
        theta.cos(),
    ))
}

fn rgbe(value: f64) -> [u8; 4] {
    if value.is_nan() || value <= 1e-32 {
        return [0; 4];
    }
    let e = value.log2().floor() as i32 + 1; // value = m 2^e with m in [0.5, 1)
    let m = (value * 256.0 / 2f64.powi(e)) as u8;
    [m, m, m, (e + 128).clamp(0, 255) as u8]
}

/// Writes `dir/sky.hdr` (a `size` x `size` angular fisheye), `dir/skylux_sky.cal` and
/// `dir/sky.rad`. `luminance_cd_m2` gives the sky luminance in a world direction of the upper
/// hemisphere (the measured map, filled where the lens did not see).
pub fn write_radiance_sky(
    dir: &Path,
    size: usize,
    luminance_cd_m2: &dyn Fn(DVec3) -> f64,
) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let mut out = std::io::BufWriter::new(std::fs::File::create(dir.join("sky.hdr"))?);
    write!(
        out,
        "#?RADIANCE\nSOFTWARE=skylux\nFORMAT=32-bit_rle_rgbe\n\n-Y {size} +X {size}\n"
    )?;
    for j in 0..size {
        for i in 0..size {
            let radiance = picture_direction(i, j, size)
                .map(|d| luminance_cd_m2(d) / WHITE_EFFICACY_LM_PER_W)
                .unwrap_or(0.0);
            out.write_all(&rgbe(radiance))?;
        }
    }
    out.flush()?;
    std::fs::write(dir.join("skylux_sky.cal"), CAL_FILE)?;
    std::fs::write(dir.join("sky.rad"), sky_description("sky.hdr"))
}
