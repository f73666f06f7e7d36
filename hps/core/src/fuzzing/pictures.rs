//! Pictures: OpenEXR (a luminance map with its camera model, or a rendered view's `Y`) and
//! RADIANCE RGBE (`.hdr`), as the tools read them.

use crate::hdr::parse_exr;
use crate::picture::exr::parse_exr_luminance;
use crate::picture::rgbe::parse_hdr;
use std::path::Path;

/// Both OpenEXR readers on the same bytes: the map reader and the luminance reader.
pub(super) fn exr(bytes: &[u8]) {
    let path = Path::new("fuzz.exr");
    match parse_exr(path, bytes) {
        Ok((map, _, _)) => {
            let pixels = map.width * map.height;
            assert!(map.luminance_cd_m2.len() == pixels && map.flags.len() == pixels);
        }
        Err(e) => super::checks::assert_names(&e.to_string(), "fuzz.exr"),
    }
    match parse_exr_luminance(path, bytes) {
        Ok(p) => assert_eq!(
            p.luminance_cd_m2.len() as u64,
            p.width_px as u64 * p.height_px as u64
        ),
        Err(e) => super::checks::assert_names(&e.to_string(), "fuzz.exr"),
    }
}

pub(super) fn rgbe(bytes: &[u8]) {
    match parse_hdr(Path::new("fuzz.hdr"), bytes) {
        Ok(p) => assert_eq!(
            p.pixels.len() as u64,
            p.width_px as u64 * p.height_px as u64
        ),
        Err(e) => super::checks::assert_names(&e.to_string(), "fuzz.hdr"),
    }
}
