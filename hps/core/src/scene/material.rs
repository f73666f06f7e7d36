//! Materials and patterns: the modifiers a surface can carry.
//!
//! Argument meanings are those of the RADIANCE reference manual (ray.html), §2.1.2
//! "Materials" and §2.1.4 "Patterns". Colours are RADIANCE's radiometric RGB, one value per
//! channel, kept as a `DVec3` (x = red, y = green, z = blue) so the engine can do channel-wise
//! arithmetic on them.

use super::brdf_material::{anisotropic, brdf_func, Anisotropic, BrdfFunc, NormalFamily};
use super::bsdf_modifier::{self, BsdfModifier};
use super::error::{ArgumentList, SceneError};
use super::function::{
    brtd, data_pattern, data_pattern_after, function_args, picture_pattern, BrtdFunc, DataPattern,
    FunctionArgs,
};
use super::parse::{PrimitiveType, RawPrimitive};
use super::text::{text_args, text_pattern, TextArgs, TextPattern};
use glam::DVec3;
use std::path::Path;

/// Index of a modifier in `Scene::modifiers`. A modifier always refers to modifiers with a
/// smaller index, so walking a chain of modifiers always ends.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ModifierId(usize);

impl ModifierId {
    pub(super) fn new(index: usize) -> Self {
        Self(index)
    }

    pub fn index(self) -> usize {
        self.0
    }
}

/// What a primitive names as its modifier: RADIANCE's built-in `void`, or the definition of
/// that name most recent at that point in the files (reference manual §2.1: later definitions
/// apply to the primitives after them and do not relink earlier ones).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum ModifierRef {
    Void,
    Defined(ModifierId),
}

/// Refractive index RADIANCE's `glass` uses when no fourth real argument is given.
pub const GLASS_DEFAULT_REFRACTIVE_INDEX: f64 = 1.52;

/// What a modifier is, with its arguments.
#[derive(Clone, Debug, PartialEq)]
pub enum ModifierKind {
    Plastic(Plastic),
    Metal(Metal),
    Trans(Trans),
    Glass(Glass),
    Mirror(Mirror),
    Light(Light),
    Glow(Glow),
    Brightfunc(Brightfunc),
    /// `BSDF` and `aBSDF` (`bsdf_modifier.rs`).
    Bsdf(BsdfModifier),
    Dielectric(Dielectric),
    Spotlight(Spotlight),
    Illum(Illum),
    Antimatter(Antimatter),
    Colorfunc(FunctionArgs),
    Brightdata(DataPattern),
    Colordata(DataPattern),
    /// `colorpict`: a RADIANCE picture as colour data (its one file is the picture, its
    /// coordinates y then x).
    Colorpict(DataPattern),
    Texfunc(FunctionArgs),
    Mixfunc(Mixfunc),
    /// `texdata`: a texture from three data files (t_data.c).
    Texdata(DataPattern),
    Mixdata(Mixdata),
    /// `mixpict`: as `mixdata`, the coefficient a function of a picture's (r, g, b).
    Mixpict(Mixdata),
    BrtdFunc(BrtdFunc),
    /// `plasfunc`, `metfunc`, `transfunc`, `plasdata`, `metdata`, `transdata`.
    BrdfFunc(BrdfFunc),
    /// `plastic2`, `metal2`, `trans2`.
    Anisotropic(Anisotropic),
    /// `brighttext`: grey values inside and outside the glyphs of a text (`text.rs`).
    Brighttext(TextPattern),
    /// `colortext`: colours inside and outside the glyphs.
    Colortext(TextPattern),
    /// `mixtext`: one modifier inside the glyphs, another outside.
    Mixtext(Mixtext),
}

impl ModifierKind {
    /// The RADIANCE type name (`plastic`, `brightfunc`, ...).
    pub fn type_name(&self) -> &'static str {
        match self {
            ModifierKind::Plastic(_) => "plastic",
            ModifierKind::Metal(_) => "metal",
            ModifierKind::Trans(_) => "trans",
            ModifierKind::Glass(_) => "glass",
            ModifierKind::Mirror(_) => "mirror",
            ModifierKind::Light(_) => "light",
            ModifierKind::Glow(_) => "glow",
            ModifierKind::Brightfunc(_) => "brightfunc",
            ModifierKind::Bsdf(b) => match b.kind {
                bsdf_modifier::BsdfType::Bsdf => "BSDF",
                bsdf_modifier::BsdfType::ABsdf => "aBSDF",
            },
            ModifierKind::Dielectric(d) if d.is_interface => "interface",
            ModifierKind::Dielectric(_) => "dielectric",
            ModifierKind::Spotlight(_) => "spotlight",
            ModifierKind::Illum(_) => "illum",
            ModifierKind::Antimatter(_) => "antimatter",
            ModifierKind::Colorfunc(_) => "colorfunc",
            ModifierKind::Brightdata(_) => "brightdata",
            ModifierKind::Colordata(_) => "colordata",
            ModifierKind::Colorpict(_) => "colorpict",
            ModifierKind::Texfunc(_) => "texfunc",
            ModifierKind::Mixfunc(_) => "mixfunc",
            ModifierKind::Texdata(_) => "texdata",
            ModifierKind::Mixdata(_) => "mixdata",
            ModifierKind::Mixpict(_) => "mixpict",
            ModifierKind::BrtdFunc(_) => "BRTDfunc",
            ModifierKind::BrdfFunc(f) => match (f.fractions.family, f.data.is_some()) {
                (NormalFamily::Plastic, false) => "plasfunc",
                (NormalFamily::Metal, false) => "metfunc",
                (NormalFamily::Trans, false) => "transfunc",
                (NormalFamily::Plastic, true) => "plasdata",
                (NormalFamily::Metal, true) => "metdata",
                (NormalFamily::Trans, true) => "transdata",
            },
            ModifierKind::Anisotropic(a) => match a.fractions.family {
                NormalFamily::Plastic => "plastic2",
                NormalFamily::Metal => "metal2",
                NormalFamily::Trans => "trans2",
            },
            ModifierKind::Brighttext(_) => "brighttext",
            ModifierKind::Colortext(_) => "colortext",
            ModifierKind::Mixtext(_) => "mixtext",
        }
    }

    /// Materials decide how a surface scatters or emits light; patterns (`brightfunc`,
    /// `colorfunc`) scale and textures (`texfunc`) tilt the material they modify.
    /// A mixture is a material unless both its sides are patterns ([`Mixfunc::pattern`]).
    pub fn is_material(&self) -> bool {
        match self {
            ModifierKind::Mixfunc(m) => !m.pattern,
            ModifierKind::Mixdata(m) | ModifierKind::Mixpict(m) => !m.pattern,
            ModifierKind::Mixtext(m) => !m.pattern,
            _ => !matches!(
                self,
                ModifierKind::Brightfunc(_)
                    | ModifierKind::Colorfunc(_)
                    | ModifierKind::Brightdata(_)
                    | ModifierKind::Colordata(_)
                    | ModifierKind::Colorpict(_)
                    | ModifierKind::Texfunc(_)
                    | ModifierKind::Texdata(_)
                    | ModifierKind::Brighttext(_)
                    | ModifierKind::Colortext(_)
            ),
        }
    }

    /// Modifiers whose values are evaluated at each hit (`.cal` expressions, data files,
    /// pictures, text): the engine builds them in `engine::function` (a `brightfunc` on a `light`
    /// or `glow` aside, which is a sky function).
    pub fn is_evaluated(&self) -> bool {
        matches!(
            self,
            ModifierKind::Brightfunc(_)
                | ModifierKind::Colorfunc(_)
                | ModifierKind::Brightdata(_)
                | ModifierKind::Colordata(_)
                | ModifierKind::Colorpict(_)
                | ModifierKind::Texfunc(_)
                | ModifierKind::Texdata(_)
                | ModifierKind::Mixfunc(_)
                | ModifierKind::Mixdata(_)
                | ModifierKind::Mixpict(_)
                | ModifierKind::BrtdFunc(_)
                | ModifierKind::BrdfFunc(_)
                | ModifierKind::Anisotropic(_)
                | ModifierKind::Brighttext(_)
                | ModifierKind::Colortext(_)
                | ModifierKind::Mixtext(_)
        )
    }

    /// Marks a mixture whose two sides reach no material (`reaches_material` follows a
    /// side's chain) as a pattern, as RADIANCE's `raymixture` treats it.
    pub(crate) fn settle_mixture(&mut self, reaches_material: impl Fn(ModifierRef) -> bool) {
        let sides_are_patterns =
            |f: ModifierRef, b: ModifierRef| !reaches_material(f) && !reaches_material(b);
        match self {
            ModifierKind::Mixfunc(m) => m.pattern = sides_are_patterns(m.foreground, m.background),
            ModifierKind::Mixdata(m) | ModifierKind::Mixpict(m) => {
                m.pattern = sides_are_patterns(m.foreground, m.background)
            }
            ModifierKind::Mixtext(m) => m.pattern = sides_are_patterns(m.foreground, m.background),
            _ => {}
        }
    }
}

/// `plastic`: diffuse reflection with uncoloured highlights (manual §2.1.2, "Plastic").
#[derive(Clone, Debug, PartialEq)]
pub struct Plastic {
    /// Diffuse reflectance per channel (`red green blue`).
    pub reflectance_rgb: DVec3,
    /// Fraction of reflection that is specular (`spec`), 0..=1.
    pub specularity: f64,
    /// RMS slope of the surface facets (`rough`); 0 is perfectly smooth.
    pub roughness: f64,
}

/// `metal`: as plastic, but highlights take the material colour (manual §2.1.2, "Metal").
#[derive(Clone, Debug, PartialEq)]
pub struct Metal {
    /// Reflectance per channel (`red green blue`), also colouring the specular part.
    pub reflectance_rgb: DVec3,
    /// Fraction of reflection that is specular (`spec`), 0..=1.
    pub specularity: f64,
    /// RMS slope of the surface facets (`rough`).
    pub roughness: f64,
}

/// `trans`: infinitely thin translucent material (manual §2.1.2, "Trans").
#[derive(Clone, Debug, PartialEq)]
pub struct Trans {
    /// Material colour (`red green blue`), applied to diffuse reflection and transmission.
    pub color_rgb: DVec3,
    /// Fraction of reflection that is specular (`spec`), 0..=1.
    pub specularity: f64,
    /// RMS slope of the surface facets (`rough`).
    pub roughness: f64,
    /// Fraction of penetrating light that travels all the way through (`trans`), 0..=1.
    pub transmissivity: f64,
    /// Fraction of transmitted light that is not diffusely scattered (`tspec`), 0..=1.
    pub transmitted_specularity: f64,
}

/// `glass`: thin glazing, one transmitted and one reflected ray (manual §2.1.2, "Glass").
#[derive(Clone, Debug, PartialEq)]
pub struct Glass {
    /// Transmissivity at normal incidence per channel (`rtn gtn btn`): light not absorbed in
    /// one traversal. Not the measured transmittance Tn; the manual gives the conversion.
    pub transmissivity_rgb: DVec3,
    /// Index of refraction (optional fourth real; [`GLASS_DEFAULT_REFRACTIVE_INDEX`] if absent).
    pub refractive_index: f64,
}

/// `mirror`: planar specular reflector that creates virtual sources (manual §2.1.2, "Mirror").
#[derive(Clone, Debug, PartialEq)]
pub struct Mirror {
    /// Reflectance per channel (`red green blue`).
    pub reflectance_rgb: DVec3,
    /// Optional material used to shade non-source rays (the one string argument); `void`
    /// makes the mirror invisible to them.
    pub alternate_material: Option<ModifierRef>,
}

/// `light`: self-luminous surface (manual §2.1.2, "Light").
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Radiance per channel in W/(sr·m²) (`red green blue`).
    pub radiance_w_sr_m2: DVec3,
}

/// `glow`: self-luminous surface with a limited effect (manual §2.1.2, "Glow"). gensky skies
/// use it for the sky and ground hemispheres.
#[derive(Clone, Debug, PartialEq)]
pub struct Glow {
    /// Radiance per channel in W/(sr·m²) (`red green blue`).
    pub radiance_w_sr_m2: DVec3,
    /// Maximum radius for shadow testing (`maxrad`): 0 means never tested for shadow (only
    /// seen through interreflection), negative means it never illuminates the scene.
    pub max_radius_m: f64,
}

/// `brightfunc`: a pattern scaling the modified material by a function (manual §2.1.4,
/// "Brightfunc"). Kept generic; the engine interprets `skyfunc` from `skybright.cal` and
/// `perezlum.cal`.
#[derive(Clone, Debug, PartialEq)]
pub struct Brightfunc {
    /// The function or variable to evaluate (`refname`), e.g. `skybright`.
    pub function_name: String,
    /// The function file (`funcfile`), e.g. `skybright.cal`; `.` means none.
    pub cal_file: String,
    /// Transform words after the file (`xform` syntax, e.g. `-rz 90`), unparsed.
    pub transform: Vec<String>,
    /// The real arguments `A1 .. An` made available to the function.
    pub real_args: Vec<f64>,
    /// The same, as the engine compiles it on a surface that is not a sky.
    pub function: FunctionArgs,
}

/// `mixfunc`: blends two modifiers by a coefficient (manual §2.1.6).
#[derive(Clone, Debug, PartialEq)]
pub struct Mixfunc {
    /// Used where the coefficient is 1 (`void`: nothing).
    pub foreground: ModifierRef,
    /// Used where the coefficient is 0.
    pub background: ModifierRef,
    /// One expression: the coefficient.
    pub function: FunctionArgs,
    /// Both sides are patterns, textures or `void` (none reaches a material): the mixture
    /// is a pattern that blends their colours and perturbations (raytrace.c `raymixture`).
    pub pattern: bool,
}

/// `mixdata`: blends two modifiers by a coefficient interpolated in a data file and passed
/// through a function (manual §2.1.6, `src/rt/mx_data.c`).
#[derive(Clone, Debug, PartialEq)]
pub struct Mixdata {
    pub foreground: ModifierRef,
    pub background: ModifierRef,
    /// One function (of the interpolated value), one data file, the coordinates.
    pub data: DataPattern,
    /// As [`Mixfunc::pattern`].
    pub pattern: bool,
}

/// `mixtext`: the foreground modifier inside the glyphs of a text, the background one
/// elsewhere (manual §2.1.6, `src/rt/text.c`).
#[derive(Clone, Debug, PartialEq)]
pub struct Mixtext {
    pub foreground: ModifierRef,
    pub background: ModifierRef,
    /// The font, the text and where it lies (`text.rs`).
    pub text: TextArgs,
    /// As [`Mixfunc::pattern`].
    pub pattern: bool,
}

/// Refractive index RADIANCE's `dielectric` adds per unit of Hartmann constant: the constant
/// is divided by the mean wavelength, 500 nm (dielectric.c `MLAMBDA`).
pub const HARTMANN_MEAN_WAVELENGTH_NM: f64 = 500.0;

/// One side of a refracting boundary: a medium's index and transmission.
#[derive(Clone, Debug, PartialEq)]
pub struct Medium {
    /// Fraction of light left after one metre in the medium, per channel (the manual's
    /// "transmission coefficient per unit length"; 1 or more: no absorption).
    pub transmission_per_m_rgb: DVec3,
    pub refractive_index: f64,
}

impl Medium {
    /// Vacuum, what surrounds a `dielectric` (manual §2.1.2, "Interface").
    pub const VACUUM: Medium = Medium {
        transmission_per_m_rgb: DVec3::ONE,
        refractive_index: 1.0,
    };
}

/// `dielectric` or `interface`: a boundary that refracts and reflects by Fresnel's equations
/// (manual §2.1.2, "Dielectric", "Interface"). The inside is behind the surface normal.
#[derive(Clone, Debug, PartialEq)]
pub struct Dielectric {
    pub inside: Medium,
    /// Vacuum for a `dielectric`.
    pub outside: Medium,
    /// Written as `interface` (two media) rather than `dielectric`.
    pub is_interface: bool,
}

/// `spotlight`: a `light` that emits only inside a cone (manual §2.1.2, "Spotlight").
#[derive(Clone, Debug, PartialEq)]
pub struct Spotlight {
    /// Radiance per channel in W/(sr·m²) inside the cone.
    pub radiance_w_sr_m2: DVec3,
    /// Full cone angle in degrees.
    pub cone_angle_deg: f64,
    /// Unit output direction (the cone's axis).
    pub direction: DVec3,
    /// Length of the given direction vector: the focal length behind the source centre,
    /// which RADIANCE uses only for distant spotlights.
    pub focal_length_m: f64,
}

/// `illum`: a secondary source (manual §2.1.2, "Illum"): light for direct sampling, and its
/// alternate material (or nothing) to every other ray.
#[derive(Clone, Debug, PartialEq)]
pub struct Illum {
    pub radiance_w_sr_m2: DVec3,
    /// The material it looks like when not sampled as a source; None or `void`: invisible.
    pub alternate_material: Option<ModifierRef>,
}

/// `antimatter`: a volume inside which the surfaces of the listed modifiers vanish (manual
/// §2.1.2, "Antimatter").
#[derive(Clone, Debug, PartialEq)]
pub struct Antimatter {
    /// The modifiers subtracted, at least one; the first also shades the antimatter's own
    /// surface where a ray leaves it into the regular volume (`void`: invisible).
    pub subtracted: Vec<ModifierRef>,
}

/// `plastic` and `metal`: 5 reals (colour, specularity, roughness).
fn plastic_or_metal(raw: &RawPrimitive<'_>) -> Result<ModifierKind, SceneError> {
    let r = &raw.reals;
    let rgb = |i: usize| DVec3::new(r[i], r[i + 1], r[i + 2]);
    raw.check_no_strings_or_integers()?;
    raw.check_real_count()?;
    non_negative(raw, 0..3, "a reflectance >= 0")?;
    unit_interval(raw, 3)?;
    non_negative(raw, 4..5, "a roughness >= 0")?;
    Ok(if raw.kind == PrimitiveType::Plastic {
        ModifierKind::Plastic(Plastic {
            reflectance_rgb: rgb(0),
            specularity: r[3],
            roughness: r[4],
        })
    } else {
        ModifierKind::Metal(Metal {
            reflectance_rgb: rgb(0),
            specularity: r[3],
            roughness: r[4],
        })
    })
}

/// `trans`: 7 reals (colour, specularity, roughness, transmissivity, transmitted specularity).
fn trans(raw: &RawPrimitive<'_>) -> Result<ModifierKind, SceneError> {
    let r = &raw.reals;
    let rgb = |i: usize| DVec3::new(r[i], r[i + 1], r[i + 2]);
    raw.check_no_strings_or_integers()?;
    raw.check_real_count()?;
    non_negative(raw, 0..3, "a colour component >= 0")?;
    unit_interval(raw, 3)?;
    non_negative(raw, 4..5, "a roughness >= 0")?;
    unit_interval(raw, 5)?;
    unit_interval(raw, 6)?;
    Ok(ModifierKind::Trans(Trans {
        color_rgb: rgb(0),
        specularity: r[3],
        roughness: r[4],
        transmissivity: r[5],
        transmitted_specularity: r[6],
    }))
}

/// `glass`: 3 transmissivities and an optional refractive index.
fn glass(raw: &RawPrimitive<'_>) -> Result<ModifierKind, SceneError> {
    let r = &raw.reals;
    let rgb = |i: usize| DVec3::new(r[i], r[i + 1], r[i + 2]);
    raw.check_no_strings_or_integers()?;
    raw.check_count(
        ArgumentList::Real,
        r.len() == 3 || r.len() == 4,
        "3 or 4 (rtn gtn btn [n])",
    )?;
    non_negative(raw, 0..3, "a transmissivity >= 0")?;
    let refractive_index = match r.get(3) {
        Some(&n) if n > 0.0 => n,
        Some(_) => return Err(raw.invalid_real(3, "a refractive index > 0")),
        None => GLASS_DEFAULT_REFRACTIVE_INDEX,
    };
    Ok(ModifierKind::Glass(Glass {
        transmissivity_rgb: rgb(0),
        refractive_index,
    }))
}

/// Interprets a modifier primitive. `resolve` looks up modifier names referenced in string
/// arguments (mirror's alternate material) as defined before this primitive; `top_file` is
/// the top-level scene file being read, `working_directory` where RADIANCE would run (both
/// for the files a modifier names).
pub(crate) fn build(
    raw: &RawPrimitive<'_>,
    resolve: &dyn Fn(&str) -> Option<ModifierRef>,
    top_file: &Path,
    working_directory: Option<&Path>,
) -> Result<ModifierKind, SceneError> {
    let r = &raw.reals;
    let rgb = |i: usize| DVec3::new(r[i], r[i + 1], r[i + 2]);
    Ok(match raw.kind {
        PrimitiveType::Plastic | PrimitiveType::Metal => plastic_or_metal(raw)?,
        PrimitiveType::Trans => trans(raw)?,
        PrimitiveType::Glass => glass(raw)?,
        PrimitiveType::Mirror => {
            let alternate_material = optional_alternate(raw, resolve)?;
            raw.check_real_count()?;
            non_negative(raw, 0..3, "a reflectance >= 0")?;
            ModifierKind::Mirror(Mirror {
                reflectance_rgb: rgb(0),
                alternate_material,
            })
        }
        PrimitiveType::Light => {
            raw.check_no_strings_or_integers()?;
            raw.check_real_count()?;
            ModifierKind::Light(Light {
                radiance_w_sr_m2: rgb(0),
            })
        }
        PrimitiveType::Glow => {
            raw.check_no_strings_or_integers()?;
            raw.check_real_count()?;
            ModifierKind::Glow(Glow {
                radiance_w_sr_m2: rgb(0),
                max_radius_m: r[3],
            })
        }
        PrimitiveType::Brightfunc => {
            raw.check_count(
                ArgumentList::String,
                raw.strings.len() >= 2,
                "at least 2 (refname funcfile [transform])",
            )?;
            let function = super::function::function_args(raw, 1, "refname funcfile [transform]")?;
            ModifierKind::Brightfunc(Brightfunc {
                function,
                function_name: raw.strings[0].to_string(),
                cal_file: raw.strings[1].to_string(),
                transform: raw.strings[2..].iter().map(|s| s.to_string()).collect(),
                real_args: r.clone(),
            })
        }
        PrimitiveType::Bsdf | PrimitiveType::ABsdf => {
            ModifierKind::Bsdf(bsdf_modifier::build(raw, top_file, working_directory)?)
        }
        PrimitiveType::Dielectric | PrimitiveType::Interface => {
            ModifierKind::Dielectric(dielectric(raw)?)
        }
        PrimitiveType::Spotlight => ModifierKind::Spotlight(spotlight(raw)?),
        PrimitiveType::Illum => ModifierKind::Illum(Illum {
            alternate_material: optional_alternate(raw, resolve)?,
            radiance_w_sr_m2: {
                raw.check_real_count()?;
                rgb(0)
            },
        }),
        PrimitiveType::Antimatter => ModifierKind::Antimatter(antimatter(raw, resolve)?),
        PrimitiveType::Colorfunc
        | PrimitiveType::Brightdata
        | PrimitiveType::Colordata
        | PrimitiveType::Colorpict
        | PrimitiveType::Texfunc
        | PrimitiveType::Mixfunc
        | PrimitiveType::Texdata
        | PrimitiveType::Mixdata
        | PrimitiveType::Mixpict
        | PrimitiveType::BrtdFunc => function_modifier(raw, resolve)?,
        PrimitiveType::Plasfunc
        | PrimitiveType::Metfunc
        | PrimitiveType::Transfunc
        | PrimitiveType::Plasdata
        | PrimitiveType::Metdata
        | PrimitiveType::Transdata => ModifierKind::BrdfFunc(brdf_func(raw)?),
        PrimitiveType::Plastic2 | PrimitiveType::Metal2 | PrimitiveType::Trans2 => {
            ModifierKind::Anisotropic(anisotropic(raw)?)
        }
        PrimitiveType::Brighttext => ModifierKind::Brighttext(text_pattern(raw)?),
        PrimitiveType::Colortext => ModifierKind::Colortext(text_pattern(raw)?),
        PrimitiveType::Mixtext => {
            let text = text_args(raw, 2)?;
            let (foreground, background) = mixture_sides(raw, resolve)?;
            ModifierKind::Mixtext(Mixtext {
                foreground,
                background,
                text,
                pattern: false,
            })
        }
        PrimitiveType::Polygon
        | PrimitiveType::Sphere
        | PrimitiveType::Cylinder
        | PrimitiveType::Ring
        | PrimitiveType::Cone
        | PrimitiveType::Source
        | PrimitiveType::Bubble
        | PrimitiveType::Tube
        | PrimitiveType::Cup => {
            return Err(raw.invalid(
                "type",
                raw.kind.name(),
                "a material or pattern (internal: surface passed to the material reader)",
            ))
        }
    })
}

/// The optional alternate material of `mirror` and `illum` (one string, a modifier defined
/// before), after checking there is no integer argument.
fn optional_alternate(
    raw: &RawPrimitive<'_>,
    resolve: &dyn Fn(&str) -> Option<ModifierRef>,
) -> Result<Option<ModifierRef>, SceneError> {
    raw.check_count(
        ArgumentList::String,
        raw.strings.len() <= 1,
        "0 or 1 (optional alternate material)",
    )?;
    raw.check_no_integers()?;
    raw.strings
        .first()
        .map(|name| {
            resolve(name).ok_or_else(|| SceneError::UnknownModifier {
                at: raw.at.clone(),
                primitive: raw.describe(),
                field: "string argument 1 (alternate material)",
                modifier: name.to_string(),
                hint: String::new(),
            })
        })
        .transpose()
}

/// `dielectric` (`rtn gtn btn n hc`, index n + hc/500 as dielectric.c computes it) or
/// `interface` (`rtn1 gtn1 btn1 n1 rtn2 gtn2 btn2 n2`, inside then outside).
fn dielectric(raw: &RawPrimitive<'_>) -> Result<Dielectric, SceneError> {
    raw.check_no_strings_or_integers()?;
    raw.check_real_count()?;
    let r = &raw.reals;
    let medium = |first: usize, index: f64| Medium {
        transmission_per_m_rgb: DVec3::new(r[first], r[first + 1], r[first + 2]),
        refractive_index: index,
    };
    let positive_index = |i: usize, n: f64| {
        if n > 0.0 {
            Ok(())
        } else {
            Err(raw.invalid_real(i, "a refractive index > 0"))
        }
    };
    if raw.kind == PrimitiveType::Interface {
        non_negative(raw, 0..3, "a transmission >= 0")?;
        non_negative(raw, 4..7, "a transmission >= 0")?;
        positive_index(3, r[3])?;
        positive_index(7, r[7])?;
        return Ok(Dielectric {
            inside: medium(0, r[3]),
            outside: medium(4, r[7]),
            is_interface: true,
        });
    }
    non_negative(raw, 0..3, "a transmission >= 0")?;
    let index = r[3] + r[4] / HARTMANN_MEAN_WAVELENGTH_NM;
    positive_index(3, index)?;
    Ok(Dielectric {
        inside: medium(0, index),
        outside: Medium::VACUUM,
        is_interface: false,
    })
}

/// `spotlight`: `red green blue angle xdir ydir zdir`.
fn spotlight(raw: &RawPrimitive<'_>) -> Result<Spotlight, SceneError> {
    raw.check_no_strings_or_integers()?;
    raw.check_real_count()?;
    let r = &raw.reals;
    if !(r[3] > 0.0 && r[3] <= 360.0) {
        return Err(raw.invalid_real(3, "a full cone angle in degrees, > 0 and <= 360"));
    }
    let given = DVec3::new(r[4], r[5], r[6]);
    let direction = super::shape::unit_vector(given).ok_or_else(|| {
        raw.invalid(
            "direction (real arguments 5-7, xdir ydir zdir)",
            format!("({} {} {})", r[4], r[5], r[6]),
            "a non-zero direction",
        )
    })?;
    Ok(Spotlight {
        radiance_w_sr_m2: DVec3::new(r[0], r[1], r[2]),
        cone_angle_deg: r[3],
        direction,
        focal_length_m: given.length(),
    })
}

/// `antimatter`: `N mod1 .. modN`, each a modifier defined before (or `void`).
fn antimatter(
    raw: &RawPrimitive<'_>,
    resolve: &dyn Fn(&str) -> Option<ModifierRef>,
) -> Result<Antimatter, SceneError> {
    raw.check_count(
        ArgumentList::String,
        !raw.strings.is_empty(),
        "at least 1 (the modifiers it subtracts)",
    )?;
    raw.check_no_integers()?;
    raw.check_count(ArgumentList::Real, raw.reals.is_empty(), "0 for antimatter")?;
    let subtracted = raw
        .strings
        .iter()
        .enumerate()
        .map(|(i, name)| {
            resolve(name).ok_or_else(|| SceneError::UnknownModifier {
                at: raw.at.clone(),
                primitive: raw.describe(),
                field: if i == 0 {
                    "string argument 1 (first subtracted modifier)"
                } else {
                    "a string argument (subtracted modifier)"
                },
                modifier: name.to_string(),
                hint: String::new(),
            })
        })
        .collect::<Result<_, _>>()?;
    Ok(Antimatter { subtracted })
}

/// `colorfunc`, `texfunc`, `mixfunc` or `BRTDfunc`, read from `raw`.
fn function_modifier(
    raw: &RawPrimitive<'_>,
    resolve: &dyn Fn(&str) -> Option<ModifierRef>,
) -> Result<ModifierKind, SceneError> {
    use super::parse::PrimitiveType as T;
    Ok(match raw.kind {
        T::Colorfunc => ModifierKind::Colorfunc(function_args(
            raw,
            3,
            "rvarname gvarname bvarname funcfile [transform]",
        )?),
        T::Texfunc => ModifierKind::Texfunc(function_args(
            raw,
            3,
            "xpert ypert zpert funcfile [transform]",
        )?),
        T::Mixfunc => {
            let function =
                function_args(raw, 3, "foreground background vname funcfile [transform]")?;
            let (foreground, background) = mixture_sides(raw, resolve)?;
            ModifierKind::Mixfunc(Mixfunc {
                foreground,
                background,
                function: FunctionArgs {
                    expressions: vec![function.expressions[2].clone()],
                    ..function
                },
                pattern: false,
            })
        }
        T::BrtdFunc => ModifierKind::BrtdFunc(brtd(raw)?),
        T::Texdata => ModifierKind::Texdata(data_pattern(raw, 3)?),
        T::Mixdata => {
            let data = data_pattern_after(raw, 1, 2)?;
            let (foreground, background) = mixture_sides(raw, resolve)?;
            ModifierKind::Mixdata(Mixdata {
                foreground,
                background,
                data,
                pattern: false,
            })
        }
        T::Brightdata => ModifierKind::Brightdata(data_pattern(raw, 1)?),
        T::Colordata => ModifierKind::Colordata(data_pattern(raw, 3)?),
        T::Colorpict => ModifierKind::Colorpict(picture_pattern(raw, 0, 3)?),
        T::Mixpict => {
            let data = picture_pattern(raw, 2, 1)?;
            let (foreground, background) = mixture_sides(raw, resolve)?;
            ModifierKind::Mixpict(Mixdata {
                foreground,
                background,
                data,
                pattern: false,
            })
        }
        _ => {
            return Err(raw.invalid(
                "type",
                raw.kind.name(),
                "a function modifier (internal: other type passed to the function reader)",
            ))
        }
    })
}

/// The two modifiers a `mixfunc` or `mixdata` names first, each defined before it or
/// `void` (its string count already checked).
fn mixture_sides(
    raw: &RawPrimitive<'_>,
    resolve: &dyn Fn(&str) -> Option<ModifierRef>,
) -> Result<(ModifierRef, ModifierRef), SceneError> {
    let side = |i: usize, field: &'static str| {
        let name = raw.strings[i];
        if name == "void" {
            return Ok(ModifierRef::Void);
        }
        resolve(name).ok_or_else(|| SceneError::UnknownModifier {
            at: raw.at.clone(),
            primitive: raw.describe(),
            field,
            modifier: name.to_string(),
            hint: String::new(),
        })
    };
    Ok((
        side(0, "string argument 1 (foreground)")?,
        side(1, "string argument 2 (background)")?,
    ))
}

/// Reflectances and transmissivities below zero have no physical meaning (RADIANCE accepts
/// them silently; a Monte-Carlo estimator would turn them into negative path weights).
fn non_negative(
    raw: &RawPrimitive<'_>,
    indices: std::ops::Range<usize>,
    expected: &str,
) -> Result<(), SceneError> {
    for i in indices {
        if raw.reals[i] < 0.0 {
            return Err(raw.invalid_real(i, expected));
        }
    }
    Ok(())
}

/// Fractions (`spec`, `trans`, `tspec`) must lie in 0..=1.
fn unit_interval(raw: &RawPrimitive<'_>, index: usize) -> Result<(), SceneError> {
    if (0.0..=1.0).contains(&raw.reals[index]) {
        Ok(())
    } else {
        Err(raw.invalid_real(index, "a fraction between 0 and 1"))
    }
}
