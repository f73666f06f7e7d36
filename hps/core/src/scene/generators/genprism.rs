//! `genprism material name { N x1 y1 .. xN yN | vfile } [-l lx ly lz] [-r radius] [-c] [-e]`:
//! a polygon in the xy plane extruded along a vector, as RADIANCE's genprism.c writes it,
//! with rounded edges (cylinders, spheres) for `-r`. Vertices from a file are read relative
//! to the command's directory; standard input (`-`) is refused.

use super::args::number;
use super::text::{polygon, reals_primitive};
use std::path::Path;

const USAGE: &str =
    "genprism material name { N v1 v2 .. vN | vfile } [-l lvect][-r radius][-c][-e]";
/// genprism's vertex limit.
const MAX_VERTICES: usize = 1024;
/// genprism's `FTINY`.
const TINY: f64 = 1e-6;

struct Prism {
    material: String,
    name: String,
    vertices: Vec<[f64; 2]>,
    /// Extrusion vector.
    l: [f64; 3],
    /// Sign of its z.
    l_dir: f64,
    l_len: f64,
    ends: bool,
    complete: bool,
    /// Edge radius, signed by `l_dir` as genprism keeps it.
    radius: f64,
    /// Edge unit vectors and corner trims (`compute_rounding`).
    u: Vec<[f64; 2]>,
    a: Vec<f64>,
}

pub(super) fn generate(args: &[String], dir: &Path) -> Result<String, String> {
    if args.len() < 3 {
        return Err(format!("{} argument(s) given; usage: {USAGE}", args.len()));
    }
    let (vertices, mut i) = read_vertices(args, dir)?;
    let mut p = Prism {
        material: args[0].clone(),
        name: args[1].clone(),
        vertices,
        l: [0.0, 0.0, 1.0],
        l_dir: 1.0,
        l_len: 1.0,
        ends: true,
        complete: false,
        radius: 0.0,
        u: Vec::new(),
        a: Vec::new(),
    };
    while i < args.len() {
        match args[i].as_str() {
            "-l" => {
                p.l = [
                    number(args, i + 1, "-l x")?,
                    number(args, i + 2, "-l y")?,
                    number(args, i + 3, "-l z")?,
                ];
                if p.l[2].abs() <= TINY {
                    return Err("illegal extrusion vector: its z must not be 0".into());
                }
                p.l_dir = p.l[2].signum();
                p.l_len = (p.l[0] * p.l[0] + p.l[1] * p.l[1] + p.l[2] * p.l[2]).sqrt();
                i += 3;
            }
            "-r" => {
                p.radius = number(args, i + 1, "-r radius")?;
                i += 1;
            }
            "-e" => p.ends = !p.ends,
            "-c" => p.complete = !p.complete,
            other => return Err(format!("unknown option `{other}`; usage: {USAGE}")),
        }
        i += 1;
    }
    let mut out = String::new();
    if p.radius > TINY {
        if p.radius > p.l_dir * p.l[2] {
            return Err("rounding greater than height".into());
        }
        p.radius *= p.l_dir;
        compute_rounding(&mut p)?;
        if p.ends {
            rounded_ends(&p, &mut out);
        }
        sides(&p, &mut out, true);
    } else {
        if p.ends {
            ends(&p, &mut out);
        }
        sides(&p, &mut out, false);
    }
    Ok(out)
}

/// The vertices from the command line or a file, and the index of the first option.
fn read_vertices(args: &[String], dir: &Path) -> Result<(Vec<[f64; 2]>, usize), String> {
    let third = &args[2];
    let (vertices, next) = if third == "-" {
        return Err("vertices from standard input (`-`): a scene file has none".into());
    } else if third.starts_with(|c: char| c.is_ascii_digit()) {
        let n = third
            .parse::<usize>()
            .map_err(|_| format!("vertex count `{third}` is not a count"))?;
        if n > MAX_VERTICES {
            return Err(format!("too many vertices ({n}; at most {MAX_VERTICES})"));
        }
        if args.len() < 3 + 2 * n {
            return Err(format!(
                "{n} vertices announced, fewer given; usage: {USAGE}"
            ));
        }
        let v = (0..n)
            .map(|k| {
                Ok([
                    number(args, 3 + 2 * k, &format!("vertex {} x", k + 1))?,
                    number(args, 4 + 2 * k, &format!("vertex {} y", k + 1))?,
                ])
            })
            .collect::<Result<Vec<_>, String>>()?;
        (v, 3 + 2 * n)
    } else {
        (vertex_file(&crate::scene::files::resolve(dir, third))?, 3)
    };
    if vertices.len() < 3 {
        return Err("not enough vertices (at least 3)".into());
    }
    Ok((vertices, next))
}

/// Pairs of numbers up to the first word that is not one (genprism's `fscanf` loop).
fn vertex_file(path: &Path) -> Result<Vec<[f64; 2]>, String> {
    let bytes = crate::scene::files::read_regular_file(path)
        .map_err(|e| format!("cannot read vertex file {}: {e}", path.display()))?;
    let text = String::from_utf8_lossy(&bytes);
    let numbers: Vec<f64> = text
        .split_whitespace()
        .map_while(|w| w.parse::<f64>().ok().filter(|v| v.is_finite()))
        .collect();
    if numbers.len() / 2 > MAX_VERTICES {
        return Err(format!("{}: too many vertices", path.display()));
    }
    Ok(numbers.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
}

fn ends(p: &Prism, out: &mut String) {
    let bottom: Vec<[f64; 3]> = p.vertices.iter().map(|v| [v[0], v[1], 0.0]).collect();
    polygon(out, &p.material, &format!("{}.b", p.name), &bottom);
    let top: Vec<[f64; 3]> = p
        .vertices
        .iter()
        .rev()
        .map(|v| [v[0] + p.l[0], v[1] + p.l[1], p.l[2]])
        .collect();
    polygon(out, &p.material, &format!("{}.t", p.name), &top);
}

fn sides(p: &Prism, out: &mut String, round: bool) {
    let n = p.vertices.len();
    let last = if p.complete { n - 1 } else { n };
    for i in 0..last {
        let next = (i + 1) % n;
        if round {
            rounded_side(p, i, next, out);
        } else {
            let (v0, v1, l) = (p.vertices[i], p.vertices[next], p.l);
            let quad = [
                [v0[0], v0[1], 0.0],
                [v0[0] + l[0], v0[1] + l[1], l[2]],
                [v1[0] + l[0], v1[1] + l[1], l[2]],
                [v1[0], v1[1], 0.0],
            ];
            polygon(out, &p.material, &format!("{}.{}", p.name, i + 1), &quad);
        }
    }
}

/// `compute_rounding`: edge directions `u` and corner trims `a`.
fn compute_rounding(p: &mut Prism) -> Result<(), String> {
    let n = p.vertices.len();
    p.u = Vec::with_capacity(n);
    let mut v0 = p.vertices[n - 1];
    for &v1 in &p.vertices {
        let d = [v0[0] - v1[0], v0[1] - v1[1]];
        let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
        if l <= TINY {
            return Err("degenerate side in prism".into());
        }
        p.u.push([d[0] / l, d[1] / l]);
        v0 = v1;
    }
    p.a = vec![0.0; n];
    let mut v1 = p.u[0];
    for i in (0..n).rev() {
        let v0 = p.u[i];
        let dot = v0[0] * v1[0] + v0[1] * v1[1];
        if 1.0 + dot <= TINY {
            return Err("overlapping sides in prism".into());
        }
        if 1.0 - dot > 0.0 {
            let cross = v1[0] * v0[1] - v1[1] * v0[0];
            p.a[i] = ((1.0 - dot) / (1.0 + dot)).sqrt() * if cross < 0.0 { -1.0 } else { 1.0 };
        }
        v1 = v0;
    }
    Ok(())
}

/// The corner of vertex `i` pulled in by the radius (bottom; add `l` for the top).
fn inset(p: &Prism, i: usize) -> [f64; 2] {
    let (v, u, a, r) = (p.vertices[i], p.u[i], p.a[i], p.radius);
    [v[0] + r * (a * u[0] - u[1]), v[1] + r * (a * u[1] + u[0])]
}

fn rounded_ends(p: &Prism, out: &mut String) {
    let n = p.vertices.len();
    let (l, r) = (p.l, p.radius);
    let bottom: Vec<[f64; 3]> = (0..n)
        .map(|i| inset(p, i))
        .map(|c| [c[0], c[1], 0.0])
        .collect();
    polygon(out, &p.material, &format!("{}.b", p.name), &bottom);
    let top: Vec<[f64; 3]> = (0..n)
        .rev()
        .map(|i| inset(p, i))
        .map(|c| [c[0] + l[0], c[1] + l[1], l[2]])
        .collect();
    polygon(out, &p.material, &format!("{}.t", p.name), &top);
    for (tag, shift, z) in [("b", [0.0, 0.0], r), ("t", [l[0], l[1]], l[2] - r)] {
        let corner = |i: usize| {
            let c = inset(p, i);
            [c[0] + shift[0], c[1] + shift[1], z]
        };
        let mut c0 = corner(n - 1);
        for i in 0..n {
            let c1 = corner(i);
            if p.l_dir * p.a[i] > 0.0 {
                let reals = [c1[0], c1[1], c1[2], p.l_dir * r];
                reals_primitive(
                    out,
                    &p.material,
                    "sphere",
                    &format!("{}.{tag}c{}", p.name, i + 1),
                    &reals,
                );
            }
            let reals = [c0[0], c0[1], c0[2], c1[0], c1[1], c1[2], p.l_dir * r];
            reals_primitive(
                out,
                &p.material,
                "cylinder",
                &format!("{}.{tag}e{}", p.name, i + 1),
                &reals,
            );
            c0 = c1;
        }
    }
}

/// `rside`: a side whose edges are rounded, and the cylinder joining it to the next.
fn rounded_side(p: &Prism, n0: usize, n1: usize, out: &mut String) {
    let (l, r, u) = (p.l, p.radius, p.u[n1]);
    let s = p.l_dir * (l[1] * u[0] - l[0] * u[1]) / p.l_len;
    let t = if s.abs() > TINY {
        let c = (1.0 - s * s).sqrt();
        [(c - 1.0) * u[1], (1.0 - c) * u[0], s]
    } else {
        [0.0; 3]
    };
    let (v0, v1, a0, a1) = (p.vertices[n0], p.vertices[n1], p.a[n0], p.a[n1]);
    let quad = [
        [
            v0[0] + r * (t[0] - a0 * u[0]),
            v0[1] + r * (t[1] - a0 * u[1]),
            r * (t[2] + 1.0),
        ],
        [
            v0[0] + l[0] + r * (t[0] - a0 * u[0]),
            v0[1] + l[1] + r * (t[1] - a0 * u[1]),
            l[2] + r * (t[2] - 1.0),
        ],
        [
            v1[0] + l[0] + r * (t[0] + a1 * u[0]),
            v1[1] + l[1] + r * (t[1] + a1 * u[1]),
            l[2] + r * (t[2] - 1.0),
        ],
        [
            v1[0] + r * (t[0] + a1 * u[0]),
            v1[1] + r * (t[1] + a1 * u[1]),
            r * (t[2] + 1.0),
        ],
    ];
    polygon(out, &p.material, &format!("{}.{}", p.name, n0 + 1), &quad);
    if p.l_dir * a1 < 0.0 {
        return;
    }
    let e = [
        v1[0] + r * (a1 * u[0] - u[1]),
        v1[1] + r * (a1 * u[1] + u[0]),
    ];
    let reals = [
        e[0],
        e[1],
        r,
        e[0] + l[0],
        e[1] + l[1],
        l[2] - r,
        p.l_dir * r,
    ];
    reals_primitive(
        out,
        &p.material,
        "cylinder",
        &format!("{}.e{}", p.name, n0 + 1),
        &reals,
    );
}
