//! RADIANCE's `xform`, natively: its options, its 4x4 transform built as `xf.c` builds it
//! (row vectors, `p' = p M`, each option applied after the previous ones, `-i N` repeating
//! what came before it), arrays (`-a N`) as `xform.c`'s `doarray`, and each primitive type's
//! arguments transformed as `xform.c`'s per-type functions transform them.

use super::primitive::Primitive;

/// Largest `-a`/`-i` count, and largest product of nested `-a` counts, Skylux expands: a
/// scene with more copies than this is a mistake (or an attack), not a building.
pub const MAX_ARRAY_COPIES: usize = 10_000;

/// Types whose string arguments carry a transform (`T_F` in RADIANCE's otypes.h): xform
/// appends its own to them, as it does to instances and meshes.
const FUNCTION_TYPES: &[&str] = &[
    "texfunc",
    "plastic2",
    "metal2",
    "trans2",
    "plasfunc",
    "metfunc",
    "brightfunc",
    "brightdata",
    "colorpict",
    "transfunc",
    "BRTDfunc",
    "BSDF",
    "aBSDF",
    "WGMDfunc",
    "plasdata",
    "metdata",
    "transdata",
    "colorfunc",
    "colordata",
    "texdata",
    "mixfunc",
    "mixdata",
    "mixpict",
    "prism1",
    "prism2",
    "ashik2",
    "specfunc",
    "specdata",
    "specpict",
    "instance",
    "mesh",
];

/// `xform`'s surface inverses under `-I` (`tinvers` in xform.c).
fn inverse_type(type_name: &str) -> &str {
    match type_name {
        "cone" => "cup",
        "cup" => "cone",
        "sphere" => "bubble",
        "bubble" => "sphere",
        "cylinder" => "tube",
        "tube" => "cylinder",
        other => other,
    }
}

/// A 4x4 matrix in RADIANCE's convention: points are row vectors, translation in row 3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Matrix4([[f64; 4]; 4]);

impl Matrix4 {
    const IDENTITY: Matrix4 = Matrix4([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);

    /// `self` then `other` (`multmat4(m, self, other)`).
    fn then(&self, other: &Matrix4) -> Matrix4 {
        let mut m = [[0.0; 4]; 4];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, value) in row.iter_mut().enumerate() {
                *value = (0..4).map(|k| self.0[i][k] * other.0[k][j]).sum();
            }
        }
        Matrix4(m)
    }

    /// A point (`multp3`).
    pub fn point(&self, p: [f64; 3]) -> [f64; 3] {
        let m = &self.0;
        std::array::from_fn(|j| p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j])
    }

    /// The rows, for callers outside the scene reader.
    pub fn rows(&self) -> [[f64; 4]; 4] {
        self.0
    }

    /// The inverse of a transform made of rotations, mirrors, a uniform scale `scale` and
    /// translations (all `xf()` makes): its 3x3 part M satisfies M Mᵀ = s² I, so
    /// M⁻¹ = Mᵀ / s², and the translation row t becomes −t M⁻¹.
    pub fn inverse_similarity(&self, scale: f64) -> [[f64; 4]; 4] {
        let m = &self.0;
        let s2 = scale * scale;
        let mut inv = [[0.0; 4]; 4];
        for (i, row) in inv.iter_mut().take(3).enumerate() {
            for (j, value) in row.iter_mut().take(3).enumerate() {
                *value = m[j][i] / s2;
            }
        }
        let translation: [f64; 3] =
            std::array::from_fn(|j| -(0..3).map(|k| m[3][k] * inv[k][j]).sum::<f64>());
        inv[3][..3].copy_from_slice(&translation);
        inv[3][3] = 1.0;
        inv
    }

    /// A direction, scaled with the transform but not translated (`multv3`).
    pub fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        let m = &self.0;
        std::array::from_fn(|j| v[0] * m[0][j] + v[1] * m[1][j] + v[2] * m[2][j])
    }
}

/// A complete transform: the matrix and its scale factor (negative once mirrored an odd
/// number of times), as `xf()` returns them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Transform {
    pub matrix: Matrix4,
    pub scale: f64,
}

/// One `xform` run (one copy of an array): what it renames, how it moves things, its inputs.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Xform {
    /// `-m`: the new modifier of every surface.
    modifier: Option<String>,
    /// `-n`: prefix of surface identifiers (several `-n` join with dots).
    prefix: Option<String>,
    /// `-I`: surfaces turned inside out.
    invert: bool,
    /// The transform words as given, appended to function types' strings.
    transform_words: Vec<String>,
    transform: Transform,
    /// Polygons are written in reverse order (mirrored or inverted).
    reverse: bool,
    /// Files to read; none means standard input (a pipe stage).
    pub files: Vec<String>,
}

/// The runs an `xform` command line stands for: one, or one per copy of each `-a` (nested
/// arrays multiply). `words` excludes the program name.
pub(crate) fn parse_xform(words: &[String]) -> Result<Vec<Xform>, String> {
    if words.iter().any(|w| w == "-f") {
        return Err("`xform -f` (argument lists from a file) is not supported".into());
    }
    let mut runs = Vec::new();
    expand_arrays(words.to_vec(), 1, &mut runs)?;
    runs.iter().map(|w| parse_single(w)).collect()
}

/// `doarray`: each `-a N` becomes `-i k` for k in 0..N, and the copies are named `a{k}` (or
/// `{prefix}.{k}` after an existing `-n`), recursively for further `-a`s.
fn expand_arrays(
    words: Vec<String>,
    copies: usize,
    out: &mut Vec<Vec<String>>,
) -> Result<(), String> {
    let Some(at) = words.iter().position(|w| w == "-a") else {
        out.push(words);
        return Ok(());
    };
    let count = words
        .get(at + 1)
        .and_then(|w| w.parse::<i64>().ok())
        .filter(|&n| n > 0)
        .ok_or("`-a` needs a positive copy count")?;
    let total = usize::try_from(count)
        .ok()
        .and_then(|n| n.checked_mul(copies))
        .filter(|&n| n <= MAX_ARRAY_COPIES)
        .ok_or_else(|| {
            format!(
                "`-a {count}` makes more than {MAX_ARRAY_COPIES} copies in all (the limit \
                 Skylux expands)"
            )
        })?;
    let has_prefix = words.iter().any(|w| w == "-n");
    for k in 0..count {
        let mut copy = Vec::with_capacity(words.len() + 2);
        for (i, w) in words.iter().enumerate() {
            copy.push(if i == at {
                "-i".to_string()
            } else if i == at + 1 {
                k.to_string()
            } else if i > 0 && words[i - 1] == "-n" {
                format!("{w}.{k}")
            } else {
                w.clone()
            });
        }
        if !has_prefix {
            copy.splice(0..0, ["-n".to_string(), format!("a{k}")]);
        }
        expand_arrays(copy, total, out)?;
    }
    Ok(())
}

/// One run's options as `xform.c`'s `main` reads them: renaming options first, then the
/// transform, then files.
fn parse_single(words: &[String]) -> Result<Xform, String> {
    let (mut modifier, mut prefix, mut invert) = (None, None::<String>, false);
    let mut a = 0;
    while let Some(w) = words.get(a) {
        match w.as_str() {
            "-m" if a + 1 < words.len() => {
                modifier.get_or_insert_with(|| words[a + 1].clone());
                a += 2;
            }
            "-n" if a + 1 < words.len() => {
                let next = &words[a + 1];
                prefix = Some(match prefix {
                    Some(p) => format!("{p}.{next}"),
                    None => next.clone(),
                });
                a += 2;
            }
            "-c" | "-e" => a += 1,
            "-I" => {
                invert = !invert;
                a += 1;
            }
            _ => break,
        }
    }
    let (transform, used) = parse_transform(&words[a..])?;
    let transform_words = words[a..a + used].to_vec();
    let files = words[a + used..].to_vec();
    if let Some(bad) = files.iter().find(|f| f.starts_with('-') && f.len() > 1) {
        return Err(format!("unknown or misplaced xform option `{bad}`"));
    }
    let reverse = (transform.scale < 0.0) != invert;
    Ok(Xform {
        modifier,
        prefix,
        invert,
        transform_words,
        transform: Transform {
            matrix: transform.matrix,
            scale: transform.scale.abs(),
        },
        reverse,
        files,
    })
}

/// `xf()`: the transform options at the start of `words`, and how many words they take.
pub(crate) fn parse_transform(words: &[String]) -> Result<(Transform, usize), String> {
    let mut total = Transform {
        matrix: Matrix4::IDENTITY,
        scale: 1.0,
    };
    let mut pending = (Matrix4::IDENTITY, 1.0, 1usize);
    let mut i = 0;
    while let Some(option) = words.get(i).filter(|w| w.starts_with('-')) {
        let number = |k: usize| -> Result<f64, String> {
            let w = words
                .get(i + k)
                .ok_or_else(|| format!("`{option}` needs {k} more number(s)"))?;
            w.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("`{option}` argument `{w}` is not a number"))
        };
        let (m4, scale, used) = match option.as_str() {
            "-t" => (translation([number(1)?, number(2)?, number(3)?]), 1.0, 4),
            "-rx" | "-ry" | "-rz" => (rotation(&option[2..], number(1)?), 1.0, 2),
            "-s" => {
                let s = number(1)?;
                if s == 0.0 {
                    return Err("`-s 0` scales everything to nothing".into());
                }
                (diagonal([s, s, s]), s, 2)
            }
            "-mx" => (diagonal([-1.0, 1.0, 1.0]), -1.0, 1),
            "-my" => (diagonal([1.0, -1.0, 1.0]), -1.0, 1),
            "-mz" => (diagonal([1.0, 1.0, -1.0]), -1.0, 1),
            "-i" => {
                let n = words
                    .get(i + 1)
                    .and_then(|w| w.parse::<usize>().ok())
                    .filter(|&n| n <= MAX_ARRAY_COPIES)
                    .ok_or_else(|| {
                        format!("`-i` needs a repeat count from 0 to {MAX_ARRAY_COPIES}")
                    })?;
                apply(&mut total, &pending);
                pending = (Matrix4::IDENTITY, 1.0, n);
                i += 2;
                continue;
            }
            _ => break,
        };
        pending.0 = pending.0.then(&m4);
        pending.1 *= scale;
        i += used;
    }
    apply(&mut total, &pending);
    Ok((total, i))
}

/// `total` followed by `matrix` repeated `count` times (xf.c multiplies in a loop; squaring
/// gives the same product in log2(count) steps).
fn apply(total: &mut Transform, (matrix, scale, count): &(Matrix4, f64, usize)) {
    let (mut base, mut n, mut power) = (*matrix, *count, Matrix4::IDENTITY);
    while n > 0 {
        if n & 1 == 1 {
            power = power.then(&base);
        }
        base = base.then(&base);
        n >>= 1;
    }
    total.matrix = total.matrix.then(&power);
    total.scale *= scale.powi(i32::try_from(*count).unwrap_or(i32::MAX));
}

fn translation(t: [f64; 3]) -> Matrix4 {
    let mut m = Matrix4::IDENTITY;
    m.0[3][..3].copy_from_slice(&t);
    m
}

fn diagonal(d: [f64; 3]) -> Matrix4 {
    let mut m = Matrix4::IDENTITY;
    for (k, v) in d.into_iter().enumerate() {
        m.0[k][k] = v;
    }
    m
}

/// Rotation by `degrees` about `axis` (x, y or z), right-handed, as `xf.c` writes it.
fn rotation(axis: &str, degrees: f64) -> Matrix4 {
    let (s, c) = degrees.to_radians().sin_cos();
    let (a, b) = match axis {
        "x" => (1, 2),
        "y" => (2, 0),
        _ => (0, 1),
    };
    let mut m = Matrix4::IDENTITY;
    m.0[a][a] = c;
    m.0[b][b] = c;
    m.0[a][b] = s;
    m.0[b][a] = -s;
    m
}

impl Xform {
    /// The primitives as this run writes them; an error names the primitive whose arguments
    /// do not fit its type (xform's "bad TYPE").
    pub fn apply(&self, input: &[Primitive]) -> Result<Vec<Primitive>, String> {
        input
            .iter()
            .map(|p| {
                self.apply_one(p).map_err(|why| {
                    format!("{} `{}` ({}): {why}", p.type_name, p.identifier, p.origin)
                })
            })
            .collect()
    }

    fn apply_one(&self, p: &Primitive) -> Result<Primitive, String> {
        let mut out = p.clone();
        if p.is_surface() {
            if let Some(m) = &self.modifier {
                out.modifier.clone_from(m);
            }
            if self.invert {
                out.type_name = inverse_type(&p.type_name).to_string();
            }
            if let Some(prefix) = &self.prefix {
                out.identifier = format!("{prefix}.{}", p.identifier);
            }
        }
        self.transform_arguments(&mut out)?;
        Ok(out)
    }

    /// The per-type argument transforms of xform.c (`o_face`, `o_sphere`, `m_glow`, ...).
    fn transform_arguments(&self, p: &mut Primitive) -> Result<(), String> {
        let t = &self.transform;
        let sca = t.scale;
        let plain = p.strings.is_empty();
        let r = &mut p.reals;
        match p.type_name.as_str() {
            "source" if plain && r.len() == 4 => vector_at(r, 0, &t.matrix),
            "sphere" | "bubble" if plain && r.len() == 4 => {
                point_at(r, 0, &t.matrix);
                r[3] *= sca;
            }
            "polygon" if plain && r.len().is_multiple_of(3) => {
                let mut points: Vec<[f64; 3]> = r
                    .chunks_exact(3)
                    .map(|c| t.matrix.point([c[0], c[1], c[2]]))
                    .collect();
                if self.reverse {
                    points.reverse();
                }
                *r = points.concat();
            }
            "cone" | "cup" if plain && r.len() == 8 => {
                point_at(r, 0, &t.matrix);
                point_at(r, 3, &t.matrix);
                r[6] *= sca;
                r[7] *= sca;
            }
            "cylinder" | "tube" if plain && r.len() == 7 => {
                point_at(r, 0, &t.matrix);
                point_at(r, 3, &t.matrix);
                r[6] *= sca;
            }
            "ring" if plain && r.len() == 8 => {
                point_at(r, 0, &t.matrix);
                let d = t.matrix.vector(get(r, 3));
                put(r, 3, if self.invert { d.map(|v| -v) } else { d });
                r[6] *= sca;
                r[7] *= sca;
            }
            "glow" if plain && r.len() == 4 => r[3] *= sca,
            "spotlight" if plain && r.len() == 7 => vector_at(r, 4, &t.matrix),
            "dielectric" if plain && r.len() == 5 => {
                r[..3].iter_mut().for_each(|v| *v = v.powf(1.0 / sca));
            }
            "interface" if plain && r.len() == 8 => {
                r[..3].iter_mut().for_each(|v| *v = v.powf(1.0 / sca));
                r[4..7].iter_mut().for_each(|v| *v = v.powf(1.0 / sca));
            }
            "mist" if r.len() <= 7 => {
                if r.len() > 2 {
                    r[..3].iter_mut().for_each(|v| *v /= sca);
                }
                if let Some(prefix) = &self.prefix {
                    for s in &mut p.strings {
                        *s = prefix_source_names(prefix, s);
                    }
                }
            }
            "colortext" | "brighttext" | "mixtext" if r.len() >= 9 => {
                point_at(r, 0, &t.matrix);
                vector_at(r, 3, &t.matrix);
                vector_at(r, 6, &t.matrix);
            }
            name if FUNCTION_TYPES.contains(&name) => self.append_transform(&mut p.strings),
            "source" | "sphere" | "bubble" | "polygon" | "cone" | "cup" | "cylinder" | "tube"
            | "ring" | "glow" | "spotlight" | "dielectric" | "interface" | "mist" | "colortext"
            | "brighttext" | "mixtext" => {
                return Err(format!(
                    "its arguments ({} string, {} real) do not fit a {}",
                    p.strings.len(),
                    r.len(),
                    p.type_name
                ));
            }
            _ => {}
        }
        Ok(())
    }

    /// `addxform`: the run's transform words after the strings, behind `-i 1` unless they
    /// start with `-i` (so an earlier array count does not repeat them).
    fn append_transform(&self, strings: &mut Vec<String>) {
        if self.transform_words.is_empty() {
            return;
        }
        if self.transform_words[0] != "-i" {
            strings.extend(["-i".to_string(), "1".to_string()]);
        }
        strings.extend(self.transform_words.iter().cloned());
    }
}

/// `m_mist`'s renaming of the light sources a mist names (`a>b` lists).
fn prefix_source_names(prefix: &str, names: &str) -> String {
    names
        .split_inclusive('>')
        .map(|name| format!("{prefix}.{name}"))
        .collect()
}

fn get(r: &[f64], at: usize) -> [f64; 3] {
    [r[at], r[at + 1], r[at + 2]]
}

fn put(r: &mut [f64], at: usize, v: [f64; 3]) {
    r[at..at + 3].copy_from_slice(&v);
}

fn point_at(r: &mut [f64], at: usize, m: &Matrix4) {
    let v = m.point(get(r, at));
    put(r, at, v);
}

fn vector_at(r: &mut [f64], at: usize, m: &Matrix4) {
    let v = m.vector(get(r, at));
    put(r, at, v);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(text: &str) -> Vec<String> {
        text.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn iterate_repeats_what_comes_after_it() {
        let (t, used) = parse_transform(&words("-t 1 0 0 -i 3 -rz 90 f.rad")).unwrap();
        assert_eq!(used, 8);
        let p = t.matrix.point([0.0, 0.0, 0.0]);
        // Translated to (1,0,0), then turned three quarter turns: (0,-1,0).
        assert!(
            (p[0] - 0.0).abs() < 1e-12 && (p[1] + 1.0).abs() < 1e-12,
            "{p:?}"
        );
    }

    #[test]
    fn arrays_name_and_place_each_copy() {
        let runs = parse_xform(&words("-a 3 -t 2 0 0 box.rad")).unwrap();
        assert_eq!(runs.len(), 3);
        assert_eq!(runs[2].prefix.as_deref(), Some("a2"));
        assert_eq!(runs[2].transform.matrix.point([0.0; 3]), [4.0, 0.0, 0.0]);
        let named = parse_xform(&words("-n row -a 2 -a 2 -t 1 0 0 b.rad")).unwrap();
        let names: Vec<_> = named.iter().map(|r| r.prefix.clone().unwrap()).collect();
        assert_eq!(names, ["row.0.0", "row.0.1", "row.1.0", "row.1.1"]);
    }

    #[test]
    fn too_many_copies_and_bad_options_are_refused() {
        assert!(parse_xform(&words("-a 200 -a 200 b.rad"))
            .unwrap_err()
            .contains("10000"));
        assert!(parse_xform(&words("-a 0 b.rad")).is_err());
        assert!(parse_xform(&words("-s 0 b.rad")).is_err());
        assert!(parse_xform(&words("-t 1 2 b.rad")).is_err());
        assert!(parse_xform(&words("-rz 10 -q b.rad"))
            .unwrap_err()
            .contains("-q"));
        assert!(parse_xform(&words("-f list.txt")).is_err());
    }
}
