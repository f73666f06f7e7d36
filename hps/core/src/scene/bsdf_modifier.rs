//! `BSDF` and `aBSDF`: materials whose scattering comes from a WINDOW / LBNL XML file
//! (RADIANCE reference manual §2.1.2 "BSDF"; RADIANCE `src/rt/m_bsdf.c`).
//!
//! `BSDF`: 6+ strings `thick BSDFfile ux uy uz funcfile [transform]`, 0 integers, 0, 3, 6 or
//! 9 reals (extra diffuse reflectance front, back, then transmittance, RGB each). `aBSDF` has
//! no thickness. The file is looked up as RADIANCE's `getpath` does with `RAYPATH`, "."
//! being where `oconv`/`rtrace` would run: the directory of the top-level scene file.

use super::error::ArgumentList;
use super::parse::{PrimitiveType, RawPrimitive};
use super::SceneError;
use glam::DVec3;
use std::path::{Path, PathBuf};

/// Which of the two types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BsdfType {
    /// `BSDF`: thin (thickness 0) or a proxy for detailed geometry (non-zero thickness).
    Bsdf,
    /// `aBSDF`: thin, with its strong "through" component passing view and shadow rays.
    ABsdf,
}

/// The arguments of a `BSDF` or `aBSDF` modifier.
#[derive(Clone, Debug, PartialEq)]
pub struct BsdfModifier {
    pub kind: BsdfType,
    /// Signed thickness of the proxied layer (`thick`); 0 for a thin surface and for aBSDF.
    pub thickness_m: f64,
    /// The XML file as the scene names it.
    pub xml_name: String,
    /// Where it was found.
    pub xml_path: PathBuf,
    /// The up vector orienting the BSDF's frame on the surface (`ux uy uz`).
    pub up: DVec3,
    /// Extra Lambertian reflectance on the front and back, and transmittance, added to the
    /// file's (`rdf gdf bdf`, `rdb gdb bdb`, `rdt gdt bdt`; zero when absent).
    pub extra_reflectance_front_rgb: DVec3,
    pub extra_reflectance_back_rgb: DVec3,
    pub extra_transmittance_rgb: DVec3,
}

/// Reads a `BSDF`/`aBSDF` primitive; `top_file` is the top-level scene file (RADIANCE's
/// working directory is its directory).
pub(crate) fn build(raw: &RawPrimitive<'_>, top_file: &Path) -> Result<BsdfModifier, SceneError> {
    let kind = if raw.kind == PrimitiveType::ABsdf {
        BsdfType::ABsdf
    } else {
        BsdfType::Bsdf
    };
    let skip = usize::from(kind == BsdfType::Bsdf);
    raw.check_count(
        ArgumentList::String,
        raw.strings.len() >= skip + 5,
        if skip == 1 {
            "at least 6 (thick BSDFfile ux uy uz funcfile [transform])"
        } else {
            "at least 5 (BSDFfile ux uy uz funcfile [transform])"
        },
    )?;
    raw.check_no_integers()?;
    let r = &raw.reals;
    raw.check_count(
        ArgumentList::Real,
        r.len() <= 9 && r.len() % 3 == 0,
        "0, 3, 6 or 9 (extra diffuse rgb front, back, transmitted)",
    )?;
    for (i, v) in r.iter().enumerate() {
        if *v < 0.0 {
            return Err(raw.invalid_real(i, "a reflectance or transmittance >= 0"));
        }
    }
    let s = &raw.strings;
    let function_file = s[skip + 4];
    if function_file != "." || s.len() > skip + 5 {
        return Err(raw.invalid(
            format!(
                "string argument {} onwards (function file, transform)",
                skip + 5
            ),
            s[skip + 4..].join(" "),
            "`.` alone: function files and transforms of BSDF materials are not read yet",
        ));
    }
    let number = |i: usize, what: &str| -> Result<f64, SceneError> {
        s[i].parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| {
                raw.invalid(
                    format!("string argument {} ({what})", i + 1),
                    s[i],
                    "a number (variables need a function file, not read yet)",
                )
            })
    };
    let thickness_m = if skip == 1 { number(0, "thick")? } else { 0.0 };
    let up = DVec3::new(
        number(skip + 1, "ux")?,
        number(skip + 2, "uy")?,
        number(skip + 3, "uz")?,
    );
    if up.length_squared() <= 0.0 {
        return Err(raw.invalid("up vector", "0 0 0", "a non-zero vector"));
    }
    let xml_name = s[skip].to_string();
    let xml_path = find_xml(&xml_name, &raw.at.file, top_file).ok_or_else(|| {
        raw.invalid(
            format!("string argument {} (BSDF file)", skip + 1),
            xml_name.as_str(),
            format!(
                "an existing file (looked in {}, beside {} and on RAYPATH)",
                run_directory(top_file).display(),
                run_directory(&raw.at.file).display()
            ),
        )
    })?;
    let rgb = |k: usize| {
        r.get(3 * k..3 * k + 3)
            .map_or(DVec3::ZERO, |c| DVec3::new(c[0], c[1], c[2]))
    };
    Ok(BsdfModifier {
        kind,
        thickness_m: if thickness_m.abs() <= 1e-6 {
            0.0 // m_bsdf.c: |thick| <= FTINY is no thickness
        } else {
            thickness_m
        },
        xml_name,
        xml_path,
        up,
        extra_reflectance_front_rgb: rgb(0),
        extra_reflectance_back_rgb: rgb(1),
        extra_transmittance_rgb: rgb(2),
    })
}

/// The directory a scene file's relative names are taken from.
fn run_directory(file: &Path) -> PathBuf {
    match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// RADIANCE's `getpath`: an absolute name as it is; a name starting with `.` from the working
/// directory only; any other name from each `RAYPATH` entry ("." by default). Skylux's
/// working directory is the top-level file's; the naming file's own directory is tried after
/// it, as for every file a scene names.
fn find_xml(name: &str, naming_file: &Path, top_file: &Path) -> Option<PathBuf> {
    let path = Path::new(name);
    let exists = |p: &Path| p.is_file().then(|| p.to_path_buf());
    if path.is_absolute() {
        return exists(path);
    }
    let run = run_directory(top_file);
    let mut candidates = vec![run.join(path), run_directory(naming_file).join(path)];
    if !name.starts_with('.') {
        if let Some(raypath) = std::env::var_os("RAYPATH") {
            candidates.extend(std::env::split_paths(&raypath).map(|dir| {
                if dir == Path::new(".") {
                    run.join(path)
                } else {
                    dir.join(path)
                }
            }));
        }
    }
    candidates.iter().find_map(|c| exists(c))
}
