//! `genworm material name 'x(t)' 'y(t)' 'z(t)' 'r(t)' nseg [-e expr] [-f file]`: a worm, a
//! string of varying thickness, as RADIANCE's genworm.c writes it: a sphere at each of the
//! `nseg + 1` points of t from 0 to 1, joined by a cylinder where the radius stays and by a
//! cone tangent to both spheres where it changes.

use super::functions::Functions;
use super::text::reals_primitive;
use glam::DVec3;
use std::path::Path;

const USAGE: &str = "genworm material name x(t) y(t) z(t) r(t) nseg [-e expr] [-f file]";
/// Most segments generated.
const MAX_SEGMENTS: usize = 100_000;
/// RADIANCE's `FTINY`: radii closer than this make a cylinder.
const TINY: f64 = 1e-6;
const NAMES: [&str; 4] = ["X`SYS`", "Y`SYS`", "Z`SYS`", "R`SYS`"];

pub(super) fn generate(args: &[String], dir: &Path) -> Result<String, String> {
    if args.len() < 7 {
        return Err(format!("{} argument(s) given; usage: {USAGE}", args.len()));
    }
    let mut functions = Functions::new();
    functions.options(&args[7..], dir, &[], USAGE)?;
    let (material, name) = (&args[0], &args[1]);
    for (k, what) in ["x(t)", "y(t)", "z(t)", "r(t)"].iter().enumerate() {
        functions.define(NAMES[k], "t", &args[2 + k], what)?;
    }
    let n = functions.count(&args[6], "nseg", MAX_SEGMENTS)?;
    let mut out = String::new();
    let mut last: Option<(DVec3, f64)> = None;
    for i in 0..=n {
        let t = [i as f64 / n as f64];
        let v = |k: usize| functions.value(NAMES[k], &t, ["x(t)", "y(t)", "z(t)", "r(t)"][k]);
        let (p, r) = (DVec3::new(v(0)?, v(1)?, v(2)?), v(3)?);
        if let Some((last_p, last_r)) = last {
            let id = format!("{name}.c{i}");
            if (last_r - r).abs() <= TINY {
                let reals = [last_p.x, last_p.y, last_p.z, p.x, p.y, p.z, r];
                reals_primitive(&mut out, material, "cylinder", &id, &reals);
            } else {
                // The cone tangent to both spheres: its ends move along the axis by the
                // radius times (r0 - r1) / |p1 - p0|², and its radii shrink by the cosine of
                // its half-angle.
                let axis = p - last_p;
                let f = (last_r - r) / axis.length_squared();
                let (a, b) = (last_p + f * last_r * axis, p + f * r * axis);
                let c = 1.0 - (last_r - r) * f;
                let c = if c <= 0.0 { 0.0 } else { c.sqrt() };
                let reals = [a.x, a.y, a.z, b.x, b.y, b.z, c * last_r, c * r];
                if reals.iter().any(|x| !x.is_finite()) {
                    return Err(format!(
                        "points {} and {i} coincide with different radii: no cone joins them",
                        i - 1
                    ));
                }
                reals_primitive(&mut out, material, "cone", &id, &reals);
            }
        }
        reals_primitive(
            &mut out,
            material,
            "sphere",
            &format!("{name}.s{i}"),
            &[p.x, p.y, p.z, r],
        );
        last = Some((p, r));
    }
    Ok(out)
}
