//! `BSDF` and `aBSDF`: materials whose scattering comes from a WINDOW / LBNL XML file
//! (RADIANCE reference manual §2.1.2 "BSDF"; RADIANCE `src/rt/m_bsdf.c`).
//!
//! `BSDF`: 6+ strings `thick BSDFfile ux uy uz funcfile [transform]`, 0 integers, 0, 3, 6 or
//! 9 reals (extra diffuse reflectance front, back, then transmittance, RGB each). `aBSDF` has
//! no thickness. The file is looked up as RADIANCE's `getpath` does with `RAYPATH`, "."
//! being where `oconv`/`rtrace` would run ([`super::LoadOptions::working_directory`]).

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
    /// `aBSDF`: thin, with its strong "through" component passing view and shadow rays
    /// (`engine::material::bsdf`, `bsdf::Through`).
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

/// Reads a `BSDF`/`aBSDF` primitive; `top_file` is the top-level scene file being read,
/// `working_directory` where RADIANCE would run (None: the process's).
pub(crate) fn build(
    raw: &RawPrimitive<'_>,
    top_file: &Path,
    working_directory: Option<&Path>,
) -> Result<BsdfModifier, SceneError> {
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
        r.len() <= 9 && r.len().is_multiple_of(3),
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
    let run = working_directory.map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let searched = super::files::search_directories(&xml_name, &run, &raw.at.file, top_file);
    let xml_path = searched
        .iter()
        .map(|dir| dir.join(&xml_name))
        .find(|p| Path::new(&xml_name).is_absolute() || p.is_file())
        .filter(|p| p.is_file())
        .ok_or_else(|| {
            let dirs: Vec<String> = searched.iter().map(|d| d.display().to_string()).collect();
            raw.invalid(
                format!("string argument {} (BSDF file)", skip + 1),
                xml_name.as_str(),
                format!("an existing file (looked in: {})", dirs.join(", ")),
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
