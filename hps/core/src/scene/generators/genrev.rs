//! `genrev material name 'z(t)' 'r(t)' nseg`: a surface of revolution about z, as RADIANCE's
//! genrev.c writes it: for each of `nseg` steps of t from 0 to 1, a cylinder (or tube), ring,
//! or cone (or cup) between consecutive (z, r). The expressions are read natively
//! ([`super::calc`]); `-e`/`-f` definitions and `-s` smoothing (which needs `rev.cal`) are
//! refused.

use super::calc;
use super::text::reals_primitive;
use std::path::Path;

const USAGE: &str = "genrev material name z(t) r(t) nseg";
/// Most segments generated.
const MAX_SEGMENTS: f64 = 100_000.0;
/// genrev's `FTINY`: smaller steps in z or r count as none.
const TINY: f64 = 1e-9;

pub(super) fn generate(args: &[String], _dir: &Path) -> Result<String, String> {
    if args.len() < 5 {
        return Err(format!("{} argument(s) given; usage: {USAGE}", args.len()));
    }
    if let Some(option) = args[5..]
        .iter()
        .find(|a| matches!(a.as_str(), "-e" | "-f" | "-s"))
    {
        return Err(format!(
            "`{option}` needs RADIANCE's function files (.cal definitions, rev.cal for -s), \
             which Skylux does not evaluate; only expressions in t are read"
        ));
    }
    if let Some(other) = args.get(5) {
        return Err(format!("unknown option `{other}`; usage: {USAGE}"));
    }
    let (material, name) = (&args[0], &args[1]);
    let z = calc::parse(&args[2]).map_err(|e| format!("z(t): {e}"))?;
    let r = calc::parse(&args[3]).map_err(|e| format!("r(t): {e}"))?;
    let segments = calc::parse(&args[4])
        .map_err(|e| format!("nseg: {e}"))?
        .eval(0.0)
        + 0.5;
    if !(1.0..=MAX_SEGMENTS).contains(&segments) {
        return Err(format!("nseg must be 1 to {MAX_SEGMENTS}"));
    }
    let n = segments as usize;
    let at = |i: usize| {
        let t = i as f64 / n as f64;
        (z.eval(t), r.eval(t))
    };
    let mut out = String::new();
    let (mut last_z, mut last_r) = at(0);
    for i in 1..=n {
        let (zi, ri) = at(i);
        if !(zi.is_finite() && ri.is_finite()) {
            return Err(format!(
                "z or r is not finite at t = {}",
                i as f64 / n as f64
            ));
        }
        let up = zi > last_z + TINY;
        let down = zi < last_z - TINY;
        let inward = ri < last_r - TINY;
        let outward = ri > last_r + TINY;
        let id = format!("{name}.{i}");
        if !(inward || outward) && (up || down) {
            let kind = if down { "tube" } else { "cylinder" };
            let reals = [0.0, 0.0, last_z, 0.0, 0.0, zi, ri];
            reals_primitive(&mut out, material, kind, &id, &reals);
        } else if !(up || down) && (inward || outward) {
            let normal = if inward { 1.0 } else { -1.0 };
            let reals = [0.0, 0.0, zi, 0.0, 0.0, normal, last_r, ri];
            reals_primitive(&mut out, material, "ring", &id, &reals);
        } else if up || down {
            let kind = if down { "cup" } else { "cone" };
            let reals = [0.0, 0.0, last_z, 0.0, 0.0, zi, last_r, ri];
            reals_primitive(&mut out, material, kind, &id, &reals);
        }
        (last_z, last_r) = (zi, ri);
    }
    Ok(out)
}
