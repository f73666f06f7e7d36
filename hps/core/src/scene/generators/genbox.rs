//! `genbox material name xsize ysize zsize [-i] [-b bevel | -r round]`: a box from the
//! origin to (x, y, z), as RADIANCE's genbox.c writes it: faces named by their corner codes,
//! bevelled edges as extra faces, rounded edges as cylinders and spheres. genbox's
//! segmented rounding (`-r` with `-n`, `-i` or `-s`, written as a mesh through objutil) and
//! `.OBJ` output (`-o`) are refused.

use super::args::{number, require};
use super::text::{polygon, reals_primitive};
use std::path::Path;

const USAGE: &str = "genbox material name xsize ysize zsize [-i] [-b bevel | -r round]";
/// genbox's letters for corner codes.
const LETTERS: &[u8] = b"0123456789._ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";

struct Box3 {
    size: [f64; 3],
    bevel: f64,
    reverse: bool,
}

impl Box3 {
    /// Corner code `v`: bits 0-2 pick the far side per axis, bits 3-5 pull it in by the bevel.
    fn vertex(&self, v: usize) -> [f64; 3] {
        std::array::from_fn(|i| {
            let far = ((v >> i) & 1 == 1) != self.reverse;
            if (v >> (i + 3)) & 1 == 1 {
                if far {
                    self.size[i] - self.bevel
                } else {
                    self.bevel
                }
            } else if far {
                self.size[i]
            } else {
                0.0
            }
        })
    }

    fn name(&self, base: &str, codes: &[usize]) -> String {
        let letters: String = codes.iter().map(|&c| char::from(LETTERS[c])).collect();
        format!("{base}.{letters}")
    }
}

pub(super) fn generate(args: &[String], _dir: &Path) -> Result<String, String> {
    require(args, 5, USAGE)?;
    let (material, name) = (&args[0], &args[1]);
    let size = [
        number(args, 2, "xsize")?,
        number(args, 3, "ysize")?,
        number(args, 4, "zsize")?,
    ];
    if size.iter().any(|&s| s <= 0.0) {
        return Err(format!("sizes must be positive; usage: {USAGE}"));
    }
    let (mut reverse, mut round, mut bevel, mut segments) = (false, false, 0.0, 1i64);
    let mut i = 5;
    while i < args.len() {
        match args[i].as_str() {
            "-i" => reverse = true,
            "-r" | "-b" => {
                round = args[i] == "-r";
                bevel = number(args, i + 1, &format!("{} radius", args[i]))?;
                if bevel <= 0.0 {
                    return Err(format!("{} needs a positive size", args[i]));
                }
                i += 1;
            }
            "-n" => {
                segments = super::args::integer(args, i + 1, "-n segments")?;
                i += 1;
            }
            "-s" => {}
            "-o" => return Err("`-o` (.OBJ output) is not a scene".into()),
            other => return Err(format!("unknown option `{other}`; usage: {USAGE}")),
        }
        i += 1;
    }
    if round && (reverse || segments > 1) {
        return Err(
            "rounded edges with -i or -n are written as a segmented mesh by \
                    RADIANCE's objutil, which Skylux does not generate"
                .into(),
        );
    }
    let b = Box3 {
        size,
        bevel,
        reverse,
    };
    Ok(write_box(&b, material, name, round))
}

fn write_box(b: &Box3, material: &str, name: &str, round: bool) -> String {
    let mut out = String::new();
    let side = |out: &mut String, codes: &[usize]| {
        let vertices: Vec<[f64; 3]> = codes.iter().map(|&c| b.vertex(c)).collect();
        polygon(out, material, &b.name(name, codes), &vertices);
    };
    if b.bevel > 0.0 {
        for codes in [
            [0o51, 0o55, 0o54, 0o50],
            [0o64, 0o66, 0o62, 0o60],
            [0o32, 0o33, 0o31, 0o30],
            [0o53, 0o52, 0o56, 0o57],
            [0o65, 0o61, 0o63, 0o67],
            [0o36, 0o34, 0o35, 0o37],
        ] {
            side(&mut out, &codes);
        }
    }
    if b.bevel > 0.0 && !round {
        for codes in [
            [0o31, 0o51, 0o50, 0o30],
            [0o60, 0o62, 0o32, 0o30],
            [0o50, 0o54, 0o64, 0o60],
            [0o34, 0o36, 0o66, 0o64],
            [0o37, 0o57, 0o56, 0o36],
            [0o52, 0o62, 0o66, 0o56],
            [0o52, 0o53, 0o33, 0o32],
            [0o57, 0o67, 0o63, 0o53],
            [0o61, 0o31, 0o33, 0o63],
            [0o65, 0o67, 0o37, 0o35],
            [0o55, 0o51, 0o61, 0o65],
            [0o34, 0o54, 0o55, 0o35],
        ] {
            side(&mut out, &codes);
        }
        for codes in [
            [0o30, 0o50, 0o60],
            [0o51, 0o31, 0o61],
            [0o32, 0o62, 0o52],
            [0o64, 0o54, 0o34],
            [0o36, 0o56, 0o66],
            [0o65, 0o35, 0o55],
            [0o53, 0o63, 0o33],
            [0o37, 0o67, 0o57],
        ] {
            side(&mut out, &codes);
        }
    }
    if b.bevel > 0.0 && round {
        write_rounding(b, material, name, &mut out);
    }
    if b.bevel == 0.0 {
        for codes in [
            [1, 5, 4, 0],
            [4, 6, 2, 0],
            [2, 3, 1, 0],
            [3, 2, 6, 7],
            [5, 1, 3, 7],
            [6, 4, 5, 7],
        ] {
            side(&mut out, &codes);
        }
    }
    out
}

/// Rounded edges (cylinders) and corners (spheres) of radius `bevel`.
fn write_rounding(b: &Box3, material: &str, name: &str, out: &mut String) {
    for (v0, v1) in [
        (0o70, 0o71),
        (0o70, 0o74),
        (0o70, 0o72),
        (0o73, 0o71),
        (0o73, 0o72),
        (0o73, 0o77),
        (0o75, 0o71),
        (0o75, 0o74),
        (0o75, 0o77),
        (0o76, 0o72),
        (0o76, 0o74),
        (0o76, 0o77),
    ] {
        let (p0, p1) = (b.vertex(v0), b.vertex(v1));
        let reals = [p0[0], p0[1], p0[2], p1[0], p1[1], p1[2], b.bevel];
        reals_primitive(out, material, "cylinder", &b.name(name, &[v0, v1]), &reals);
    }
    for v in 0o70..=0o77 {
        let p = b.vertex(v);
        reals_primitive(
            out,
            material,
            "sphere",
            &b.name(name, &[v]),
            &[p[0], p[1], p[2], b.bevel],
        );
    }
}
