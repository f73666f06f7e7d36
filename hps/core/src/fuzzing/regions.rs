//! Region files of `skylux compare`: polygons as JSON, or a RADIANCE mask picture.

use crate::compare::regions::{mask_regions, parse_polygons, rasterise};
use std::path::Path;

/// Measured picture size the regions are laid on.
const WIDTH_PX: u32 = 24;
const HEIGHT_PX: u32 = 16;

/// The first byte picks the reader (even: polygon JSON, odd: mask picture); the rest is
/// the file. Every region read covers the picture's pixels with known ids only.
pub(super) fn regions(bytes: &[u8]) {
    let Some((&pick, file)) = bytes.split_first() else {
        return;
    };
    let regions = if pick % 2 == 0 {
        match parse_polygons(&super::checks::text(file)) {
            Ok(polygons) => rasterise(&polygons, WIDTH_PX, HEIGHT_PX),
            Err(_) => return, // the caller adds the file's name (read_regions)
        }
    } else {
        match mask_regions(Path::new("fuzz.hdr"), file, WIDTH_PX, HEIGHT_PX) {
            Ok(r) => r,
            Err(e) => return super::checks::assert_names(&e.to_string(), "fuzz.hdr"),
        }
    };
    assert_eq!(regions.id_of_pixel.len(), (WIDTH_PX * HEIGHT_PX) as usize);
    for id in &regions.id_of_pixel {
        assert!(
            *id == 0 || regions.names.contains_key(id),
            "id {id} has no name"
        );
    }
}
