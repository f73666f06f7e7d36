//! `genrev material name 'z(t)' 'r(t)' nseg [-e expr] [-f file] [-s]`: a surface of
//! revolution about z, as RADIANCE's genrev.c writes it: for each of `nseg` steps of t from 0
//! to 1, a cylinder (or tube), ring, or cone (or cup) between consecutive (z, r). With `-s`,
//! each piece is smoothed by a `texfunc Phong` of `rev.cal` that interpolates the normals of
//! the neighbouring pieces.

use super::functions::Functions;
use super::text::reals_primitive;
use std::fmt::Write as _;
use std::path::Path;

const USAGE: &str = "genrev material name z(t) r(t) nseg [-e expr] [-f file] [-s]";
/// Most segments generated.
const MAX_SEGMENTS: usize = 100_000;
/// genrev's `FTINY`: smaller steps in z or r count as none.
const TINY: f64 = 1e-9;
const Z: &str = "Z`SYS`";
const R: &str = "R`SYS`";

/// Which way a piece goes (genrev.c's orientation bits).
#[derive(Clone, Copy, Default)]
struct Orientation {
    up: bool,
    down: bool,
    inward: bool,
    outward: bool,
}

impl Orientation {
    fn between(last: (f64, f64), now: (f64, f64)) -> Self {
        Self {
            down: now.0 < last.0 - TINY,
            up: now.0 > last.0 + TINY,
            inward: now.1 < last.1 - TINY,
            outward: now.1 > last.1 + TINY,
        }
    }
    fn axial(self) -> bool {
        self.up || self.down
    }
    fn radial(self) -> bool {
        self.inward || self.outward
    }
}

/// The unit normal (n_z, n_r) of the piece from (z0, r0) to (z1, r1): the step turned by a
/// right angle.
fn normal((z0, r0): (f64, f64), (z1, r1): (f64, f64)) -> (f64, f64) {
    let (nz, nr) = (r0 - r1, z1 - z0);
    let length = nz.hypot(nr);
    (nz / length, nr / length)
}

pub(super) fn generate(args: &[String], dir: &Path) -> Result<String, String> {
    if args.len() < 5 {
        return Err(format!("{} argument(s) given; usage: {USAGE}", args.len()));
    }
    let mut functions = Functions::new();
    let smooth = !functions
        .options(&args[5..], dir, &["-s"], USAGE)?
        .is_empty();
    let (material, name) = (&args[0], &args[1]);
    functions.define(Z, "t", &args[2], "z(t)")?;
    functions.define(R, "t", &args[3], "r(t)")?;
    let n = functions.count(&args[4], "nseg", MAX_SEGMENTS)?;
    let at = |i: usize| -> Result<(f64, f64), String> {
        let t = i as f64 / n as f64;
        Ok((
            functions.value(Z, &[t], "z(t)")?,
            functions.value(R, &[t], "r(t)")?,
        ))
    };
    let modifier = if smooth { "Phong" } else { material.as_str() };
    let mut out = String::new();
    let (mut last, mut now) = (at(0)?, at(1)?);
    let (mut last_normal, mut normal_now) = ((0.0, 0.0), normal(last, now));
    for i in 1..=n {
        let (next, next_normal) = if i < n {
            let next = at(i + 1)?;
            (next, normal(now, next))
        } else {
            ((0.0, 0.0), (0.0, 0.0))
        };
        let o = Orientation::between(last, now);
        if o.axial() || o.radial() {
            if smooth {
                phong(&mut out, material, o, last, now, last_normal, next_normal)?;
            }
            piece(&mut out, modifier, &format!("{name}.{i}"), o, last, now);
        }
        (last, now) = (now, next);
        (last_normal, normal_now) = (normal_now, next_normal);
    }
    Ok(out)
}

/// The `texfunc Phong` before a smoothed piece: per axis, the slope and intercept of the
/// normal's component along the piece (from the previous piece's normal to the next one's),
/// or a constant where the piece does not move along that axis.
fn phong(
    out: &mut String,
    material: &str,
    o: Orientation,
    (last_z, last_r): (f64, f64),
    (z, r): (f64, f64),
    (last_nz, last_nr): (f64, f64),
    (next_nz, next_nr): (f64, f64),
) -> Result<(), String> {
    let (z_line, r_line) = (
        if o.axial() {
            let slope = (next_nz - last_nz) / (z - last_z);
            (slope, last_nz - slope * last_z)
        } else {
            (0.0, if o.inward { 1.0 } else { -1.0 })
        },
        if o.radial() {
            let slope = (next_nr - last_nr) / (r - last_r);
            (slope, last_nr - slope * last_r)
        } else {
            (0.0, if o.up { 1.0 } else { -1.0 })
        },
    );
    let reals = [z_line.0, z_line.1, r_line.0, r_line.1];
    if reals.iter().any(|v| !v.is_finite()) {
        return Err(format!(
            "-s: the normals are not finite near z = {z}, r = {r} (two points coincide)"
        ));
    }
    let _ = write!(
        out,
        "\n{material} texfunc Phong\n4 rev_dx rev_dy rev_dz rev.cal\n0\n4 {} {} {} {}\n",
        reals[0], reals[1], reals[2], reals[3]
    );
    Ok(())
}

/// The piece from `last` to `now`: a cylinder or tube (along z), a ring (across), or a cone
/// or cup.
fn piece(
    out: &mut String,
    modifier: &str,
    id: &str,
    o: Orientation,
    last: (f64, f64),
    now: (f64, f64),
) {
    let ((last_z, last_r), (z, r)) = (last, now);
    if !o.radial() {
        let kind = if o.down { "tube" } else { "cylinder" };
        reals_primitive(out, modifier, kind, id, &[0.0, 0.0, last_z, 0.0, 0.0, z, r]);
    } else if !o.axial() {
        let normal = if o.inward { 1.0 } else { -1.0 };
        reals_primitive(
            out,
            modifier,
            "ring",
            id,
            &[0.0, 0.0, z, 0.0, 0.0, normal, last_r, r],
        );
    } else {
        let kind = if o.down { "cup" } else { "cone" };
        reals_primitive(
            out,
            modifier,
            kind,
            id,
            &[0.0, 0.0, last_z, 0.0, 0.0, z, last_r, r],
        );
    }
}
