//! Function modifiers: patterns, textures, mixtures and materials whose values come from
//! `.cal` expressions evaluated at each hit (`colorfunc`, `brightfunc` on any material,
//! `texfunc`, `mixfunc`, `BRTDfunc`).
//!
//! String arguments follow the RADIANCE reference manual (ray.html §2.1.2 "BRTDfunc", §2.1.4
//! "Colorfunc", §2.1.5 "Texfunc", §2.1.6 "Mixfunc") and `src/rt/func.c` `getfunc`: a given
//! number of expressions, the function file (`.` for none), then transform words, which start
//! at the first word beginning with `-`. The expressions and the file are compiled by the
//! engine (`engine::function`); here they are only split and checked for count.

use super::error::{ArgumentList, SceneError};
use super::parse::RawPrimitive;
use super::xform::parse_transform;
use std::path::PathBuf;

/// What every function modifier carries: its expressions, its file, its transform and its
/// real arguments `A1 ..`.
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionArgs {
    /// The expressions named by the type (`rvarname gvarname bvarname` for colorfunc, ...),
    /// each a `.cal` expression, usually a variable name.
    pub expressions: Vec<String>,
    /// The function file as written (`.` for none), found through RAYPATH by the engine.
    pub cal_file: String,
    /// The directory of the scene file that names it (searched after RAYPATH).
    pub scene_dir: PathBuf,
    pub transform: FunctionTransform,
    /// Every real argument (`arg(1)` is the first, BRTDfunc's `rdf` included).
    pub real_args: Vec<f64>,
}

/// The transform that takes a function's coordinates to the scene's: kept as its inverse,
/// which RADIANCE applies to the hit (`func.c`: `funcxf` from `invxf`), and the forward one,
/// which it applies to a texture's perturbation (`t_func.c`).
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionTransform {
    /// Scene to function coordinates; points are row vectors, translation in row 3.
    pub inverse: [[f64; 4]; 4],
    /// Function to scene coordinates.
    pub forward: [[f64; 4]; 4],
    /// `|scale|` of the transform (`-s`), RADIANCE's `S` is its inverse's.
    pub scale: f64,
}

impl FunctionTransform {
    pub const IDENTITY: FunctionTransform = FunctionTransform {
        inverse: IDENTITY,
        forward: IDENTITY,
        scale: 1.0,
    };
}

const IDENTITY: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// `BRTDfunc`: a thin surface with specular reflection and transmission given by
/// expressions, Lambertian parts given by reals, and a directional-diffuse part seen from
/// light sources (manual §2.1.2 "BRTDfunc", `src/rt/m_brdf.c`).
#[derive(Clone, Debug, PartialEq)]
pub struct BrtdFunc {
    /// Nine expressions: specular reflection r g b, specular transmission r g b, and the
    /// directional-diffuse functions r g b of (lx, ly, lz) (`0` for none).
    pub function: FunctionArgs,
    /// Diffuse reflectance of the front (`rdf gdf bdf`).
    pub front_diffuse_rgb: glam::DVec3,
    /// Diffuse reflectance of the back (`rdb gdb bdb`).
    pub back_diffuse_rgb: glam::DVec3,
    /// Diffuse transmittance (`rdt gdt bdt`).
    pub diffuse_transmittance_rgb: glam::DVec3,
}

/// Reads `expression_count` expressions, the file and the transform of a function
/// modifier, with its real arguments from `first_real` on.
pub(crate) fn function_args(
    raw: &RawPrimitive<'_>,
    expression_count: usize,
    synopsis: &str,
) -> Result<FunctionArgs, SceneError> {
    raw.check_count(
        ArgumentList::String,
        raw.strings.len() > expression_count,
        format!("at least {} ({synopsis})", expression_count + 1),
    )?;
    raw.check_no_integers()?;
    let words: Vec<String> = raw.strings[expression_count + 1..]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let transform = transform(raw, &words)?;
    let scene_dir = raw.at.file.parent().map(PathBuf::from).unwrap_or_default();
    Ok(FunctionArgs {
        expressions: raw.strings[..expression_count]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        cal_file: raw.strings[expression_count].to_string(),
        scene_dir,
        transform,
        real_args: raw.reals.clone(),
    })
}

/// The transform words after the file: all of them must be transform options.
fn transform(raw: &RawPrimitive<'_>, words: &[String]) -> Result<FunctionTransform, SceneError> {
    if words.is_empty() {
        return Ok(FunctionTransform::IDENTITY);
    }
    let bad = |message: String| raw.invalid("transform", words.join(" "), message);
    let (forward, used) = parse_transform(words).map_err(bad)?;
    if used != words.len() {
        return Err(bad(format!(
            "transform options (-t -rx -ry -rz -s -mx -my -mz -i); `{}` is not one",
            words[used]
        )));
    }
    Ok(FunctionTransform {
        inverse: forward.matrix.inverse_similarity(forward.scale),
        forward: forward.matrix.rows(),
        scale: forward.scale.abs(),
    })
}

/// `BRTDfunc`'s arguments.
pub(crate) fn brtd(raw: &RawPrimitive<'_>) -> Result<BrtdFunc, SceneError> {
    let function = function_args(
        raw,
        9,
        "rrefl grefl brefl rtrns gtrns btrns rbrtd gbrtd bbrtd funcfile [transform]",
    )?;
    raw.check_count(
        ArgumentList::Real,
        raw.reals.len() >= 9,
        "at least 9 (rdf gdf bdf rdb gdb bdb rdt gdt bdt [A10 ..])",
    )?;
    let r = &raw.reals;
    if let Some(i) = r[..9].iter().position(|&x| x < 0.0) {
        return Err(raw.invalid_real(i, "a reflectance or transmittance >= 0"));
    }
    let rgb = |i: usize| glam::DVec3::new(r[i], r[i + 1], r[i + 2]);
    Ok(BrtdFunc {
        front_diffuse_rgb: rgb(0),
        back_diffuse_rgb: rgb(3),
        diffuse_transmittance_rgb: rgb(6),
        function,
    })
}

/// `brightdata` and `colordata`: patterns interpolated in data files (manual §2.1.4,
/// `src/rt/p_data.c`).
#[derive(Clone, Debug, PartialEq)]
pub struct DataPattern {
    /// The functions applied to the interpolated values (1 for brightdata, r g b for
    /// colordata).
    pub functions: Vec<String>,
    /// The data files (1 or 3), found through RAYPATH by the engine.
    pub data_files: Vec<String>,
    /// The coordinate expressions (one per dimension of the data), the function file and
    /// the transform.
    pub function: FunctionArgs,
}

/// Words that start a transform (`xf` options).
const TRANSFORM_OPTIONS: [&str; 9] = ["-t", "-rx", "-ry", "-rz", "-s", "-mx", "-my", "-mz", "-i"];

/// `colorpict` (`rfunc gfunc bfunc picture funcfile u v [transform]`, `first` 0, 3
/// `channels`) and `mixpict` (`foreground background func picture funcfile u v
/// [transform]`, `first` 2, 1 channel), as p_data.c `p_pdata` and mx_data.c `mx_pdata` read
/// them: kept as a data pattern of one file whose coordinates are v then u, the order in
/// which RADIANCE indexes the picture (y major).
pub(crate) fn picture_pattern(
    raw: &RawPrimitive<'_>,
    first: usize,
    channels: usize,
) -> Result<DataPattern, SceneError> {
    let picture = first + channels;
    let synopsis = if first > 0 {
        "foreground background func picture funcfile u v [transform]"
    } else {
        "rfunc gfunc bfunc picture funcfile u v [transform]"
    };
    raw.check_count(
        ArgumentList::String,
        raw.strings.len() >= picture + 4,
        format!("at least {} ({synopsis})", picture + 4),
    )?;
    raw.check_no_integers()?;
    let words: Vec<String> = raw.strings[picture + 4..]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let scene_dir = raw.at.file.parent().map(PathBuf::from).unwrap_or_default();
    Ok(DataPattern {
        functions: raw.strings[first..picture]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        data_files: vec![raw.strings[picture].to_string()],
        function: FunctionArgs {
            expressions: vec![
                raw.strings[picture + 3].to_string(),
                raw.strings[picture + 2].to_string(),
            ],
            cal_file: raw.strings[picture + 1].to_string(),
            scene_dir,
            transform: transform(raw, &words)?,
            real_args: raw.reals.clone(),
        },
    })
}

/// `func.. datafile.. funcfile x1 .. xn [transform]` with `channels` functions and files.
pub(crate) fn data_pattern(
    raw: &RawPrimitive<'_>,
    channels: usize,
) -> Result<DataPattern, SceneError> {
    data_pattern_after(raw, channels, 0)
}

/// [`data_pattern`] from string argument `first` on (`mixdata` names its two modifiers
/// first).
pub(crate) fn data_pattern_after(
    raw: &RawPrimitive<'_>,
    channels: usize,
    first: usize,
) -> Result<DataPattern, SceneError> {
    let names = first + 2 * channels;
    let synopsis = if first > 0 {
        "foreground background func datafile funcfile x1 .. xn [transform]"
    } else if channels == 1 {
        "func datafile funcfile x1 .. xn [transform]"
    } else {
        "rfunc gfunc bfunc rdatafile gdatafile bdatafile funcfile x1 .. xn [transform]"
    };
    raw.check_count(
        ArgumentList::String,
        raw.strings.len() > names + 1,
        format!("at least {} ({synopsis})", names + 2),
    )?;
    raw.check_no_integers()?;
    let after_file = &raw.strings[names + 1..];
    let coordinates = after_file
        .iter()
        .position(|w| TRANSFORM_OPTIONS.contains(w))
        .unwrap_or(after_file.len());
    let words: Vec<String> = after_file[coordinates..]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let scene_dir = raw.at.file.parent().map(PathBuf::from).unwrap_or_default();
    Ok(DataPattern {
        functions: raw.strings[first..first + channels]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        data_files: raw.strings[first + channels..names]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        function: FunctionArgs {
            expressions: after_file[..coordinates]
                .iter()
                .map(|s| s.to_string())
                .collect(),
            cal_file: raw.strings[names].to_string(),
            scene_dir,
            transform: transform(raw, &words)?,
            real_args: raw.reals.clone(),
        },
    })
}
