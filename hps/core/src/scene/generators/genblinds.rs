//! `genblinds mat name depth width height nslats angle [-r|+r rcurv]`: venetian blinds as
//! RADIANCE's genblinds.c builds them: `nslats` slats along z over `height`, each `depth`
//! deep along x and `width` wide along y, tilted by `angle` degrees, flat or curved (radius
//! `rcurv`, facets of at most 3°).

use super::args::{integer, number};
use super::text::polygon;
use std::f64::consts::PI;
use std::path::Path;

const USAGE: &str = "genblinds mat name depth width height nslats angle [-r|+r rcurv]";
/// Most facets per curved slat (genblinds' array size).
const MAX_FACETS: usize = 180;
/// Most slats generated, and most polygons (slats times facets).
const MAX_SLATS: i64 = 100_000;
const MAX_POLYGONS: usize = 1_000_000;
/// Largest angle one facet of a curved slat spans, degrees (genblinds' `DELTA`).
const FACET_DEG: f64 = 3.0;

pub(super) fn generate(args: &[String], _dir: &Path) -> Result<String, String> {
    if args.len() != 7 && args.len() != 9 {
        return Err(format!("{} argument(s) given; usage: {USAGE}", args.len()));
    }
    let (material, name) = (&args[0], &args[1]);
    let depth = number(args, 2, "depth")?;
    let width = number(args, 3, "width")?;
    let height = number(args, 4, "height")?;
    let slats = integer(args, 5, "nslats")?;
    let angle_deg = number(args, 6, "angle")?;
    if !(1..=MAX_SLATS).contains(&slats) {
        return Err(format!("nslats is {slats}; expected 1 to {MAX_SLATS}"));
    }
    let curvature = match args.get(7).map(String::as_str) {
        None => 0.0,
        Some("-r") => number(args, 8, "-r radius")?,
        Some("+r") => -number(args, 8, "+r radius")?,
        Some(other) => return Err(format!("unknown option `{other}`; usage: {USAGE}")),
    };
    let facets = if curvature == 0.0 {
        vec![flat(width, depth, angle_deg.to_radians())]
    } else {
        curved(width, depth, angle_deg, curvature)?
    };
    if facets.len().saturating_mul(slats as usize) > MAX_POLYGONS {
        return Err(format!(
            "{slats} slats of {} facets exceed {MAX_POLYGONS} polygons",
            facets.len()
        ));
    }
    let mut out = String::new();
    for n in 1..=slats {
        let lift = height * (n as f64 - 0.5) / slats as f64;
        for (k, facet) in facets.iter().enumerate() {
            let lifted = facet.map(|v| [v[0], v[1], v[2] + lift]);
            polygon(&mut out, material, &format!("{name}.{n}.{k}"), &lifted);
        }
    }
    Ok(out)
}

/// One flat facet `d` deep and `w` wide, tilted by `a` radians (`makeflat`).
fn flat(w: f64, d: f64, a: f64) -> [[f64; 3]; 4] {
    let (h, d) = (d * a.sin(), d * a.cos());
    [[0.0, 0.0, 0.0], [0.0, w, 0.0], [d, w, h], [d, 0.0, h]]
}

/// The facets of a slat curved with radius `r` (positive: curved up).
fn curved(w: f64, depth: f64, angle_deg: f64, r: f64) -> Result<Vec<[[f64; 3]; 4]>, String> {
    let ratio = depth / (2.0 * r.abs());
    if !(0.0..=1.0).contains(&ratio) {
        return Err(format!(
            "a slat {depth} deep cannot be curved with radius {}: expected depth <= 2 x radius",
            r.abs()
        ));
    }
    let theta = 2.0 * ratio.asin();
    let count = (theta / (FACET_DEG.to_radians()) + 0.99999) as usize;
    if count == 0 || count > MAX_FACETS {
        return Err(format!(
            "the slat needs {count} facets; expected 1 to {MAX_FACETS}"
        ));
    }
    let step_deg = theta.to_degrees() / count as f64;
    let step = step_deg.to_radians();
    let element = 2.0 * r.abs() * (step / 2.0).sin();
    let beta = (PI - theta) / 2.0;
    let gamma = beta - angle_deg.to_radians();
    let half_rest = ((180.0 - step_deg) / 2.0).to_radians();
    let anchor = if r < 0.0 {
        [-r.abs() * gamma.cos(), 0.0, r.abs() * gamma.sin()]
    } else {
        [
            r.abs() * (gamma + theta).cos(),
            0.0,
            -r.abs() * (gamma + theta).sin(),
        ]
    };
    let facets = (0..count)
        .map(|k| {
            let kd = k as f64 * step;
            let (chi, x) = if r < 0.0 {
                (
                    half_rest - (gamma + kd),
                    [
                        -r.abs() * (gamma + kd).cos(),
                        0.0,
                        r.abs() * (gamma + kd).sin(),
                    ],
                )
            } else {
                (
                    PI - (gamma + theta) + kd - half_rest,
                    [
                        r.abs() * (gamma + theta - kd).cos(),
                        0.0,
                        -r.abs() * (gamma + theta - kd).sin(),
                    ],
                )
            };
            let offset = [x[0] - anchor[0], 0.0, x[2] - anchor[2]];
            flat(w, element, chi).map(|v| [v[0] + offset[0], v[1] + offset[1], v[2] + offset[2]])
        })
        .collect();
    Ok(facets)
}
