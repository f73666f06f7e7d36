//! Regions of the measured picture compared on their own: a mask picture (each pixel's
//! value, rounded, is its region id; 0 is no region) or polygons in pixel coordinates from a
//! JSON file.

use super::error::CompareError;
use crate::picture::rgbe;
use std::collections::BTreeMap;
use std::path::Path;

/// Largest region id a mask may hold (ids are names, not quantities).
const MAX_REGION_ID: f64 = 65_535.0;
/// Most polygon corners read from a file (a bound on work).
const MAX_CORNERS: usize = 100_000;

/// Region id per measured pixel (0: none) and each id's name.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Regions {
    pub id_of_pixel: Vec<u32>,
    pub names: BTreeMap<u32, String>,
}

/// A polygon region as the JSON file gives it: `[{"name": "window", "polygon": [[x, y],
/// ...]}, ...]`, x from the left and y from the top edge, in pixels (pixel centres at .5).
#[derive(Clone, Debug, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolygonRegion {
    pub name: String,
    pub polygon: Vec<[f64; 2]>,
}

/// Reads a region file for a `width` × `height` measured picture: `.json` polygons, else a
/// RADIANCE mask picture of the same size (the red channel's value is the id).
pub fn read_regions(path: &Path, width: u32, height: u32) -> Result<Regions, CompareError> {
    let is_json = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    if is_json {
        let text = std::fs::read_to_string(path).map_err(|e| region_error(path, e))?;
        let polygons = parse_polygons(&text).map_err(|m| region_error(path, m))?;
        Ok(rasterise(&polygons, width, height))
    } else {
        let bytes = std::fs::read(path).map_err(|e| region_error(path, e))?;
        mask_regions(path, &bytes, width, height)
    }
}

fn region_error(path: &Path, message: impl ToString) -> CompareError {
    CompareError::Regions {
        path: path.into(),
        message: message.to_string(),
    }
}

/// Parses and checks the polygon JSON (names, at least 3 finite corners each).
pub fn parse_polygons(text: &str) -> Result<Vec<PolygonRegion>, String> {
    let polygons: Vec<PolygonRegion> = serde_json::from_str(text).map_err(|e| {
        format!("not a polygon list ([{{\"name\": ..., \"polygon\": [[x, y], ...]}}]): {e}")
    })?;
    let corners: usize = polygons.iter().map(|p| p.polygon.len()).sum();
    if corners > MAX_CORNERS {
        return Err(format!("{corners} corners: at most {MAX_CORNERS}"));
    }
    for (k, p) in polygons.iter().enumerate() {
        if p.polygon.len() < 3 {
            return Err(format!(
                "region {} (`{}`) has {} corners: a polygon needs 3",
                k + 1,
                p.name,
                p.polygon.len()
            ));
        }
        if p.polygon.iter().flatten().any(|v| !v.is_finite()) {
            return Err(format!(
                "region {} (`{}`) has a corner that is not a finite number",
                k + 1,
                p.name
            ));
        }
    }
    Ok(polygons)
}

/// Region ids (1, 2, ... in file order) of the pixels whose centre lies in each polygon
/// (even-odd rule); a later polygon wins where they overlap.
pub fn rasterise(polygons: &[PolygonRegion], width: u32, height: u32) -> Regions {
    let (w, h) = (width as usize, height as usize);
    let mut id_of_pixel = vec![0u32; w * h];
    let mut names = BTreeMap::new();
    for (k, p) in polygons.iter().enumerate() {
        let id = k as u32 + 1;
        names.insert(id, p.name.clone());
        let (x_lo, x_hi, y_lo, y_hi) = bounds(&p.polygon, w, h);
        for row in y_lo..y_hi {
            for column in x_lo..x_hi {
                if contains(&p.polygon, column as f64 + 0.5, row as f64 + 0.5) {
                    id_of_pixel[row * w + column] = id;
                }
            }
        }
    }
    Regions { id_of_pixel, names }
}

/// The pixel range a polygon can cover, clamped to the picture.
fn bounds(polygon: &[[f64; 2]], w: usize, h: usize) -> (usize, usize, usize, usize) {
    let clamp = |v: f64, n: usize| v.clamp(0.0, n as f64) as usize;
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &[x, y] in polygon {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    (
        clamp(x0.floor(), w),
        clamp(x1.ceil(), w),
        clamp(y0.floor(), h),
        clamp(y1.ceil(), h),
    )
}

/// Even-odd point-in-polygon test (crossings of a ray towards +x).
fn contains(polygon: &[[f64; 2]], x: f64, y: f64) -> bool {
    let mut inside = false;
    let mut previous = polygon[polygon.len() - 1];
    for &corner in polygon {
        let ([xi, yi], [xj, yj]) = (corner, previous);
        if (yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi {
            inside = !inside;
        }
        previous = corner;
    }
    inside
}

/// Region ids from a mask picture of the measured picture's size.
pub fn mask_regions(
    path: &Path,
    bytes: &[u8],
    width: u32,
    height: u32,
) -> Result<Regions, CompareError> {
    let mask = rgbe::parse_hdr(path, bytes).map_err(|e| region_error(path, e))?;
    if (mask.width_px, mask.height_px) != (width, height) {
        return Err(region_error(
            path,
            format!(
                "the mask is {} × {} pixels, the measured picture {width} × {height}",
                mask.width_px, mask.height_px
            ),
        ));
    }
    let mut id_of_pixel = Vec::with_capacity(mask.pixels.len());
    for (i, &[red, _, _]) in mask.pixels.iter().enumerate() {
        let v = f64::from(red).round();
        if !(0.0..=MAX_REGION_ID).contains(&v) {
            let w = width as usize;
            return Err(region_error(
                path,
                format!(
                    "pixel (column {}, row {}) holds {red}: a region id is 0 to {MAX_REGION_ID}",
                    i % w,
                    i / w
                ),
            ));
        }
        id_of_pixel.push(v as u32);
    }
    let names = id_of_pixel
        .iter()
        .filter(|&&id| id > 0)
        .map(|&id| (id, format!("region {id}")))
        .collect();
    Ok(Regions { id_of_pixel, names })
}
